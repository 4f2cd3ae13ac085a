// What `facet render FILE` makes of a file (docs/turntables.md): mesh
// formats told by their bytes, which way up a model stands, the scene text
// with options written in, and the clear refusals of files that are no
// scene and no mesh, of meshes with nothing to show, and of options that
// cannot apply.
#include <catch2/catch.hpp>

#include <filesystem>

#include "assets/mesh_format.hpp"
#include "render/world.hpp"
#include "support.hpp"
#include "turntable/model_turntable.hpp"
#include "turntable/up_axis.hpp"
#include "turntable/yaml_writer.hpp"
#include "turntable_support.hpp"

using namespace facet::test;
using Catch::Matchers::Contains;
using facet::MeshFormat;

namespace {

std::optional<MeshFormat> format_of(const std::string& bytes) {
    return facet::mesh_format_of_bytes(
        {reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size()}, bytes.size());
}

facet::Mesh mesh_of(const std::vector<glm::vec3>& corners) {
    facet::Mesh mesh;
    facet::MeshPart part;
    part.positions = corners;
    for (uint32_t i = 0; i < corners.size(); ++i) part.indices.push_back(i);
    mesh.parts.push_back(part);
    return mesh;
}

// A run that must fail with exit code 2 and a message holding `needle`.
void require_refused(const std::string& args, const std::string& needle) {
    const RunResult r = run_facet(args);
    INFO(r.output);
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.output, Contains(needle));
}

}  // namespace

TEST_CASE("mesh formats are told by their bytes", "[turntable][assets]") {
    CHECK(format_of(std::string("glTF\x02\0\0\0", 8)) == MeshFormat::glb);
    CHECK(format_of("{\n \"asset\": {\"version\": \"2.0\"}}") == MeshFormat::gltf);
    CHECK(format_of("ply\nformat ascii 1.0\n") == MeshFormat::ply);
    CHECK(format_of("solid cube\n  facet normal 0 0 1\n") == MeshFormat::stl);
    CHECK(format_of("# made by hand\nmtllib a.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n") ==
          MeshFormat::obj);
    CHECK(format_of(std::string("Kaydara FBX Binary  \0", 21)) == MeshFormat::fbx);
    CHECK(format_of("; FBX 7.5.0 project file\n") == MeshFormat::fbx);
    CHECK(format_of("<?xml version=\"1.0\"?>\n<COLLADA xmlns=\"x\">") == MeshFormat::collada);
    std::string max3ds = std::string("MM\x0a\0\0\0", 6) + "abcd";
    CHECK(format_of(max3ds) == MeshFormat::max3ds);
    // A binary STL is known by its size: 84 bytes and 50 a triangle.
    std::string stl(84 + 50, '\0');
    stl[80] = 1;
    CHECK(format_of(stl) == MeshFormat::stl);
    // Scenes, and other things, are none of them.
    CHECK_FALSE(
        format_of("# a scene\noutput: { size: [64, 36] }\nobjects:\n  - primitive: cube\n"));
    CHECK_FALSE(format_of("{objects: [{primitive: cube}]}"));
    CHECK_FALSE(format_of("hello world\n"));
    CHECK_FALSE(format_of(std::string("\x89PNG\r\n\x1a\n", 8)));
    // The name is the fallback, in any letter case.
    CHECK(facet::mesh_format_of_name("a/Model.GLB") == MeshFormat::glb);
    CHECK_FALSE(facet::mesh_format_of_name("model.yaml"));
}

TEST_CASE("STL and PLY models stand on their flat base, and other formats are Y-up",
          "[turntable][assets]") {
    using facet::UpAxis;
    const facet::Mesh column = mesh_of(z_up_column());
    CHECK(facet::flat_base_share(column, UpAxis::z) == Approx(1.0));
    const facet::UpChoice stl = facet::choose_up_axis(column, MeshFormat::stl);
    CHECK(stl.axis == UpAxis::z);
    CHECK(stl.detected);
    // The same column in a glTF file is read as glTF says: Y-up.
    CHECK(facet::choose_up_axis(column, MeshFormat::glb).axis == UpAxis::y);
    // A house standing on its floor at its lowest Y, round nowhere else.
    CHECK(facet::choose_up_axis(mesh_of(house()), MeshFormat::ply).axis == UpAxis::y);
    // No flat base at all: facet's own Y-up, said so.
    const facet::UpChoice gem = facet::choose_up_axis(mesh_of(octahedron()), MeshFormat::stl);
    CHECK(gem.axis == UpAxis::y);
    CHECK_THAT(gem.reason, Contains("no flat base"));
    // A slab flat on both: it stands along its longer side.
    CHECK(facet::choose_up_axis(mesh_of(box_triangles({0, 0, 0}, {1, 0.5f, 2})), MeshFormat::stl)
              .axis == UpAxis::z);
    CHECK(facet::choose_up_axis(mesh_of(box_triangles({0, 0, 0}, {1, 2, 0.5f})), MeshFormat::stl)
              .axis == UpAxis::y);
}

