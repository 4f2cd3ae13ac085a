// facet preview's parts that need no window (docs/preview.md): the view
// camera and its YAML, hot reload's file watch, the panel's tweaks as
// overrides and style files, the rendering worker's steps, errors and
// snapshots, and the command's refusals. The window itself is tested under
// Xvfb (tests/preview/preview_test.py).
#include <catch2/catch.hpp>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <thread>

#include <glm/geometric.hpp>

#include "core/display_transform.hpp"
#include "output/encoders.hpp"
#include "preview/file_watch.hpp"
#include "preview/preview_worker.hpp"
#include "preview/tweaks.hpp"
#include "preview/view_camera.hpp"
#include "scene/scene_desc.hpp"
#include "scene_support.hpp"
#include "support.hpp"

using Catch::Contains;
using namespace facet;
using namespace facet::test;
namespace fs = std::filesystem;

namespace {

const std::string kScene = R"(output:
  size: [64, 48]
  frames: 1-4
  samples: 4
camera:
  position: [0, 1.5, 4]
  target: [0, 0.3, 0]
objects:
  - primitive: cube
    material: { color: [0.8, 0.2, 0.1] }
)";

float degrees_from(const glm::vec3& a, const glm::vec3& b) {
    return glm::degrees(
        std::acos(std::clamp(glm::dot(glm::normalize(a), glm::normalize(b)), -1.0f, 1.0f)));
}

// Takes the worker's updates until `done` says so (or a minute passes:
// sanitizer builds render slowly).
std::vector<PreviewUpdate> updates_until(PreviewWorker& worker,
                                         const std::function<bool(const PreviewUpdate&)>& done) {
    std::vector<PreviewUpdate> all;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    while (std::chrono::steady_clock::now() < deadline) {
        PreviewUpdate u = worker.take();
        const bool finished = done(u);
        all.push_back(std::move(u));
        if (finished) return all;
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    FAIL("the preview worker did not finish within a minute");
    return all;
}

bool final_image(const PreviewUpdate& u) {
    return u.image && u.image->last_step;
}

// Asks for `request` and waits for its last step: the image, and every
// step on the way (with the scene when one was loaded).
struct Rendered {
    PreviewImage image;
    std::vector<PreviewStep> steps;
    std::shared_ptr<const SceneDesc> scene;
};

Rendered render_view(PreviewWorker& worker, const PreviewRequest& request) {
    worker.request(request);
    Rendered out;
    for (PreviewUpdate& u : updates_until(worker, final_image)) {
        if (u.scene) out.scene = u.scene;
        out.steps.insert(out.steps.end(), u.steps.begin(), u.steps.end());
        if (u.image) out.image = *u.image;
    }
    return out;
}

bool has_error(const PreviewUpdate& u) {
    return u.error && !u.error->empty();
}

}  // namespace

