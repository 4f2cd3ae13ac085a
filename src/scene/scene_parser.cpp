// YAML scene file -> SceneDesc records (docs/scene-format.md).
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>

#include "assets/mesh_format.hpp"
#include "core/frame_range.hpp"
#include "core/input_file.hpp"
#include "core/limits.hpp"
#include "core/number_text.hpp"
#include "core/plain_text.hpp"
#include "scene/scene_desc.hpp"
#include "scene/style_layers.hpp"
#include "scene/yaml_field.hpp"

namespace facet {
namespace fs = std::filesystem;

LightDesc parse_light(const Field& f);                                     // light_parser.cpp
MaterialDesc parse_material(const Field& f, const std::string& base_dir);  // material_parser.cpp
EnvironmentDesc parse_environment(const Field& f,
                                  const std::string& base_dir);  // environment_parser.cpp
OutputDesc parse_output(const Field& f);                         // output_parser.cpp

namespace {

constexpr EnumName<FramingFit> kFramingFits[] = {
    {FramingFit::sphere, "sphere"}, {FramingFit::box, "box"}, {FramingFit::geometry, "geometry"}};

glm::vec3 nonzero_direction(const Field& field) {
    glm::vec3 v = field.vec3();
    if (v.x == 0 && v.y == 0 && v.z == 0) field.fail("direction must not be [0, 0, 0]");
    return v;
}

AssetSettings parse_assets(const Field& f) {
    f.check_keys({"allow_paths_outside", "max_file_mb", "texture_budget_mb"});
    AssetSettings a;
    constexpr uint64_t kMb = uint64_t(1) << 20;
    if (f.has("allow_paths_outside")) a.allow_paths_outside = f["allow_paths_outside"].boolean();
    if (f.has("max_file_mb"))
        a.max_file_bytes = static_cast<uint64_t>(f["max_file_mb"].integer(1, 1 << 20)) * kMb;
    if (f.has("texture_budget_mb"))
        a.texture_budget_bytes =
            static_cast<uint64_t>(f["texture_budget_mb"].integer(1, 1 << 20)) * kMb;
    return a;
}

// `target:` is a point, a keyed point, or the name of an object to follow.
void parse_target(const Field& f, CameraDesc& cam) {
    if (f.is_scalar() && !f.is_null()) {
        cam.target_object = f.text();
        cam.target_object_at = f.where();
    } else {
        cam.target = f.animated_vec3();
    }
}

OrbitDesc parse_orbit(const Field& o) {
    o.check_keys({"center", "radius", "elevation", "start_angle", "turns", "direction"});
    OrbitDesc orbit;
    if (o.has("center")) orbit.center = o["center"].animated_vec3();
    if (o.has("radius")) orbit.radius = o["radius"].animated_number(1e-6, kMaxCoordinate);
    if (o.has("elevation")) orbit.elevation = o["elevation"].animated_number(-89.9, 89.9);
    if (o.has("start_angle")) orbit.start_angle = o["start_angle"].animated_number(-36000, 36000);
    if (o.has("turns")) orbit.turns = static_cast<float>(o["turns"].number(-1000, 1000));
    if (o.has("direction"))
        orbit.clockwise = o["direction"].choice({"counterclockwise", "clockwise"}) == "clockwise";
    return orbit;
}

PathDesc parse_path(const Field& p) {
    p.check_keys({"points", "closed", "at"});
    PathDesc path;
    path.where = p.where();
    Field points = p.require("points");
    for (size_t i = 0; i < points.size(); ++i) path.points.push_back(points[i].vec3());
    if (p.has("closed")) path.closed = p["closed"].boolean();
    const size_t needed = path.closed ? 3 : 2;
    if (path.points.size() < needed)
        points.fail("a" + std::string(path.closed ? " closed" : "n open") +
                    " path needs at least " + std::to_string(needed) + " points, got " +
                    std::to_string(path.points.size()));
    for (size_t i = 0; i < path.points.size(); ++i) {
        const size_t next = (i + 1) % path.points.size();
        if ((next != 0 || path.closed) && path.points[i] == path.points[next])
            points[next].fail("repeats the point before it; a path needs distinct neighbours");
    }
    if (p.has("at")) path.at = p["at"].animated_number(0, 1);
    return path;
}

FramingDesc parse_framing(const Field& f) {
    FramingDesc framing;
    framing.where = f.where();
    auto add_names = [&](const Field& names) {
        if (names.is_scalar()) {
            if (names.text() != "all") {
                framing.objects.push_back(names.text());
                framing.object_at.push_back(names.where());
            }
            return;
        }
        if (names.size() == 0) names.fail("name at least one object, or write `all`");
        for (size_t i = 0; i < names.size(); ++i) {
            framing.objects.push_back(names[i].text());
            framing.object_at.push_back(names[i].where());
        }
    };
    if (!f.is_map()) {
        add_names(f);
        return framing;
    }
    f.check_keys({"objects", "margin", "fit"});
    if (f.has("objects")) add_names(f["objects"]);
    if (f.has("margin")) framing.margin = static_cast<float>(f["margin"].number(0, 10));
    if (f.has("fit")) framing.fit = f["fit"].choice_of(kFramingFits);
    return framing;
}

CameraDesc parse_camera(const Field& f, bool named, const std::string& base_dir,
                        Warnings& warnings) {
    CameraDesc cam;
    cam.where = f.where();
    cam.key = f.path();
    f.check_keys({"position", "target", "up", "fov", "near", "far", "orbit", "path", "frame",
                  "name", "from"});
    cam.name_given = f.has("name");
    if (f.has("from")) {
        // The file places the camera and sets its lens: nothing else may.
        for (const char* key :
             {"position", "target", "up", "fov", "near", "far", "orbit", "path", "frame"})
            if (f.has(key))
                f[key].fail("a camera `from:` a file takes its " + std::string(key) +
                            " from the file");
        cam.from = existing_file(f["from"], base_dir);
        cam.from_at = f["from"].where();
        std::string ext = fs::path(cam.from).extension().string();
        for (auto& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        if (ext != ".gltf" && ext != ".glb")
            f["from"].fail("cameras are read from glTF files (.gltf or .glb)");
    }
    if (named)
        cam.name = f.require("name").text();
    else if (f.has("name"))
        cam.name = f["name"].text();
    if (cam.name.empty() || cam.name.find_first_of("/\\") != std::string::npos)
        f["name"].fail("a camera name must be non-empty and contain no slashes");
    if (f.has("position")) cam.position = f["position"].animated_vec3();
    if (f.has("target")) parse_target(f["target"], cam);
    if (f.has("up")) cam.up = f["up"].animated_direction();
    if (f.has("fov")) cam.fov = f["fov"].animated_number(1, 179);
    if (f.has("near")) cam.near = f["near"].animated_number(1e-6, kMaxCoordinate);
    if (f.has("far")) cam.far = f["far"].animated_number(1e-6, kMaxCoordinate);
    // Unset planes are the defaults, unless `frame:` fits them (checked below).
    const float near = cam.near ? cam.near->value : kDefaultCameraNear;
    const float far = cam.far ? cam.far->value : kDefaultCameraFar;
    const bool fitted = f.has("frame") && !(cam.near && cam.far);
    if (!fitted && !(cam.near && cam.near->animated()) && !(cam.far && cam.far->animated()) &&
        far <= near)
        (cam.far ? f["far"] : f["near"])
            .fail("far (" + format_number(far) + ") must be greater than near (" +
                  format_number(near) + ")");
    if (f.has("orbit")) cam.orbit = parse_orbit(f["orbit"]);
    if (f.has("path")) cam.path = parse_path(f["path"]);
    if (f.has("frame")) cam.frame = parse_framing(f["frame"]);

    // Each of these decides where the camera is. Contradictions that cannot
    // be meant are errors; a value made redundant (say an orbit added with
    // -D to a scene with a fixed position) is reported and ignored.
    auto ignored = [&](const char* key, const std::string& why) {
        warnings.push_back({f[key].where(), f[key].path(), "is ignored: " + why});
    };
    if (cam.orbit && cam.path) f["path"].fail("a camera has either an orbit or a path, not both");
    if (cam.frame && cam.path)
        f["frame"].fail(
            "`frame:` moves the camera to fit the objects, which a path fixes; use one");
    if (cam.frame && cam.orbit && f["orbit"].has("radius"))
        f["orbit"]["radius"].fail("with `frame:` the orbit radius comes from the objects' bounds");
    if (cam.frame && cam.orbit && f["orbit"].has("center"))
        f["orbit"]["center"].fail("with `frame:` the orbit centre is the objects' bounds centre");
    if (cam.orbit && f.has("position")) ignored("position", "the orbit places the camera");
    if (cam.path && f.has("position")) ignored("position", "the path places the camera");
    if (cam.orbit && f.has("target")) ignored("target", "an orbit looks at its centre");
    if (cam.frame && f.has("target")) ignored("target", "`frame:` aims at the framed objects");
    if (!cam.orbit && !cam.path && !cam.frame && cam.target_object.empty() &&
        !cam.position.animated() && !cam.target.animated()) {
        if (glm::vec3 d = cam.target.value - cam.position.value; d.x == 0 && d.y == 0 && d.z == 0)
            f.fail("camera position and target are the same point");
    }
    return cam;
}

// The keys each primitive type takes besides `type` (docs/scene-format.md).
struct PrimitiveKeys {
    const char* type;
    std::vector<std::string> keys;
};

const std::vector<PrimitiveKeys> kPrimitiveKeys = {
    {"plane", {"size"}},
    {"cube", {"size"}},
    {"box", {"size"}},
    {"sphere", {"radius", "segments", "rings", "smooth"}},
    {"cylinder", {"radius", "height", "segments", "smooth"}},
    {"cone", {"radius", "height", "segments", "smooth"}},
    {"tetrahedron", {"radius"}},
    {"octahedron", {"radius"}},
    {"icosahedron", {"radius"}},
    {"dodecahedron", {"radius"}},
    {"prism", {"sides", "radius", "edge", "top_radius", "height"}},
    {"antiprism", {"sides", "radius", "edge", "height"}},
    {"pyramid", {"sides", "radius", "edge", "top_radius", "height"}},
    {"icosphere", {"radius", "subdivisions", "smooth"}},
    {"torus", {"radius", "tube", "segments", "rings", "smooth"}},
    {"flagpole", {"radius", "height", "segments", "rings", "smooth"}},
    {"platform", {"size", "thickness", "hole_radius", "segments", "smooth"}},
};

constexpr int kMaxDivisions = 4096;
constexpr int kMaxSubdivisions = 7;  // 327680 triangles

const PrimitiveKeys& primitive_type(const Field& f) {
    std::string type = f.text();
    std::vector<std::string_view> names;
    for (const auto& entry : kPrimitiveKeys) {
        if (type == entry.type) return entry;
        names.push_back(entry.type);
    }
    f.fail_not_one_of(type, names);
}

float length_value(const Field& f) {
    return static_cast<float>(f.number(1e-6, kMaxCoordinate));
}

PrimitiveDesc parse_primitive(const Field& f) {
    PrimitiveDesc desc;
    desc.where = f.where();
    PrimitiveSpec& p = desc.spec;
    if (f.is_scalar()) {  // shorthand: `primitive: sphere`
        p.type = primitive_type(f).type;
        if (p.type == "flagpole") p.radius = 0.05f;  // see below
        return desc;
    }
    f.check_keys({"type", "size", "radius", "height", "segments", "rings", "sides", "tube",
                  "subdivisions", "smooth", "thickness", "hole_radius", "edge", "top_radius"});
    const PrimitiveKeys& type = primitive_type(f.require("type"));
    p.type = type.type;
    for (const std::string& key : f.keys()) {
        if (key == "type" || std::find(type.keys.begin(), type.keys.end(), key) != type.keys.end())
            continue;
        std::string list = "type";
        for (const auto& k : type.keys) list += ", " + k;
        f.key(key).fail("'" + key + "' does not apply to a " + p.type + " (its keys are: " + list +
                        ")");
    }
    if (f.has("size")) {
        Field size = f["size"];
        if (p.type != "box") {
            p.size = length_value(size);
        } else if (size.is_scalar()) {
            p.box_size = glm::vec3(length_value(size));
        } else {
            size.vec3();  // reports anything but a list of three numbers
            for (int k = 0; k < 3; ++k) p.box_size[k] = length_value(size[static_cast<size_t>(k)]);
        }
    }
    // A flagpole's tip has twice its radius, so the shared default of 0.5
    // would not fit its default height of 1; its own default is 0.05.
    if (p.type == "flagpole") p.radius = 0.05f;
    if (f.has("radius")) p.radius = length_value(f["radius"]);
    if (f.has("height")) p.height = length_value(f["height"]);
    if (f.has("segments")) p.segments = f["segments"].integer(3, kMaxDivisions);
    if (f.has("rings")) p.rings = f["rings"].integer(p.type == "torus" ? 3 : 2, kMaxDivisions);
    if (f.has("sides")) p.sides = f["sides"].integer(3, kMaxDivisions);
    if (f.has("subdivisions")) p.subdivisions = f["subdivisions"].integer(0, kMaxSubdivisions);
    if (f.has("thickness")) p.thickness = length_value(f["thickness"]);
    if (f.has("hole_radius")) p.hole_radius = length_value(f["hole_radius"]);
    if (f.has("smooth")) p.smooth = f["smooth"].boolean();
    if (f.has("top_radius"))
        p.top_radius = static_cast<float>(f["top_radius"].number(0, kMaxCoordinate));
    if (f.has("edge")) {
        // Seed 001 gives a base by its edge length: a regular n-gon of edge
        // a has circumradius a / (2 sin(pi/n)).
        if (f.has("radius")) f["edge"].fail("give either 'radius' or 'edge', not both");
        const double edge = f["edge"].number(1e-6, kMaxCoordinate);
        p.radius = static_cast<float>(edge / (2 * std::sin(std::numbers::pi / p.sides)));
    }
    p.tube = p.radius / 2;
    if (f.has("tube")) {
        p.tube = length_value(f["tube"]);
        if (p.tube >= p.radius) {
            std::ostringstream s;
            s << "must be greater than 0 and less than the radius (" << p.radius << "), got "
              << f["tube"].text();
            f["tube"].fail(s.str());
        }
    }
    return desc;
}

glm::vec3 parse_axis(const Field& f) {
    if (f.is_scalar()) {
        std::string axis = f.choice({"x", "y", "z"});
        return axis == "x"   ? glm::vec3(1, 0, 0)
               : axis == "y" ? glm::vec3(0, 1, 0)
                             : glm::vec3(0, 0, 1);
    }
    return nonzero_direction(f);
}

ClothDesc parse_cloth(const Field& f) {
    ClothDesc c;
    ClothParams& p = c.params;
    c.where = f.where();
    f.check_keys({"size", "grid", "pin", "mass", "stiffness", "shear", "bend", "max_stretch",
                  "friction", "damping", "wind_drag", "wind_tangential_drag", "gravity", "substeps",
                  "preroll", "wind"});
    if (f.has("size")) {
        Field size = f["size"];
        if (!size.is_sequence() || size.size() != 2) size.fail("must be [width, height]");
        p.width = length_value(size[0]);
        p.height = length_value(size[1]);
    }
    if (f.has("grid")) {
        Field grid = f["grid"];
        if (!grid.is_sequence() || grid.size() != 2) grid.fail("must be [columns, rows]");
        p.columns = grid[0].integer(2, kMaxClothGridSide);
        p.rows = grid[1].integer(2, kMaxClothGridSide);
    }
    if (f.has("pin")) {
        Field pin = f["pin"];
        c.pins.left_edge = false;
        if (pin.is_scalar()) {
            const std::string where = pin.choice({"left_edge", "top_edge", "left_and_top"});
            c.pins.left_edge = where != "top_edge";
            c.pins.top_edge = where != "left_edge";
        } else {
            if (pin.size() == 0) pin.fail("pin at least one vertex");
            const int count = p.columns * p.rows;
            for (size_t i = 0; i < pin.size(); ++i)
                c.pins.vertices.push_back(pin[i].integer(0, count - 1));
        }
    }
    auto number = [&](const char* key, auto& out, double lo, double hi) {
        if (f.has(key))
            out = static_cast<std::remove_reference_t<decltype(out)>>(f[key].number(lo, hi));
    };
    // Keyable, checked for stability at every frame (anim/cloth_scene.cpp).
    auto keyable = [&](const char* key, Animated<float>& out, float& first, double lo, double hi) {
        out = first;
        if (!f.has(key)) return;
        out = f[key].animated_number(lo, hi);
        first = out.value;
    };
    keyable("mass", c.mass, p.mass, 1e-6, 1e6);
    keyable("stiffness", c.stiffness, p.stiffness, 1e-6, 1e9);
    keyable("friction", c.friction, p.friction, 0, kMaxFriction);
    keyable("damping", c.damping, p.damping, 0, 1);
    number("shear", p.shear_stiffness, 0, 1);
    number("bend", p.bend_stiffness, 0, 1);
    number("max_stretch", p.max_stretch, 0.01, 1);
    number("wind_drag", p.wind_drag, 0, kMaxWindDrag);
    number("wind_tangential_drag", p.wind_tangential_drag, 0, kMaxWindDrag);
    number("preroll", p.preroll_seconds, 0, 60);
    if (f.has("gravity")) p.gravity = f["gravity"].vec3();
    if (f.has("substeps")) p.substeps = f["substeps"].integer(0, kMaxClothSubsteps);
    if (f.has("wind")) {
        Field w = f["wind"];
        w.check_keys({"direction", "strength", "gust", "seed"});
        if (w.has("direction")) c.wind_direction = w["direction"].animated_direction();
        if (w.has("strength")) c.wind_strength = w["strength"].animated_number(0, kMaxWindStrength);
        if (w.has("gust")) c.gust = w["gust"].animated_number(0, 1);
        if (w.has("seed")) c.seed = w["seed"].integer(0, 1000000000);
    }
    return c;
}

// One animation or several: `walk`, `0`, `all`, or a list `[walk, blink]`.
std::vector<std::string> animation_names(const Field& f) {
    std::vector<std::string> names;
    if (!f.is_sequence()) return {f.text()};
    for (size_t i = 0; i < f.size(); ++i) names.push_back(f[i].text());
    if (names.empty()) f.fail("give at least one animation name, or all");
    return names;
}

// `animation: walk`, `animation: 0`, `animation: all`, `animation: [walk,
// blink]`, or a mapping with name (one or a list), speed, offset and loop.
AnimationChoiceDesc parse_animation_choice(const Field& f) {
    AnimationChoiceDesc choice;
    choice.where = f.where();
    if (!f.is_map()) {
        choice.names = animation_names(f);
        return choice;
    }
    f.check_keys({"name", "speed", "offset", "loop"});
    choice.names = f.has("name") ? animation_names(f["name"]) : std::vector<std::string>{"0"};
    if (f.has("speed")) choice.speed = f["speed"].number(-1000, 1000);
    if (f.has("offset")) choice.offset = f["offset"].number(-1e7, 1e7);
    if (f.has("loop")) choice.loop = f["loop"].boolean();
    return choice;
}

// An object's `style:` is a preset (name or path) of its own, or values that
// change the scene's style for this object only.
// Outlines, background and the depth view range belong to the whole image,
// so an object's style cannot change them: its own keys are errors, and a
// preset's are left as the scene has them, with a warning.
StyleDesc parse_object_style(const Field& f, const StyleDesc& scene_style,
                             const StyleContext& context, Warnings& warnings) {
    if (f.is_map())
        for (const char* key : {"outlines", "background", "depth_range", "shadows"})
            if (f.has(key))
                f.key(key).fail(std::string("'") + key +
                                "' applies to the whole image; set it in the scene's style");
    StyleDesc style;
    if (f.is_map()) {
        style = scene_style;
        std::vector<std::string> visiting;
        apply_style_layer(f, style, context, visiting);
    } else {
        style = parse_style_field(f, context);
        const bool own_outlines = style.outlines.any();
        if (own_outlines || style.background)
            warnings.push_back({f.where(), f.path(),
                                "the outlines and background of preset '" + style.name +
                                    "' apply to whole images only; the scene's style sets them"});
    }
    style.outlines = scene_style.outlines;
    style.background = scene_style.background;
    style.depth_range = scene_style.depth_range;
    style.shadows = scene_style.shadows;
    return style;
}

ObjectDesc parse_object(const Field& f, size_t index, const std::string& base_dir,
                        const StyleDesc& scene_style, const StyleContext& style_context,
                        Warnings& warnings) {
    ObjectDesc obj;
    obj.where = f.where();
    f.check_keys({"name", "mesh", "primitive", "translate", "rotate", "scale", "material", "spin",
                  "visible", "animation", "style", "cast_shadows", "receive_shadows", "cloth",
                  "lights"});
    obj.name = f.has("name") ? f["name"].text() : "object" + std::to_string(index);
    if (int(f.has("mesh")) + int(f.has("primitive")) + int(f.has("cloth")) != 1)
        f.fail("an object needs exactly one of 'mesh' (a file), 'primitive' or 'cloth'");
    if (f.has("mesh")) {
        // The file is read once, by the world: its format (by its bytes,
        // else its name) and its content are checked there, and an error
        // names this key (render/world.cpp).
        obj.mesh = existing_file(f["mesh"], base_dir);
        obj.mesh_at = f["mesh"].where();
    } else if (f.has("primitive")) {
        obj.primitive = parse_primitive(f["primitive"]);
    } else {
        obj.cloth = parse_cloth(f["cloth"]);
    }
    if (f.has("translate")) obj.translate = f["translate"].animated_vec3();
    if (f.has("rotate")) obj.rotate = f["rotate"].animated_rotation();
    if (f.has("scale")) obj.scale = f["scale"].animated_scale();
    if (f.has("material")) obj.material = parse_material(f["material"], base_dir);
    if (f.has("style"))
        obj.style = parse_object_style(f["style"], scene_style, style_context, warnings);
    if (f.has("spin")) {
        Field s = f["spin"];
        s.check_keys({"axis", "turns"});
        SpinDesc spin;
        if (s.has("axis")) spin.axis = parse_axis(s["axis"]);
        if (s.has("turns")) spin.turns = static_cast<float>(s["turns"].number(-1000, 1000));
        obj.spin = spin;
    }
    if (f.has("visible")) obj.visible = f["visible"].boolean();
    if (f.has("cast_shadows")) obj.cast_shadows = f["cast_shadows"].boolean();
    if (f.has("receive_shadows")) obj.receive_shadows = f["receive_shadows"].boolean();
    if (f.has("lights")) {
        const Field lights = f["lights"];
        const std::string ext = fs::path(obj.mesh).extension().string();
        if (obj.mesh.empty() ||
            (ext != ".gltf" && ext != ".glb" && ext != ".GLTF" && ext != ".GLB"))
            lights.fail("only glTF meshes carry lights (KHR_lights_punctual)");
        if (lights.is_map()) {
            lights.check_keys({"intensity"});
            obj.file_lights = lights.has("intensity")
                                  ? static_cast<float>(lights["intensity"].number(0, 1e9))
                                  : 1.0f;
        } else if (lights.boolean()) {
            obj.file_lights = 1.0f;
        }
    }
    if (f.has("animation")) {
        if (obj.mesh.empty()) f["animation"].fail("only glTF meshes carry animations");
        obj.animation = parse_animation_choice(f["animation"]);
    }
    return obj;
}

// Cameras name objects to follow or frame; the names must exist.
void check_object_references(const SceneDesc& scene) {
    auto check = [&](const std::string& name, const SourceLocation& at, const std::string& key) {
        for (const ObjectDesc& obj : scene.objects)
            if (obj.name == name) return;
        fail_input(at, key,
                   "no object named '" + name + "' (objects: " +
                       comma_list(scene.objects, [](const ObjectDesc& o) { return o.name; }) + ")");
    };
    for (const CameraDesc& cam : scene.cameras) {
        if (!cam.target_object.empty())
            check(cam.target_object, cam.target_object_at, cam.key + ".target");
        if (cam.frame)
            for (size_t i = 0; i < cam.frame->objects.size(); ++i)
                check(cam.frame->objects[i], cam.frame->object_at[i], cam.key + ".frame");
    }
}

bool has_yaml_name(const std::string& path) {
    std::string ext = fs::path(path).extension().string();
    for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return ext == ".yaml" || ext == ".yml";
}

// What a scene file holds and what a mesh file is, for a file that is neither.
std::string neither_scene_nor_mesh() {
    return "neither a scene nor a mesh facet reads: a scene is a YAML file (.yaml) whose top "
           "level is a mapping (output, camera, objects, ...), and the meshes facet reads are " +
           mesh_formats_read();
}

// The checks of the top of the document, before its keys.
void check_scene_root(const Field& root, const std::string& path) {
    if (root.is_null()) root.fail("the scene file is empty");
    // Text in another format than YAML, named as something else than YAML,
    // is no scene: saying so helps more than "must be a mapping".
    if (!root.is_map() && !has_yaml_name(path))
        fail_input({path, 0, 0, ""}, "", neither_scene_nor_mesh());
}

SceneDesc scene_from_document(const std::shared_ptr<YamlDocument>& doc, const std::string& path,
                              const SceneOptions& options) {
    // -D style.KEY=VALUE changes the style whatever the scene's `style:` is
    // (a preset name is a plain value with no keys to set), so these
    // overrides form a layer of their own, applied after the scene's style.
    std::vector<Override> scene_overrides, style_overrides;
    for (const Override& ov : options.overrides)
        (ov.path.rfind("style.", 0) == 0 ? style_overrides : scene_overrides).push_back(ov);
    apply_overrides(*doc, scene_overrides);
    Field root = root_field(doc);
    check_scene_root(root, path);

    SceneDesc scene;
    scene.sha256 = doc->sha256;
    scene.path = path;
    scene.name = fs::path(path).stem().string();
    scene.directory = fs::path(path).parent_path().string();
    if (scene.directory.empty()) scene.directory = ".";

    root.check_keys({"output", "style", "camera", "cameras", "lights", "objects", "assets",
                     "environment", "variant"});
    if (root.has("variant")) {
        scene.variant = root["variant"].text();
        scene.variant_at = root["variant"].where();
        if (scene.variant.empty()) root["variant"].fail("names no variant; give a name or all");
    }
    if (root.has("output")) scene.output = parse_output(root["output"]);
    if (root.has("environment"))
        scene.environment = parse_environment(root["environment"], scene.directory);
    if (root.has("assets")) scene.assets = parse_assets(root["assets"]);
    StyleContext style_context{options.style_dirs, scene.directory};
    style_context.style_dirs.push_back((fs::path(scene.directory) / "styles").string());
    if (root.has("style"))
        scene.style = parse_style_field(root["style"], style_context);
    else
        scene.style.name = "default";
    if (!style_overrides.empty()) {
        auto layer = read_yaml_text("style: {}", "command line");
        apply_overrides(*layer, style_overrides);
        std::vector<std::string> visiting;
        apply_style_layer(root_field(layer)["style"], scene.style, style_context, visiting);
    }
    // Physically based styles are made for a product's tone curve: the
    // scene's own `tonemap:` wins.
    if (scene.style.shading == ShadingModel::pbr &&
        !(root.has("output") && root["output"].has("tonemap")))
        scene.output.display.tonemap = Tonemap::neutral;
    if (root.has("camera") && root.has("cameras"))
        root["cameras"].fail("give either `camera` (one) or `cameras` (a named list), not both");
    if (root.has("cameras")) {
        Field cameras = root["cameras"];
        if (cameras.size() == 0) cameras.fail("the list of cameras is empty");
        for (size_t i = 0; i < cameras.size(); ++i) {
            scene.cameras.push_back(
                parse_camera(cameras[i], true, scene.directory, scene.warnings));
            for (size_t j = 0; j < i; ++j)
                if (scene.cameras[j].name == scene.cameras[i].name)
                    cameras[i]["name"].fail("another camera is already named '" +
                                            scene.cameras[i].name + "'");
        }
    } else {
        scene.cameras.push_back(root.has("camera") ? parse_camera(root["camera"], false,
                                                                  scene.directory, scene.warnings)
                                                   : CameraDesc{});
    }
    if (root.has("lights")) {  // `lights: []` is a scene without lights, on purpose
        Field lights = root["lights"];
        for (size_t i = 0; i < lights.size(); ++i) scene.lights.push_back(parse_light(lights[i]));
    } else {
        scene.lights.push_back(default_key_light());
        // Under `pbr` the studio environment lights the scene too: the key
        // light is there for its shadow and its direction, at half strength,
        // so that a white surface facing both is not twice as bright.
        if (scene.style.shading == ShadingModel::pbr) scene.lights.back().intensity = 0.5f;
    }
    if (scene.style.shadows)
        for (LightDesc& light : scene.lights)
            if (light.type != LightType::ambient) light.shadows = *scene.style.shadows;
    Field objects = root.require("objects");
    if (objects.size() == 0) objects.fail("the scene has no objects");
    for (size_t i = 0; i < objects.size(); ++i) {
        scene.objects.push_back(parse_object(objects[i], i, scene.directory, scene.style,
                                             style_context, scene.warnings));
        for (size_t j = 0; j < i; ++j) {
            if (scene.objects[j].name != scene.objects[i].name) continue;
            // An unnamed object got its name from its index; it has no `name`
            // text to point at, so the object itself is blamed.
            Field at = objects[i].has("name") ? objects[i]["name"] : objects[i];
            at.fail("another object is already named '" + scene.objects[i].name + "'");
        }
    }
    check_object_references(scene);
    return scene;
}

}  // namespace

void check_variant(const SceneDesc& scene, const std::vector<std::string>& declared,
                   bool one_at_a_time) {
    if (scene.variant.empty()) return;
    const bool all = scene.variant == kAllVariants;
    const bool known = std::find(declared.begin(), declared.end(), scene.variant) != declared.end();
    // `all` is every variant, even where a model names one so.
    if (known && !all) return;
    if (declared.empty())
        fail_input(scene.variant_at, "variant",
                   "no model in the scene declares variants (KHR_materials_variants): each is "
                   "drawn in its default materials without `variant:`");
    const std::string list = comma_list(declared);
    if (!all)
        fail_input(scene.variant_at, "variant",
                   "no model in the scene declares the variant '" + scene.variant +
                       "' (variants: " + list + ", or all)");
    if (one_at_a_time)
        fail_input(scene.variant_at, "variant",
                   "all: this command draws one variant at a time (render and validate take "
                   "all); give one of: " +
                       list);
}

SceneInputKind scene_input_kind(const std::string& path) {
    if (has_yaml_name(path)) return SceneInputKind::scene;
    // A mesh's name says so without a read; the bytes of a file without
    // one are looked at (the loader reads the file once, later).
    if (mesh_format_of_name(path)) return SceneInputKind::mesh;
    if (!input_file_problem(path).empty()) return SceneInputKind::scene;  // its reader says why
    if (recognise_mesh_file(path)) return SceneInputKind::mesh;
    // A YAML scene is text: a NUL byte at its start says it is not one.
    std::ifstream in(path, std::ios::binary);
    std::string head(4096, '\0');
    in.read(head.data(), static_cast<std::streamsize>(head.size()));
    head.resize(static_cast<size_t>(in.gcount()));
    return head.find('\0') == std::string::npos ? SceneInputKind::scene : SceneInputKind::neither;
}

SceneDesc load_scene(const std::string& path, const SceneOptions& options) {
    const SceneInputKind kind = scene_input_kind(path);
    if (kind == SceneInputKind::mesh) {
        const std::optional<MeshFormat> format = recognise_mesh_file(path);
        fail_input({path, 0, 0, ""}, "",
                   "a mesh (" + (format ? mesh_format_name(*format) : std::string("?")) +
                       "), not a scene: `facet render " + path +
                       "` makes a turntable of it, and `facet scene " + path + " -o " +
                       fs::path(path).stem().string() +
                       ".yaml` writes that turntable as a scene file to edit");
    }
    if (kind == SceneInputKind::neither) fail_input({path, 0, 0, ""}, "", neither_scene_nor_mesh());
    return scene_from_document(read_yaml_file(path), path, options);
}

SceneDesc load_scene_text(const std::string& text, const std::string& text_name,
                          const std::string& path, const SceneOptions& options) {
    return scene_from_document(read_yaml_text(text, text_name), path, options);
}

}  // namespace facet