TEST_CASE("the scene writer puts an override's value where its key is, and says which it left",
          "[turntable]") {
    facet::YamlWriter w({{"camera.orbit.turns", "2", "command line --turns 2"},
                         {"output.background", "#ff8800", "command line --background #ff8800"},
                         {"objects.ground.visible", "false", "command line --ground none"},
                         {"output.exposure", "1", "command line -D output.exposure=1"},
                         {"camera.near", "0.5", "command line -D camera.near=0.5"}});
    w.begin_map("output");
    w.value("background", "[0.2, 0.2, 0.2, 1]");
    w.optional_value("exposure");
    w.optional_value("tonemap");
    w.end_map();
    w.begin_map("camera");
    w.begin_map("orbit");
    w.value("turns", "1", "--turns N");
    w.end_map();
    w.end_map();
    w.begin_list("objects");
    w.begin_item("ground");
    w.value("cast_shadows", "false");
    w.optional_value("visible");
    w.end_item();
    w.end_list();
    CHECK(w.text() ==
          "output:\n"
          "  background: \"#ff8800\"         # command line --background #ff8800\n"
          "  exposure: 1                   # command line -D output.exposure=1\n"
          "camera:\n"
          "  orbit:\n"
          "    turns: 2                    # command line --turns 2\n"
          "objects:\n"
          "  - name: ground\n"
          "    cast_shadows: false\n"
          "    visible: false              # command line --ground none\n");
    REQUIRE(w.unused().size() == 1);
    CHECK(w.unused().front().path == "camera.near");
}

TEST_CASE("files that are no scene and no mesh are refused, saying what facet reads",
          "[turntable][errors]") {
    TempDir dir("turntable-neither");
    std::vector<uint8_t> junk(3000);
    for (size_t i = 0; i < junk.size(); ++i) junk[i] = static_cast<uint8_t>(i * 131 + 7);
    const std::string binary = write_bytes(dir.file("model.dat"), junk);
    require_refused("render '" + binary + "'", "neither a scene nor a mesh facet reads");
    require_refused("render '" + binary + "'", "glTF (.gltf, .glb), OBJ (.obj), STL (.stl)");
    const std::string text = write_text(dir.file("notes.txt"), "a shopping list\n");
    require_refused("render '" + text + "'", "notes.txt: neither a scene nor a mesh");
    // A broken YAML scene is still a broken YAML scene.
    const std::string broken = write_text(dir.file("broken.yaml"), "objects: [ {primitive: cube\n");
    require_refused("render '" + broken + "'", "broken.yaml:2:1: YAML syntax error");
    // Commands that take scenes only say what to do with a model.
    const std::string obj = write_obj(dir.file("house.obj"), house());
    require_refused("bench '" + obj + "'", "a mesh (OBJ), not a scene: `facet render");
    require_refused("scene '" + broken + "'", "a scene already");
}

TEST_CASE("meshes with nothing to show or no size to frame are refused", "[turntable][errors]") {
    TempDir dir("turntable-empty");
    require_refused("render '" + write_text(dir.file("points.obj"), "v 0 0 0\nv 1 0 0\n") + "'",
                    "points.obj: the OBJ file has no faces");
    require_refused(
        "render '" + write_text(dir.file("line.obj"), "v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n") + "'",
        "line.obj: its one triangle has no area (every vertex lies on one line");
    Gltf points;
    points.one_node_scene(
        {{"attributes", {{"POSITION", points.floats(kTriangle, "VEC3")}}}, {"mode", 0}});
    require_refused("render '" + points.write(dir.file("points.gltf")) + "'",
                    "points.gltf: the glTF file has no triangles");
    std::vector<glm::vec3> speck = box_triangles({0, 0, 0}, {1e-7f, 1e-7f, 1e-7f});
    require_refused("render '" + write_binary_stl(dir.file("speck.stl"), speck) + "'",
                    "speck.stl: the model is 1e-07 units across, too small to frame");
}