TEST_CASE("the preview camera orbits about its target at the same distance, short of the poles",
          "[preview]") {
    const ViewCamera camera{{0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 40, 0.1f, 100};
    const ViewCamera turned = orbit(camera, 90, 0);
    CHECK(glm::length(turned.position - glm::vec3(5, 0, 0)) < 1e-4f);
    const ViewCamera raised = orbit(camera, 0, 30);
    CHECK(degrees_from(raised.position, {0, 1, 0}) == Approx(60).margin(1e-3));
    CHECK(glm::length(raised.position) == Approx(5).epsilon(1e-5));
    // However far the drag, the view stops 1 degree from straight down or up.
    CHECK(degrees_from(orbit(camera, 0, 500).position, {0, 1, 0}) == Approx(1).margin(1e-3));
    CHECK(degrees_from(orbit(camera, 0, -500).position, {0, 1, 0}) == Approx(179).margin(1e-3));
    CHECK(turned.target == camera.target);
    CHECK(turned.fov_degrees == camera.fov_degrees);
}

TEST_CASE("the preview camera pans by a share of the view's height and dollies its planes along",
          "[preview]") {
    // fov 90 at distance 5: the view is 10 units high at the target.
    const ViewCamera camera{{0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 90, 0.1f, 100};
    const ViewCamera moved = pan(camera, 0.5f, -0.1f);
    CHECK(glm::length(moved.target - glm::vec3(5, -1, 0)) < 1e-4f);
    CHECK(glm::length((moved.position - moved.target) - (camera.position - camera.target)) < 1e-5f);
    const ViewCamera closer = dolly(camera, 0.5f);
    CHECK(glm::length(closer.position - glm::vec3(0, 0, 2.5f)) < 1e-5f);
    CHECK(closer.near == Approx(0.05f));
    CHECK(closer.far == Approx(97.5f));  // what was 100 away from the camera still is in range
    const ViewCamera farther = dolly(camera, 2.0f);
    CHECK(farther.near == Approx(0.1f));
    CHECK(farther.far == Approx(105.0f));
    // A camera looking straight down its `up` still pans and orbits.
    const ViewCamera top{{0, 5, 0}, {0, 0, 0}, {0, 1, 0}, 90, 0.1f, 100};
    const ViewCamera slid = pan(top, 0.5f, 0);
    CHECK(std::isfinite(slid.target.x + slid.target.y + slid.target.z));
    CHECK(glm::length(slid.target) == Approx(5.0f));
    const ViewCamera tilted = orbit(top, 0, -30);
    CHECK(degrees_from(tilted.position, {0, 1, 0}) == Approx(30).margin(1e-3));
}

TEST_CASE("the printed camera reads back as exactly the camera shown", "[preview]") {
    TempDir dir("preview-camera");
    const std::string path = write_text(dir.file("scene.yaml"),
                                        "cameras:\n  - name: front\n  - name: side\n    orbit: "
                                        "{ radius: 6 }\n" +
                                            kMinimalObjects);
    const SceneDesc scene = load(path);
    ViewCamera view{
        {1.1f, 2.0f / 3.0f, -4.25f}, {0.1f, 0.2f, 0.3f}, {0, 1, 0.01f}, 37.5f, 0.0123f, 456.7f};
    view = orbit(view, 12.3f, -4.5f);
    const Override o = camera_override(view, scene.cameras[1]);
    CHECK(o.path == "cameras.1");
    SceneOptions options = with_styles();
    options.overrides.push_back(o);
    const SceneDesc back = load(path, options);
    const CameraDesc& camera = back.cameras[1];
    CHECK(camera.name == "side");
    CHECK_FALSE(camera.orbit);                      // the still camera replaces the orbit
    CHECK(camera.position.value == view.position);  // bit for bit: the shortest exact text
    CHECK(camera.target.value == view.target);
    CHECK(camera.up.value == view.up);
    CHECK(camera.fov.value == view.fov_degrees);
    CHECK(camera.near->value == view.near);
    CHECK(camera.far->value == view.far);
    CHECK_THAT(camera_yaml(view, "side"), Contains("name: \"side\"\nposition: ["));
}

TEST_CASE("the file watch reports a settled change once and ignores editors' swap files",
          "[preview]") {
    TempDir dir("preview-watch");
    const std::string scene = write_text(dir.file("scene.yaml"), "a");
    write_text(dir.file("meshes/model.obj"), "v 0 0 0\n");
    FileWatch watch;
    watch.watch({{scene}, {dir.file("meshes")}});
    CHECK_FALSE(watch.poll());
    write_text(scene, "bb");
    CHECK_FALSE(watch.poll());  // changed since the last poll: maybe still being written
    CHECK(watch.poll());        // the same twice: reported
    CHECK_FALSE(watch.poll());  // and only once
    write_text(dir.file("meshes/.model.obj.swp"), "x");
    write_text(dir.file("meshes/model.obj~"), "x");
    CHECK_FALSE(watch.poll());
    CHECK_FALSE(watch.poll());
    // A texture appearing beside the mesh, then one replaced by a rename.
    write_text(dir.file("meshes/wood.png"), "png");
    watch.poll();
    CHECK(watch.poll());
    write_text(dir.file("meshes/wood.new"), "png");
    fs::rename(dir.file("meshes/wood.new"), dir.file("meshes/wood.png"));
    watch.poll();
    CHECK(watch.poll());
    // A texture two folders down; three down is beyond the watch.
    write_text(dir.file("meshes/textures/wood/grain.png"), "png");
    watch.poll();
    CHECK(watch.poll());
    write_text(dir.file("meshes/a/b/c/deep.png"), "png");
    watch.poll();
    CHECK_FALSE(watch.poll());
    fs::remove(scene);
    watch.poll();
    CHECK(watch.poll());
}

TEST_CASE("the watch list names the scene, its style chain, its meshes and their folders",
          "[preview]") {
    TempDir dir("preview-watch-list");
    write_text(dir.file("looks/mine.yaml"), "extends: toon\nalpha: 0.3\n");
    write_text(dir.file("meshes/tri.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    const std::string path = write_text(
        dir.file("scene.yaml"), "style: looks/mine.yaml\nobjects:\n  - mesh: meshes/tri.obj\n");
    const WatchList list = scene_watch_list(load(path));
    auto has = [](const std::vector<std::string>& v, const std::string& p) {
        return std::any_of(v.begin(), v.end(), [&](const std::string& s) {
            return fs::weakly_canonical(s) == fs::weakly_canonical(p);
        });
    };
    CHECK(has(list.files, path));
    CHECK(has(list.files, dir.file("looks/mine.yaml")));
    CHECK(has(list.files, std::string(facet::test::styles_dir()) + "/toon.yaml"));
    CHECK(has(list.files, dir.file("meshes/tri.obj")));
    CHECK(has(list.folders, dir.file("meshes")));
}

TEST_CASE("the panel's values leave as -D arguments and as a style file that mean the same",
          "[preview]") {
    TempDir dir("preview-tweaks");
    const std::string path =
        write_text(dir.file("scene.yaml"),
                   "style: palette\nlights:\n  - { type: directional, direction: [0, -1, 0] }\n" +
                       kMinimalObjects);
    Tweaks tweaks;
    tweaks["style.alpha"] = 0.35f;
    tweaks["style.cels"] = 3;
    tweaks["style.cool"] = glm::vec3(0.1f, 0.2f, 0.5f);
    tweaks["style.outlines.silhouette.width"] = 2.5f;
    tweaks["style.outlines.silhouette.color"] = glm::vec3(0.2f, 0, 0);
    tweaks["lights.0.color"] = glm::vec3(1, 0.9f, 0.8f);
    const std::vector<Override> overrides = tweak_overrides(tweaks);
    CHECK(define_arguments(overrides) ==
          "-D 'lights.0.color=[1, 0.9, 0.8]' -D 'style.alpha=0.35' -D 'style.cels=3' "
          "-D 'style.cool=[0.1, 0.2, 0.5]' -D 'style.outlines.silhouette.color=[0.2, 0, 0]' "
          "-D 'style.outlines.silhouette.width=2.5'");
    CHECK(define_arguments({{"style", "\"it's\"", ""}}) == "-D 'style=\"it'\\''s\"'");

    SceneOptions with_overrides = with_styles();
    with_overrides.overrides = overrides;
    const SceneDesc tweaked = load(path, with_overrides);
    CHECK(tweaked.style.alpha.value == 0.35f);
    CHECK(tweaked.lights[0].color.value == glm::vec3(1, 0.9f, 0.8f));

    // The style file: extends the scene's preset by name, nests the keys,
    // and lists the light as a scene value.
    const std::string yaml =
        style_file_yaml(tweaked, tweaks, {facet::test::styles_dir()}, dir.file("look.yaml"));
    CHECK_THAT(yaml, Contains("extends: palette\n"));
    CHECK_THAT(yaml,
               Contains("outlines:\n  silhouette:\n    color: [0.2, 0, 0]\n    width: 2.5\n"));
    CHECK_THAT(yaml, Contains("#   -D lights.0.color=[1, 0.9, 0.8]"));
    SceneOptions with_file = with_styles();
    std::string look = "\"";
    look += write_text(dir.file("look.yaml"), yaml);
    with_file.overrides.push_back({"style", look + "\"", ""});
    const SceneDesc with_look = load(path, with_file);
    const StyleDesc& from_file = with_look.style;
    const StyleDesc& from_overrides = tweaked.style;
    CHECK(from_file.shading == from_overrides.shading);
    CHECK(from_file.alpha.value == from_overrides.alpha.value);
    CHECK(from_file.beta.value == from_overrides.beta.value);
    CHECK(from_file.cels.value == from_overrides.cels.value);
    CHECK(from_file.cool.value == from_overrides.cool.value);
    CHECK(from_file.warm.value == from_overrides.warm.value);
    CHECK(from_file.outlines.silhouette.enabled);
    CHECK(from_file.outlines.silhouette.width.value == 2.5f);
    CHECK(from_file.outlines.silhouette.color.value == glm::vec3(0.2f, 0, 0));
}

TEST_CASE("a style file written from the panel keeps the look's own keys and never extends itself",
          "[preview]") {
    TempDir dir("preview-style-file");
    write_text(dir.file("look.yaml"), "extends: palette\nalpha: 0.1\ncels: 5\n");
    const std::string path =
        write_text(dir.file("scene.yaml"), "style: look.yaml\n" + kMinimalObjects);
    const std::string inline_path = write_text(
        dir.file("inline.yaml"), "style: { extends: palette, cels: 2 }\n" + kMinimalObjects);
    Tweaks tweaks;
    tweaks["style.alpha"] = 0.3f;
    SceneOptions options = with_styles();
    options.overrides = tweak_overrides(tweaks);

    // Written back over the scene's own style: its keys stay, the value changes.
    const std::string own = style_file_yaml(load(path, options), tweaks,
                                            {facet::test::styles_dir()}, dir.file("look.yaml"));
    CHECK_THAT(own, Contains("extends: palette"));
    CHECK_THAT(own, !Contains("extends: look"));
    write_text(dir.file("look.yaml"), own);
    const StyleDesc rewritten = load(path).style;
    CHECK(rewritten.alpha.value == 0.3f);
    CHECK(rewritten.cels.value == 5.0f);

    // An inline style written out: its keys and the panel's values.
    const std::string out =
        style_file_yaml(load(inline_path, options), tweaks, {facet::test::styles_dir()},
                        dir.file("inline-look.yaml"));
    write_text(dir.file("inline-look.yaml"), out);
    const StyleDesc from_inline =
        load(write_text(dir.file("uses.yaml"), "style: inline-look.yaml\n" + kMinimalObjects))
            .style;
    CHECK(from_inline.shading == ShadingModel::palette);
    CHECK(from_inline.cels.value == 2.0f);
    CHECK(from_inline.alpha.value == 0.3f);

    // A preset the scene's style extends is not written over.
    CHECK_THROWS_WITH(style_file_yaml(load(path, options), tweaks, {facet::test::styles_dir()},
                                      std::string(facet::test::styles_dir()) + "/palette.yaml"),
                      Contains("a preset the scene's style extends"));
}

TEST_CASE("the preview renders a quarter image, then full size, then the scene's samples",
          "[preview]") {
    TempDir dir("preview-steps");
    const std::string path = write_text(dir.file("scene.yaml"), kScene);
    PreviewWorker worker(path, with_styles(), 2);
    PreviewRequest request;
    request.frame = kSceneFirstFrame;
    const Rendered rendered = render_view(worker, request);
    const std::vector<PreviewStep>& steps = rendered.steps;
    REQUIRE(rendered.scene);
    CHECK(rendered.scene->output.samples == 4);
    REQUIRE(steps.size() == 3);
    CHECK(steps[0].step == "quarter");
    CHECK((steps[0].width == 16 && steps[0].height == 12));
    CHECK(steps[1].step == "full");
    CHECK((steps[1].width == 64 && steps[1].height == 48));
    CHECK(steps[2].step == "final");
    for (const PreviewStep& step : steps) CHECK(step.frame == 1);
    const PreviewImage& last = rendered.image;
    CHECK(last.step == "final");
    // The final image is the pixels of the PNG facet render writes.
    const RunResult render =
        run_facet("render '" + path + "' -f 1 -q -o '" + dir.file("out") + "'");
    REQUIRE(render.exit_code == 0);
    const DecodedPng png = read_png(dir.file("out/scene/color.0001.png"));
    REQUIRE(png.channels == 3);
    bool same = true;
    for (size_t p = 0; p < png.samples.size() / 3; ++p)
        for (int c = 0; c < 3; ++c) same = same && last.rgba[p * 4 + c] == png.samples[p * 3 + c];
    CHECK(same);

    // A live request (a drag, or playing) gets one small step.
    request.live = true;
    const std::vector<PreviewStep> live = render_view(worker, request).steps;
    REQUIRE(live.size() == 1);
    CHECK_THAT(live[0].step, Contains("live 1/2"));
    CHECK((live[0].width == 32 && live[0].height == 24));
}

TEST_CASE("the preview shows any pass as its PNG shows it", "[preview]") {
    TempDir dir("preview-pass");
    const std::string path = write_text(dir.file("scene.yaml"), kScene);
    PreviewWorker worker(path, with_styles(), 2);
    PreviewRequest request;
    request.frame = 2;
    request.pass = Pass::depth;  // not among the scene's passes: rendered for the window anyway
    const PreviewImage last = render_view(worker, request).image;
    const RunResult render =
        run_facet("render '" + path + "' -f 2 -q --passes depth -o '" + dir.file("out") + "'");
    REQUIRE(render.exit_code == 0);
    const DecodedPng png = read_png(dir.file("out/scene/depth.0002.png"));
    REQUIRE((png.channels == 1 && png.bit_depth == 16));
    REQUIRE(last.rgba.size() == png.samples.size() * 4);
    size_t differing = 0, grey = 0;
    for (size_t p = 0; p < png.samples.size(); ++p) {
        const uint8_t* shown = &last.rgba[p * 4];
        differing += shown[0] != facet::narrow_to_byte(png.samples[p]);
        grey += shown[0] == shown[1] && shown[1] == shown[2] && shown[3] == 255;
    }
    CHECK(differing == 0);
    CHECK(grey == png.samples.size());
}

TEST_CASE("the preview shows a broken scene's error and renders again once it is fixed",
          "[preview]") {
    TempDir dir("preview-error");
    const std::string path = write_text(dir.file("scene.yaml"), kScene);
    PreviewWorker worker(path, with_styles(), 1);
    PreviewRequest request;
    request.frame = 2;
    render_view(worker, request);

    std::string broken = kScene;
    broken.replace(broken.find("color:"), 6, "colr:");
    write_text(path, broken);
    request.files_version = 1;
    worker.request(request);
    std::string error;
    for (PreviewUpdate& u : updates_until(worker, has_error)) {
        CHECK_FALSE(u.image);  // no image from a broken scene: the last good one stays
        if (u.error) error = *u.error;
    }
    CHECK_THAT(error, Contains(path + ":" + line_col(broken, "colr")));
    CHECK_THAT(error, Contains("did you mean 'color'"));
    // The file the error is in is watched from now on.
    write_text(path, kScene);
    request.files_version = 2;
    worker.request(request);
    bool cleared = false;
    for (PreviewUpdate& u : updates_until(worker, final_image))
        if (u.error && u.error->empty()) cleared = true;
    CHECK(cleared);
}

TEST_CASE("after a failed load the file the error is in is watched", "[preview]") {
    TempDir dir("preview-error-watch");
    write_text(dir.file("looks/broken.yaml"), "extends: toon\nalpah: 0.3\n");
    const std::string path =
        write_text(dir.file("scene.yaml"), "style: looks/broken.yaml\n" + kMinimalObjects);
    PreviewWorker worker(path, with_styles(), 1);
    worker.request({});
    std::optional<WatchList> watched;
    std::string error;
    for (PreviewUpdate& u : updates_until(worker, has_error)) {
        if (u.watch) watched = u.watch;
        if (u.error) error = *u.error;
    }
    CHECK_THAT(error, Contains("broken.yaml:2:1"));
    REQUIRE(watched);
    auto names = [&](const std::string& file) {
        return std::any_of(watched->files.begin(), watched->files.end(), [&](const auto& f) {
            return fs::weakly_canonical(f) == fs::weakly_canonical(file);
        });
    };
    CHECK(names(path));
    CHECK(names(dir.file("looks/broken.yaml")));
}

TEST_CASE("moving the camera after an unnoticed edit keeps the world with its own objects",
          "[preview]") {
    TempDir dir("preview-splice");
    const std::string path = write_text(
        dir.file("scene.yaml"), kScene + "  - primitive: sphere\n    translate: [1, 0, 0]\n");
    PreviewWorker worker(path, with_styles(), 1);
    PreviewRequest request;
    request.frame = 1;
    const Rendered before = render_view(worker, request);
    REQUIRE(before.scene);
    CHECK(before.scene->objects.size() == 2);
    // The file loses an object; the watch has not said so yet (same
    // files_version) when the camera moves.
    write_text(path, kScene);
    const ViewCamera view{{0, 2, 5}, {0, 0, 0}, {0, 1, 0}, 40, 0.1f, 100};
    request.camera = camera_override(view, before.scene->cameras.front());
    const Rendered moved = render_view(worker, request);
    REQUIRE(moved.scene);
    CHECK(moved.scene->objects.size() == 2);  // the world's objects
    CHECK(moved.scene->cameras.front().position.value == view.position);
    CHECK(moved.image.camera_moved);
    CHECK(moved.image.width == 64);
}

TEST_CASE(
    "a preview snapshot writes the files facet render writes, with the tweaks in the manifest",
    "[preview]") {
    TempDir dir("preview-snapshot");
    const std::string path = write_text(dir.file("scene.yaml"), kScene);
    PreviewWorker worker(path, with_styles(), 2);
    SnapshotRequest snapshot;
    snapshot.view.frame = 3;
    snapshot.view.overrides = {{"objects.0.material.color", "[0.1, 0.3, 0.9]", "preview panel"}};
    snapshot.out_dir = dir.file("snapshots");
    snapshot.command_line = {"facet", "preview", path};
    worker.snapshot(snapshot);
    PreviewMessage message;
    updates_until(worker, [&](const PreviewUpdate& u) {
        if (!u.messages.empty()) message = u.messages.front();
        return !message.text.empty();
    });
    CHECK_THAT(message.text, Contains("snapshot of frame 3: wrote color.0003.png"));
    CHECK_FALSE(message.failed);
    const RunResult render = run_facet("render '" + path + "' -f 3 -q -o '" + dir.file("out") +
                                       "' -D 'objects.0.material.color=[0.1, 0.3, 0.9]'");
    REQUIRE(render.exit_code == 0);
    const std::string written = read_file(dir.file("snapshots/scene/color.0003.png"));
    CHECK(!written.empty());
    CHECK(written == read_file(dir.file("out/scene/color.0003.png")));
    CHECK_THAT(read_file(dir.file("snapshots/scene/manifest.json")),
               Contains("objects.0.material.color"));
}

TEST_CASE("facet preview refuses to start without a display, a scene or one camera",
          "[preview][cli]") {
    TempDir dir("preview-cli");
    const std::string path = write_text(dir.file("scene.yaml"), kScene);
    const std::string headless = "env -u DISPLAY -u WAYLAND_DISPLAY -u SDL_VIDEODRIVER ";
    RunResult r = run_command(headless + "'" + facet::test::facet_executable() + "' preview '" +
                              path + "' 2>&1");
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.output, Contains("needs a display"));
    CHECK_THAT(r.output, Contains("DISPLAY"));
    // With a display named (any: these fail before opening it).
    const std::string display = "env DISPLAY=:none ";
    r = run_command(display + "'" + facet::test::facet_executable() + "' preview '" +
                    dir.file("missing.yaml") + "' 2>&1");
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.output, Contains("no such file"));
    r = run_command(display + "'" + facet::test::facet_executable() + "' preview '" + path +
                    "' --camera a,b 2>&1");
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.output, Contains("one camera"));
    // A camera the scene lacks, as render refuses it.
    r = run_command(display + "'" + facet::test::facet_executable() + "' preview '" + path +
                    "' --camera nope 2>&1");
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.output, Contains("nope"));
    // A display named but not there: SDL's reason and exit 2, not an
    // invisible off-screen window (the test is killed after 20 s if so).
    // (SDL's failed X11 and Wayland set-up leaves allocations LeakSanitizer
    // cannot name, as the Xvfb test notes: leak checks are off for these.)
    for (const char* unreachable :
         {"env -u WAYLAND_DISPLAY -u SDL_VIDEODRIVER ASAN_OPTIONS=detect_leaks=0 DISPLAY=:77 ",
          "env -u DISPLAY -u SDL_VIDEODRIVER ASAN_OPTIONS=detect_leaks=0 "
          "WAYLAND_DISPLAY=nowhere-77 "}) {
        INFO(unreachable);
        r = run_command(std::string(unreachable) + "timeout -s KILL 20 '" +
                        facet::test::facet_executable() + "' preview '" + path + "' 2>&1");
        CHECK(r.exit_code == 2);
        CHECK_THAT(r.output, Contains("cannot open a window"));
    }
    // The display is checked first: before the scene file or the options.
    r = run_command(headless + "'" + facet::test::facet_executable() + "' preview '" +
                    dir.file("missing.yaml") + "' 2>&1");
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.output, Contains("needs a display"));
}
