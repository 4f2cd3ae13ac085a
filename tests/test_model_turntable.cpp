// `facet render MODEL` and `facet scene MODEL` (docs/turntables.md): models
// the tests make in each format render as turntables that frame the model,
// ground it with its shadow, stand a Z-up STL upright, write the same bytes
// through a scene file, make movies and compare against references.
#include <catch2/catch.hpp>

#include <filesystem>

#include "compare_support.hpp"
#include "core/sha256.hpp"
#include "turntable_support.hpp"
#include "video_reader.hpp"

using namespace facet::test;
using Catch::Matchers::Contains;

namespace {

// What the turntable tests render: small, the frames the issue names, the
// colour's alpha and the object ids as exact EXR values.
const std::string kFramesAndPasses =
    " --size 96x54 --frames 1,19,37,55 --passes color,object_id --formats exr";

// The turntable of `model` into `out`; returns the run's folder.
std::string render_model(const std::string& model, const std::string& out,
                         const std::string& extra = "") {
    const RunResult r = run_facet("render '" + model + "' -o '" + out + "'" + extra);
    INFO(r.output);
    REQUIRE(r.exit_code == 0);
    return (std::filesystem::path(out) / std::filesystem::path(model).stem()).string();
}

// The model (object id 1) spans between half the frame and nearly all of
// it, wide or high, and stays inside it, at the frames rendered.
void check_framed(const std::string& run) {
    for (int frame : {1, 19, 37, 55}) {
        const TurntableFrame f = read_turntable_frame(run, frame);
        const PixelBox model = pixels_of(f, 1);
        INFO("frame " << frame << ": the model spans x " << model.x0 << ".." << model.x1 << ", y "
                      << model.y0 << ".." << model.y1 << " of " << f.width << "x" << f.height);
        REQUIRE_FALSE(model.empty());
        const double across = double(model.width()) / f.width;
        const double high = double(model.height()) / f.height;
        CHECK(std::max(across, high) >= 0.5);
        CHECK(across <= 0.98);
        CHECK(high <= 0.98);
    }
}

// The model stands taller than it is wide at the frames rendered.
void check_upright(const std::string& run) {
    for (int frame : {1, 19}) {
        const PixelBox model = pixels_of(read_turntable_frame(run, frame), 1);
        INFO("frame " << frame << ": " << model.width() << " wide, " << model.height() << " high");
        CHECK(model.height() > 1.5 * model.width());
    }
}

}  // namespace

TEST_CASE("turntable: a glTF with an animation, an OBJ, a Z-up STL and a PLY each render",
          "[turntable]") {
    TempDir dir("turntable-formats");
    const std::string gltf = write_bobbing_box(dir.file("bobbing.gltf"));
    const std::string obj = write_obj(dir.file("house.obj"), house());
    const std::string stl = write_binary_stl(dir.file("column.stl"), z_up_column());
    const std::string ply = write_ply(dir.file("gem.ply"), octahedron());
    for (const std::string& model : {gltf, obj, stl, ply}) {
        SECTION(std::filesystem::path(model).filename().string()) {
            const RunResult r =
                run_facet("render '" + model + "' -o '" + dir.file("out") + "'" + kFramesAndPasses);
            INFO(r.output);
            REQUIRE(r.exit_code == 0);
            const std::string run = dir.file("out/" + std::filesystem::path(model).stem().string());
            check_framed(run);
            // The manifest says the scene was built around this model.
            const nlohmann::json m = read_manifest_json(run);
            REQUIRE(m.contains("model"));
            const std::string bytes = read_file(model);
            CHECK(m["model"]["sha256"] == facet::sha256_hex(bytes.data(), bytes.size()));
            CHECK(m["model"]["file"] ==
                  "../../" + std::filesystem::path(model).filename().string());
            CHECK(m["model"]["options"]["turns"] == "1");
            CHECK(m["ids"]["object_id"][0]["name"] == "model");
            if (model == stl) {
                CHECK_THAT(r.output, Contains("taken as Z-up"));
                CHECK(m["model"]["options"]["up"] == "z");
                check_upright(run);
            }
            if (model == gltf) CHECK_THAT(r.output, Contains("glTF files are Y-up"));
        }
    }
}