TEST_CASE("a flat model is framed, and a model is known by its bytes whatever its name",
          "[turntable]") {
    TempDir dir("turntable-flat");
    // A square lying flat: no height at all. Drawn without the studio, for speed.
    const std::vector<glm::vec3> square = {{-1, 0, -1}, {-1, 0, 1}, {1, 0, 1},
                                           {-1, 0, -1}, {1, 0, 1},  {1, 0, -1}};
    const std::string flat = write_obj(dir.file("tile"), square);
    const RunResult r =
        run_facet("render '" + flat + "' -o '" + dir.file("out") +
                  "' --size 96x54 --frames 1 --passes color,object_id "
                  "--formats exr --style blinn-phong -D environment.background=false");
    INFO(r.output);
    REQUIRE(r.exit_code == 0);
    CHECK_THAT(r.output, Contains("tile: a model (OBJ)"));
    const PixelBox tile = pixels_of(read_turntable_frame(dir.file("out/tile"), 1), 1);
    CHECK(tile.width() >= 48);
    CHECK(tile.width() <= 95);
    // A .glb saved under another name, and a glTF JSON too, are checked as what they are.
    const std::string knot = dir.file("download.bin");
    std::filesystem::copy_file(source_path("scenes/assets/knot.glb"), knot);
    const RunResult glb = run_facet("validate '" + knot + "' -q");
    INFO(glb.output);
    CHECK(glb.exit_code == 0);
    const std::string gltf = write_bobbing_box(dir.file("bobbing.model"));
    const RunResult json = run_facet("validate '" + gltf + "'");
    INFO(json.output);
    CHECK(json.exit_code == 0);
    CHECK_THAT(json.output, Contains("glTF (.gltf)"));
}

TEST_CASE("turntable options get clear errors, and apply to models only", "[turntable][errors]") {
    TempDir dir("turntable-options");
    const std::string obj = write_obj(dir.file("house.obj"), house());
    const std::string render = "render '" + obj + "' -o '" + dir.file("out") + "' ";
    require_refused(render + "--ground flor",
                    "--ground: expected shadow, floor or none, got "
                    "'flor'; did you mean 'floor'?");
    require_refused(render + "--up x", "--up: expected y or z, got 'x'");
    require_refused(render + "--elevation 95", "--elevation: expected a number from -89.9 to 89.9");
    require_refused(render + "--turns 0x2", "--turns: expected a number");
    require_refused(render + "--background blu", "command line --background blu");
    require_refused(render + "--environment missing.hdr", "command line --environment missing.hdr");
    const std::string scene = write_text(dir.file("cube.yaml"), "objects:\n  - primitive: cube\n");
    require_refused("render '" + scene + "' --turns 2",
                    "--turns: builds the turntable of a model (a mesh file)");
    // facet scene writes the keys its file has, and says so of others.
    require_refused("scene '" + obj + "' -D camera.near=0.5",
                    "command line -D camera.near=0.5: 'camera.near': facet scene writes only the "
                    "keys its file has");
    const RunResult tonemapped = run_facet("scene '" + obj + "' -q -D output.tonemap=agx");
    CHECK(tonemapped.exit_code == 0);
    CHECK_THAT(tonemapped.output, Contains("tonemap: agx"));
}

// (tests/test_read_once.cpp counts the opens of the model file.)
TEST_CASE(
    "facet render MODEL hands the survey's mesh to the world, unless -D asks for other "
    "asset settings",
    "[turntable][assets]") {
    TempDir dir("turntable-read-once");
    const std::vector<glm::vec3> corners = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0},
                                            {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    facet::TurntableRequest request;
    request.model = write_obj(dir.file("tile"), corners);
    request.scene_options.style_dirs = {facet::test::styles_dir()};
    const facet::Turntable turntable = facet::load_turntable(request);
    // The survey's mesh is offered under the path the scene's object names.
    REQUIRE(turntable.meshes.size() == 1);
    const auto& [path, loaded] = *turntable.meshes.begin();
    CHECK(loaded.mesh == turntable.survey.mesh);
    bool named = false;
    for (const facet::ObjectDesc& object : turntable.scene.objects) named |= object.mesh == path;
    CHECK(named);
    // The world takes it, and is the world the file would give.
    const facet::World taken = facet::build_world(turntable.scene, 1, &turntable.meshes);
    const facet::World read = facet::build_world(turntable.scene, 1);
    CHECK(taken.triangle_count() == read.triangle_count());
    CHECK(taken.positions == read.positions);
    // The world charges its budget what the survey's textures took, as a
    // reading of the file would: a charge past the budget is refused.
    facet::LoadedMeshes over = turntable.meshes;
    over.begin()->second.texture_charges.push_back({"huge.png", 65536, 65536, uint64_t(1) << 40});
    CHECK_THROWS_WITH(facet::build_world(turntable.scene, 1, &over),
                      Contains("huge.png") && Contains("texture budget"));
    // Another texture budget: the survey's reading is not the scene's, so
    // nothing is offered and the world reads the file under the user's.
    request.scene_options.overrides.push_back({"assets.texture_budget_mb", "64", "test"});
    CHECK(facet::load_turntable(request).meshes.empty());
}
