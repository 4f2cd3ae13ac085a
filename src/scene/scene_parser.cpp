// YAML scene file -> SceneDesc records (docs/scene-format.md).
#include <algorithm>
#include <filesystem>
#include <sstream>

#include "core/frame_range.hpp"
#include "scene/scene_desc.hpp"
#include "scene/yaml_field.hpp"

namespace facet {
namespace fs = std::filesystem;

StyleDesc parse_style_field(const Field& field, const std::string& base_dir,
                            const std::vector<std::string>& style_dirs);

namespace {

constexpr int kMaxImageSide = 16384;
constexpr float kMaxCoordinate = 1e7f;

std::string resolve_path(const std::string& base_dir, const std::string& relative) {
    fs::path p(relative);
    if (p.is_absolute()) return p.lexically_normal().string();
    return (fs::path(base_dir) / p).lexically_normal().string();
}

std::string existing_file(const Field& field, const std::string& base_dir) {
    std::string path = resolve_path(base_dir, field.text());
    std::error_code ec;
    if (!fs::is_regular_file(path, ec)) field.fail("file not found: " + path);
    return path;
}

glm::vec3 nonzero_direction(const Field& field) {
    glm::vec3 v = field.vec3();
    if (v.x == 0 && v.y == 0 && v.z == 0) field.fail("direction must not be [0, 0, 0]");
    return v;
}

OutputDesc parse_output(const Field& f) {
    OutputDesc out;
    out.where = f.where();
    f.check_keys({"size", "frames", "fps", "passes", "formats", "background", "samples",
                  "png_compression", "depth_range"});
    if (f.has("size")) {
        Field size = f["size"];
        if (!size.is_sequence() || size.size() != 2) size.fail("must be [width, height]");
        out.width = size[0].integer(1, kMaxImageSide);
        out.height = size[1].integer(1, kMaxImageSide);
    }
    if (f.has("frames")) {
        Field frames = f["frames"];
        out.frames_text = frames.text();
        try {
            out.frames = parse_frame_ranges(out.frames_text);
        } catch (const std::invalid_argument& e) {
            frames.fail(e.what());
        }
    }
    if (f.has("fps")) out.fps = f["fps"].number(0.001, 1000);
    if (f.has("passes")) {
        auto passes = f["passes"].choices({"color", "depth"});
        if (passes.empty()) f["passes"].fail("must name at least one pass");
        out.write_color = out.write_depth = false;
        for (auto& p : passes) (p == "color" ? out.write_color : out.write_depth) = true;
    }
    if (f.has("formats")) {
        auto formats = f["formats"].choices({"png", "exr"});
        if (formats.empty()) f["formats"].fail("must name at least one format");
        out.write_png = out.write_exr = false;
        for (auto& fmt : formats) (fmt == "png" ? out.write_png : out.write_exr) = true;
    }
    if (f.has("background")) out.background = f["background"].color4();
    if (f.has("samples")) {
        out.samples = f["samples"].integer(1, 25);
        const int side = out.samples_per_side();
        if (side * side != out.samples) f["samples"].fail("must be a square: 1, 4, 9, 16 or 25");
        if (out.width * side > kMaxImageSide || out.height * side > kMaxImageSide)
            f["samples"].fail("the supersampled image (" + std::to_string(out.width * side) + "x" +
                              std::to_string(out.height * side) + ") would be larger than " +
                              std::to_string(kMaxImageSide) + " on a side");
    }
    if (f.has("png_compression")) out.png_compression = f["png_compression"].integer(0, 9);
    if (f.has("depth_range")) out.depth_range = f["depth_range"].distance_range();
    return out;
}

CameraDesc parse_camera(const Field& f) {
    CameraDesc cam;
    cam.where = f.where();
    f.check_keys({"position", "target", "up", "fov", "near", "far", "orbit"});
    if (f.has("position")) cam.position = f["position"].vec3();
    if (f.has("target")) cam.target = f["target"].vec3();
    if (f.has("up")) cam.up = nonzero_direction(f["up"]);
    if (f.has("fov")) cam.fov = static_cast<float>(f["fov"].number(1, 179));
    if (f.has("near")) cam.near = static_cast<float>(f["near"].number(1e-6, kMaxCoordinate));
    if (f.has("far")) cam.far = static_cast<float>(f["far"].number(1e-6, kMaxCoordinate));
    if (cam.far <= cam.near)
        (f.has("far") ? f["far"] : f)
            .fail("far (" + std::to_string(cam.far) + ") must be greater than near (" +
                  std::to_string(cam.near) + ")");
    if (f.has("orbit")) {
        Field o = f["orbit"];
        o.check_keys({"center", "radius", "elevation", "start_angle", "turns"});
        OrbitDesc orbit;
        if (o.has("center")) orbit.center = o["center"].vec3();
        if (o.has("radius"))
            orbit.radius = static_cast<float>(o["radius"].number(1e-6, kMaxCoordinate));
        if (o.has("elevation"))
            orbit.elevation = static_cast<float>(o["elevation"].number(-89.9, 89.9));
        if (o.has("start_angle"))
            orbit.start_angle = static_cast<float>(o["start_angle"].number(-36000, 36000));
        if (o.has("turns")) orbit.turns = static_cast<float>(o["turns"].number(-1000, 1000));
        cam.orbit = orbit;
    } else if (glm::vec3 d = cam.target - cam.position; d.x == 0 && d.y == 0 && d.z == 0) {
        f.fail("camera position and target are the same point");
    }
    return cam;
}

LightDesc parse_light(const Field& f) {
    LightDesc light;
    light.where = f.where();
    f.check_keys({"type", "direction", "position", "color", "intensity"});
    std::string type = f.require("type").choice({"directional", "point"});
    light.type = type == "point" ? LightType::point : LightType::directional;
    if (light.type == LightType::directional) {
        light.direction = nonzero_direction(f.require("direction"));
        if (f.has("position"))
            f["position"].fail("a directional light has no position; use direction");
    } else {
        light.position = f.require("position").vec3();
        if (f.has("direction")) f["direction"].fail("a point light has no direction; use position");
    }
    if (f.has("color")) light.color = f["color"].color3();
    if (f.has("intensity")) light.intensity = static_cast<float>(f["intensity"].number(0, 1e9));
    return light;
}

MaterialDesc parse_material(const Field& f, const std::string& base_dir) {
    MaterialDesc m;
    f.check_keys({"color", "ambient", "diffuse", "specular", "shininess", "texture", "wrap",
                  "uv_scale", "double_sided"});
    if (f.has("color")) m.color = f["color"].color3();
    if (f.has("ambient")) m.ambient = static_cast<float>(f["ambient"].number(0, 1000));
    if (f.has("diffuse")) m.diffuse = static_cast<float>(f["diffuse"].number(0, 1000));
    if (f.has("specular")) m.specular = static_cast<float>(f["specular"].number(0, 1000));
    if (f.has("shininess")) m.shininess = static_cast<float>(f["shininess"].number(0, 100000));
    if (f.has("texture")) {
        m.texture = existing_file(f["texture"], base_dir);
        m.texture_at = f["texture"].where();
    }
    if (f.has("wrap"))
        m.wrap = f["wrap"].choice({"repeat", "clamp"}) == "clamp" ? TextureWrap::clamp
                                                                  : TextureWrap::repeat;
    if (f.has("uv_scale")) {
        Field s = f["uv_scale"];
        m.uv_scale = s.is_scalar() ? glm::vec2(static_cast<float>(s.number(-1e6, 1e6))) : s.vec2();
    }
    if (f.has("double_sided")) m.double_sided = f["double_sided"].boolean();
    return m;
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
    {"prism", {"sides", "radius", "height"}},
    {"antiprism", {"sides", "radius", "height"}},
    {"pyramid", {"sides", "radius", "height"}},
    {"icosphere", {"radius", "subdivisions", "smooth"}},
    {"torus", {"radius", "tube", "segments", "rings", "smooth"}},
};

constexpr int kMaxDivisions = 4096;
constexpr int kMaxSubdivisions = 7;  // 327680 triangles

const PrimitiveKeys& primitive_type(const Field& f) {
    std::string type = f.text();
    std::string list;
    for (const auto& entry : kPrimitiveKeys) {
        if (type == entry.type) return entry;
        list += std::string(list.empty() ? "" : ", ") + entry.type;
    }
    f.fail("must be one of: " + list + "; got '" + type + "'");
}

float length_value(const Field& f) {
    return static_cast<float>(f.number(1e-6, kMaxCoordinate));
}

PrimitiveDesc parse_primitive(const Field& f) {
    PrimitiveDesc p;
    p.where = f.where();
    if (f.is_scalar()) {  // shorthand: `primitive: sphere`
        p.type = primitive_type(f).type;
        return p;
    }
    f.check_keys({"type", "size", "radius", "height", "segments", "rings", "sides", "tube",
                  "subdivisions", "smooth"});
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
    if (f.has("radius")) p.radius = length_value(f["radius"]);
    if (f.has("height")) p.height = length_value(f["height"]);
    if (f.has("segments")) p.segments = f["segments"].integer(3, kMaxDivisions);
    if (f.has("rings")) p.rings = f["rings"].integer(p.type == "torus" ? 3 : 2, kMaxDivisions);
    if (f.has("sides")) p.sides = f["sides"].integer(3, kMaxDivisions);
    if (f.has("subdivisions")) p.subdivisions = f["subdivisions"].integer(0, kMaxSubdivisions);
    if (f.has("smooth")) p.smooth = f["smooth"].boolean();
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
    return p;
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

ObjectDesc parse_object(const Field& f, size_t index, const std::string& base_dir) {
    ObjectDesc obj;
    obj.where = f.where();
    f.check_keys({"name", "mesh", "primitive", "translate", "rotate", "scale", "material", "spin",
                  "visible"});
    obj.name = f.has("name") ? f["name"].text() : "object" + std::to_string(index);
    if (f.has("mesh") == f.has("primitive"))
        f.fail("an object needs exactly one of 'mesh' (a file) or 'primitive'");
    if (f.has("mesh")) {
        obj.mesh = existing_file(f["mesh"], base_dir);
        obj.mesh_at = f["mesh"].where();
        std::string ext = fs::path(obj.mesh).extension().string();
        for (auto& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        if (ext != ".obj" && ext != ".gltf" && ext != ".glb")
            f["mesh"].fail("unsupported mesh format '" + ext + "' (use .obj, .gltf or .glb)");
    } else {
        obj.primitive = parse_primitive(f["primitive"]);
    }
    if (f.has("translate")) obj.translate = f["translate"].vec3();
    if (f.has("rotate")) obj.rotate = f["rotate"].vec3();
    if (f.has("scale")) {
        Field s = f["scale"];
        obj.scale = s.is_scalar()
                        ? glm::vec3(static_cast<float>(s.number(-kMaxCoordinate, kMaxCoordinate)))
                        : s.vec3();
        if (obj.scale.x == 0 || obj.scale.y == 0 || obj.scale.z == 0)
            s.fail("scale must not be zero on any axis");
    }
    if (f.has("material")) obj.material = parse_material(f["material"], base_dir);
    if (f.has("spin")) {
        Field s = f["spin"];
        s.check_keys({"axis", "turns"});
        SpinDesc spin;
        if (s.has("axis")) spin.axis = parse_axis(s["axis"]);
        if (s.has("turns")) spin.turns = static_cast<float>(s["turns"].number(-1000, 1000));
        obj.spin = spin;
    }
    if (f.has("visible")) obj.visible = f["visible"].boolean();
    return obj;
}

}  // namespace

SceneDesc load_scene(const std::string& path, const SceneOptions& options) {
    auto doc = read_yaml_file(path);
    apply_overrides(*doc, options.overrides);
    Field root = root_field(doc);
    if (root.is_null()) root.fail("the scene file is empty");

    SceneDesc scene;
    scene.path = path;
    scene.name = fs::path(path).stem().string();
    scene.directory = fs::path(path).parent_path().string();
    if (scene.directory.empty()) scene.directory = ".";

    root.check_keys({"output", "style", "camera", "lights", "objects"});
    if (root.has("output")) scene.output = parse_output(root["output"]);
    std::vector<std::string> style_dirs = options.style_dirs;
    style_dirs.push_back((fs::path(scene.directory) / "styles").string());
    if (root.has("style"))
        scene.style = parse_style_field(root["style"], scene.directory, style_dirs);
    else
        scene.style.name = "default";
    if (root.has("camera")) scene.camera = parse_camera(root["camera"]);
    if (root.has("lights")) {
        Field lights = root["lights"];
        for (size_t i = 0; i < lights.size(); ++i) scene.lights.push_back(parse_light(lights[i]));
    }
    Field objects = root.require("objects");
    if (objects.size() == 0) objects.fail("the scene has no objects");
    for (size_t i = 0; i < objects.size(); ++i) {
        scene.objects.push_back(parse_object(objects[i], i, scene.directory));
        for (size_t j = 0; j < i; ++j) {
            if (scene.objects[j].name != scene.objects[i].name) continue;
            // An unnamed object got its name from its index; it has no `name`
            // text to point at, so the object itself is blamed.
            Field at = objects[i].has("name") ? objects[i]["name"] : objects[i];
            at.fail("another object is already named '" + scene.objects[i].name + "'");
        }
    }
    return scene;
}

}  // namespace facet