TEST_CASE(
    "turntable: the shadow lies on the ground under the model, and a transparent "
    "background is transparent away from the model and its shadow",
    "[turntable]") {
    TempDir dir("turntable-shadow");
    const std::string model = write_obj(dir.file("house.obj"), house());
    const std::string run = render_model(model, dir.file("out"),
                                         " --size 160x90 --frames 1 --passes color,object_id "
                                         "--formats exr --background transparent");
    const TurntableFrame f = read_turntable_frame(run, 1);
    const PixelBox house_box = pixels_of(f, 1);
    REQUIRE_FALSE(house_box.empty());
    // The ground (object 2) shows the shadow as coverage: pixels next to
    // the house's base, within its columns, are darkened.
    int shadow = 0, near_base = 0;
    for (int y = 0; y < f.height; ++y)
        for (int x = 0; x < f.width; ++x) {
            if (f.id_at(x, y) != 2 || f.alpha_at(x, y) < 0.3f) continue;
            ++shadow;
            if (x >= house_box.x0 && x <= house_box.x1 && y >= house_box.y1 - f.height / 10 &&
                y <= house_box.y1 + 2)
                ++near_base;
        }
    INFO(shadow << " shadow pixels, " << near_base << " at the house's base");
    CHECK(shadow > f.width * f.height / 100);
    CHECK(near_base > 0);
    // Nothing but the model, its shadow and occlusion covers anything:
    // the background is empty, and so is the ground left of the house (the
    // key light comes from the camera's left) and in front of it, beyond
    // the reach of the occlusion (its radius, a tenth of the model, and its
    // blur). Pixels next to the house's edge are partly covered by it.
    const int reach = std::max(8, house_box.height() / 6);
    auto away = [&](int x, int y) {
        const float id = f.id_at(x, y);
        return id == 0 || (id == 2 && (x < house_box.x0 - reach || y > house_box.y1 + reach));
    };
    int checked = 0;
    for (int y = 1; y + 1 < f.height; ++y)
        for (int x = 1; x + 1 < f.width; ++x) {
            bool all_away = true;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) all_away = all_away && away(x + dx, y + dy);
            if (!all_away) continue;
            ++checked;
            INFO("pixel " << x << "," << y << " (object " << f.id_at(x, y) << ")");
            REQUIRE(f.alpha_at(x, y) == 0.0f);
        }
    CHECK(checked > f.width * f.height / 8);
    // The manifest keeps the model's hash: an edited model is other settings.
    write_text(model, read_file(model) + "# edited\n");
    const RunResult edited = run_facet("render '" + model + "' -o '" + dir.file("out") +
                                       "' --size 160x90 --frames 1 --passes color,object_id "
                                       "--formats exr --background transparent");
    CHECK(edited.exit_code == 2);
    CHECK_THAT(edited.output, Contains("the model file changed since the manifest was written"));
}

TEST_CASE("turntable: facet scene writes the scene that facet render MODEL renders, to the byte",
          "[turntable]") {
    TempDir dir("turntable-scene");
    const std::string model = write_bobbing_box(dir.file("bobbing.gltf"));
    const std::string options =
        " --size 96x54 --frames 1,19 --passes color,object_id --formats png,exr --turns 2 "
        "--elevation 35 --ground floor --background '#334455' -D output.samples=1";
    const std::string direct = render_model(model, dir.file("direct"), options);
    // Written beside nothing in particular: a folder of its own, named after the model.
    const std::string file = dir.file("scenes/bobbing.yaml");
    const RunResult written = run_facet("scene '" + model + "' -o '" + file + "'" +
                                        " --size 96x54 --passes color,object_id --formats png,exr "
                                        "--turns 2 --elevation 35 --ground floor "
                                        "--background '#334455' -D output.samples=1");
    INFO(written.output);
    REQUIRE(written.exit_code == 0);
    const std::string text = read_file(file);
    CHECK_THAT(text, Contains("turns: 2"));
    CHECK_THAT(text, Contains("# command line --turns 2"));
    CHECK_THAT(text, Contains("background: \"#334455\""));
    CHECK_THAT(text, Contains("shadow_catcher: false"));
    CHECK_THAT(text, Contains("animation: all"));
    // Standing on the lowest point of its poses, not of its rest pose.
    CHECK_THAT(text, Contains("translate: [0, 1.1, 0]"));
    CHECK_THAT(text, Contains("mesh: \"../bobbing.gltf\""));
    // On one thread where the first run had two: the same bytes too.
    const RunResult again = run_facet("render '" + file + "' -o '" + dir.file("from-file") +
                                      "' --frames 1,19 --threads 1 -q");
    INFO(again.output);
    REQUIRE(again.exit_code == 0);
    const auto a = listed_hashes(read_manifest_json(direct));
    const auto b = listed_hashes(read_manifest_json(dir.file("from-file/bobbing")));
    CHECK(a.size() == 8);
    CHECK(a == b);
    // The run from the model lists what the options stand for.
    const nlohmann::json m = read_manifest_json(direct);
    std::vector<std::string> keys;
    for (const auto& o : m["overrides"]) keys.push_back(o["key"]);
    CHECK(std::find(keys.begin(), keys.end(), "camera.orbit.turns") != keys.end());
    CHECK(std::find(keys.begin(), keys.end(), "objects.ground.material.shadow_catcher") !=
          keys.end());
    CHECK(m["model"]["options"]["ground"] == "floor");
}

TEST_CASE(
    "turntable: the scene file of a Z-up STL renders as the model does, and is the "
    "reference it compares with",
    "[turntable]") {
    TempDir dir("turntable-reference");
    const std::string model = write_binary_stl(dir.file("column.stl"), z_up_column());
    const std::string direct = render_model(model, dir.file("direct"), kFramesAndPasses + " -q");
    check_upright(direct);
    const std::string file = dir.file("column.yaml");
    REQUIRE(run_facet("scene '" + model + "' -o '" + file + "' -q" +
                      " --size 96x54 --passes color,object_id --formats exr")
                .exit_code == 0);
    CHECK_THAT(read_file(file), Contains("rotate: [-90, 0, 0]"));
    // --up y keeps the file's axes: the column lies down.
    const RunResult lying = run_facet("scene '" + model + "' --up y -q");
    CHECK_THAT(lying.output, Contains("rotate: [0, 0, 0]"));
    CHECK_THAT(lying.output, Contains("--up y (the file alone would be read z-up)"));
    // Rendered from the file and compared with the model's run: the same.
    const RunResult compared =
        run_facet("render '" + file + "' -o '" + dir.file("from-file") +
                  "' --frames 1,19,37,55 --reference '" + direct + "' --no-report -q");
    INFO(compared.output);
    CHECK(compared.exit_code == 0);
    CHECK(read_manifest_json(dir.file("from-file/column"))["files"].size() == 8);
    CHECK(listed_hashes(read_manifest_json(direct)) ==
          listed_hashes(read_manifest_json(dir.file("from-file/column"))));
}

TEST_CASE(
    "turntable: the studio turns with the camera, so the background holds still over the turn",
    "[turntable]") {
    // The environment follows the camera (environment.follow_camera): the
    // mean of the top rows, all background, stays within 2/255 at every
    // quarter turn. Before, the camera circled a studio that stood still
    // and the mean swung by about 57/255.
    TempDir dir("turntable-background");
    const std::string model = write_binary_stl(dir.file("column.stl"), z_up_column());
    const std::string run =
        render_model(model, dir.file("out"), " --size 96x54 --frames 1,10,19,28,37,46,55,64 -q");
    double lowest = 255, highest = 0;
    for (int frame : {1, 10, 19, 28, 37, 46, 55, 64}) {
        char name[32];
        std::snprintf(name, sizeof name, "/color.%04d.png", frame);
        const facet::DecodedPng png = facet::read_png(run + name);
        REQUIRE(png.bit_depth == 8);
        double sum = 0;
        const int rows = 6;
        for (int y = 0; y < rows; ++y)
            for (int x = 0; x < png.width; ++x)
                for (int c = 0; c < 3; ++c)
                    sum += png.samples[(static_cast<size_t>(y) * png.width + x) * png.channels + c];
        const double mean = sum / (rows * png.width * 3);
        INFO("frame " << frame << ": top rows' mean " << mean);
        CHECK(mean > 40);  // the studio shows there
        lowest = std::min(lowest, mean), highest = std::max(highest, mean);
    }
    CHECK(highest - lowest <= 2.0);
}

TEST_CASE("turntable: facet scene's printed text names the model wherever it is saved",
          "[turntable]") {
    // `facet scene models/column.stl > scenes/column.yaml`, run from the
    // folder above both: the saved text must still find the model.
    TempDir dir("turntable-printed");
    std::filesystem::create_directories(dir.file("models"));
    std::filesystem::create_directories(dir.file("scenes"));
    write_binary_stl(dir.file("models/column.stl"), z_up_column());
    const RunResult printed =
        run_command("cd '" + dir.path() + "' && '" + facet::test::facet_executable() +
                    "' scene models/column.stl -q > scenes/column.yaml");
    REQUIRE(printed.exit_code == 0);
    const std::string text = read_file(dir.file("scenes/column.yaml"));
    CHECK_THAT(text, Contains("mesh: \"" + dir.file("models/column.stl")));
    const RunResult rendered = run_facet("render '" + dir.file("scenes/column.yaml") + "' -o '" +
                                         dir.file("out") + "' --frames 1 --size 32x18 -q");
    INFO(rendered.output);
    CHECK(rendered.exit_code == 0);
}

TEST_CASE("turntable: --environment lights it with an .hdr, --ground none leaves no ground",
          "[turntable]") {
    TempDir dir("turntable-environment");
    const std::string model = write_obj(dir.file("house.obj"), house());
    // A grey sky of radiance 1 (Radiance texels: mantissas, then the exponent).
    std::string sky = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 4 +X 8\n";
    for (int i = 0; i < 32; ++i) sky += std::string("\x80\x80\x80\x81", 4);
    write_text(dir.file("sky.hdr"), sky);
    const std::string run = render_model(model, dir.file("out"),
                                         " --size 96x54 --frames 1 --passes color,object_id "
                                         "--formats exr --ground none --environment '" +
                                             dir.file("sky.hdr") + "'");
    const TurntableFrame f = read_turntable_frame(run, 1);
    CHECK_FALSE(pixels_of(f, 1).empty());
    CHECK(pixels_of(f, 2).empty());
    // The sky shows behind the model: radiance 1 in every channel wherever
    // nothing is drawn (the studio would show its grey gradient there).
    const facet::DecodedExr color = facet::read_exr(run + "/color.0001.exr");
    const std::vector<float>& red = facet::test::exr_channel(color, "R");
    const std::vector<float>& blue = facet::test::exr_channel(color, "B");
    // (Pixels beside the model may mix in its edge: all within 10%, most
    // within 2%.)
    int background = 0, exact = 0;
    for (size_t i = 0; i < f.id.size(); ++i) {
        if (f.id[i] != 0) continue;
        ++background;
        INFO("pixel " << i);
        REQUIRE(red[i] == Approx(1.0).epsilon(0.1));
        REQUIRE(blue[i] == Approx(1.0).epsilon(0.1));
        exact += std::fabs(red[i] - 1.0f) < 0.02f && std::fabs(blue[i] - 1.0f) < 0.02f;
    }
    CHECK(background > 1000);
    CHECK(exact > 0.9 * background);
    const nlohmann::json m = read_manifest_json(run);
    CHECK(m["model"]["options"]["environment"] == dir.file("sky.hdr"));
    CHECK(m["model"]["options"]["ground"] == "none");
}

TEST_CASE("turntable: --video writes a movie of the turntable", "[turntable][video]") {
    TempDir dir("turntable-video");
    const std::string model = write_obj(dir.file("house.obj"), house());
    const std::string movie = dir.file("turntable.mp4");
    const RunResult r = run_facet("render '" + model + "' -o '" + dir.file("out") +
                                  "' --size 64x36 --frames 1-3 -q --video '" + movie + "'");
    if (r.exit_code != 0 && r.output.find("has no encoder") != std::string::npos)
        FACET_SKIP("FFmpeg has no H.264 encoder here: " + r.output);
    INFO(r.output);
    REQUIRE(r.exit_code == 0);
    const facet::VideoSummary v = facet::read_video(movie);
    CHECK(v.codec == "h264");
    CHECK(v.frames == 3);
    CHECK(v.width == 64);
    CHECK(v.fps == Approx(24));
}

TEST_CASE(
    "turntable: -D replacing a whole mapping that holds an option's key (environment: none) "
    "renders, and facet scene writes it",
    "[turntable]") {
    // The keys the options set are checked against the turntable's text
    // each time it is written; a key under a mapping that -D replaces is
    // still one the text has.
    TempDir dir("turntable-whole-mapping");
    const std::string model = write_binary_stl(dir.file("column.stl"), z_up_column());
    const std::string run =
        render_model(model, dir.file("out"), " --size 48x27 --frames 1 -D environment=none -q");
    CHECK(std::filesystem::exists(run + "/color.0001.png"));
    const RunResult written = run_facet("scene '" + model + "' -D environment=none --turns 2 -q");
    INFO(written.output);
    REQUIRE(written.exit_code == 0);
    CHECK_THAT(written.output, Contains("environment: none"));
    CHECK_THAT(written.output, Contains("turns: 2"));
}
