#pragma once
// The scene as plain records, straight from the YAML files, each value that a
// user can get wrong keeping the place it came from. Nothing here loads
// meshes or builds render objects: that happens later, from these records.
#include <array>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <glm/ext/vector_int2.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "assets/mesh.hpp"
#include "assets/texture.hpp"
#include "cloth/cloth_params.hpp"
#include "core/diagnostics.hpp"
#include "core/display_transform.hpp"
#include "core/error.hpp"
#include "output/exr_compression.hpp"
#include "output/passes.hpp"
#include "scene/animated.hpp"
#include "scene/style_desc.hpp"
#include "shapes/primitives.hpp"

namespace facet {

// `output.exr_compression`: one method for every EXR file, or one per pass
// over a default (which a multilayer file takes). Unset: zip, but depth
// stored as it is: float depth barely compresses (about 1.4:1 with the
// fast deflate), and its deflate cost more than the rest of the frame's
// files together (docs/performance.md, "Encoding (issue 36)").
struct ExrCompressionChoice {
    ExrCompression all = ExrCompression::zip;
    std::array<std::optional<ExrCompression>, kPassCount> per_pass = unset_depth_stored();
    static std::array<std::optional<ExrCompression>, kPassCount> unset_depth_stored() {
        std::array<std::optional<ExrCompression>, kPassCount> passes{};
        passes[static_cast<size_t>(Pass::depth)] = ExrCompression::none;
        return passes;
    }
    ExrCompression of(Pass p) const { return per_pass[static_cast<size_t>(p)].value_or(all); }
};

// How material textures are read (`output.texture_filter`): by the
// pixel's footprint with up to 16 lookups along its longer axis, or
// trilinearly by its longer axis alone (faster, blurred at a slant).
enum class TextureFilter { anisotropic, trilinear };

// The Sampler::max_anisotropy a filter gives every material texture.
constexpr int max_anisotropy(TextureFilter filter) {
    return filter == TextureFilter::anisotropic ? 16 : 1;
}

struct OutputDesc {
    int width = 1280;
    int height = 720;
    std::vector<int> frames = {1};
    std::string frames_text = "1";
    double fps = 24;
    // What each frame writes (docs/passes.md): colour unless `passes:` says otherwise.
    PassSet passes = {1u << static_cast<int>(Pass::color)};
    bool writes(Pass p) const { return passes.has(p); }
    bool write_png = true;
    bool write_exr = false;
    glm::vec4 background = {0, 0, 0, 1};  // linear RGBA, straight; `transparent` is all 0
    // The normal pass: world space, or the camera's (x right, y up, z towards the viewer).
    bool normals_in_camera_space = false;
    // `exr: multilayer`: one EXR per frame with every pass as layers, instead of one per pass.
    bool exr_multilayer = false;
    // Samples per pixel on a regular grid (1, 4, 9, 16, 25): anti-aliasing
    // by supersampling, resolved in post/resolve.cpp.
    int samples = 1;
    // k of the k x k sample grid (rounded up if `samples` is not a square).
    int samples_per_side() const {
        int k = 1;
        while (k * k < samples) ++k;
        return k;
    }
    DisplayTransform display;  // exposure and tone curve: PNG, video, sheets (not EXR)
    TextureFilter texture_filter = TextureFilter::anisotropic;
    int png_compression = 1;  // zlib level 0..9; 1 is fast, 9 small
    ExrCompressionChoice exr_compression;
    // File names relative to the output folder (docs/output-naming.md);
    // unset: {scene}/{pass}.{frame}.{ext}, with {camera}/ after {scene} when
    // a run renders several cameras. Checked before rendering starts.
    std::optional<std::string> path;
    SourceLocation path_at;
    // Range of linear depth mapped to white..black in the 16-bit depth PNG;
    // unset means "fit the scene's bounds" (docs/scene-format.md).
    std::optional<glm::vec2> depth_range;
    SourceLocation where;
};

struct OrbitDesc {
    Animated<glm::vec3> center = glm::vec3(0, 0, 0);
    Animated<float> radius = 5.0f;       // unused when the camera frames objects
    Animated<float> elevation = 20.0f;   // degrees above the centre's horizontal plane
    Animated<float> start_angle = 0.0f;  // degrees around +Y; 0 puts the camera on +Z
    float turns = 1;                     // circles over the frame range, may be fractional
    bool clockwise = false;              // seen from above; counterclockwise by default
};

// A spline path through control points, travelled at constant speed.
struct PathDesc {
    std::vector<glm::vec3> points;
    bool closed = false;
    // Fraction of the path's length travelled at each frame, 0..1. Unset: 0 at
    // the first frame, 1 at the last (a closed path loops like an orbit).
    std::optional<Animated<float>> at;
    SourceLocation where;
};

enum class FramingFit { sphere, box, geometry };

// `frame:` places the camera so that these objects' bounds fill the view.
struct FramingDesc {
    std::vector<std::string> objects;  // empty: all visible objects
    std::vector<SourceLocation> object_at;
    float margin = 0.1f;  // fraction of the view left free around the bounds
    // sphere: the bounding sphere (the distance stays constant however the
    // objects turn); box: the bounding box corners; geometry: the vertices
    // themselves, exactly (docs/scene-format.md, "Fit objects in the view").
    // Unset: sphere, or geometry over the whole turn for an orbit.
    std::optional<FramingFit> fit;
    SourceLocation where;
};

// Clip planes of a camera that sets neither them nor `frame:`.
inline constexpr float kDefaultCameraNear = 0.1f;
inline constexpr float kDefaultCameraFar = 100;

struct CameraDesc {
    std::string name = "main";
    Animated<glm::vec3> position = glm::vec3(0, 1, 5);
    Animated<glm::vec3> target = glm::vec3(0, 0, 0);
    std::string target_object;  // follow this object's bounds centre instead of `target`
    SourceLocation target_object_at;
    Animated<glm::vec3> up = glm::vec3(0, 1, 0);
    Animated<float> fov = 45.0f;  // vertical, degrees
    // Unset: 0.1 and 100, or fitted around the framed bounds with `frame:`.
    std::optional<Animated<float>> near, far;
    std::optional<OrbitDesc> orbit;
    std::optional<PathDesc> path;
    std::optional<FramingDesc> frame;
    // `from: FILE`: the camera of a glTF file, placed and animated by the
    // file (render/world.hpp loads it); `name` then names it in the file,
    // and empty means the file's first camera.
    std::string from;
    SourceLocation from_at;
    bool name_given = false;
    SourceLocation where;
    std::string key;  // "camera" or "cameras.N", for messages
};

enum class LightType { directional, point, spot, ambient };

// Lights and their shadows: docs/scene-format.md, "Lights" and "Shadows".
struct LightDesc {
    LightType type = LightType::directional;
    Animated<glm::vec3> direction = glm::vec3(0, -1, 0);  // directional, spot: travel direction
    Animated<glm::vec3> position = glm::vec3(0, 0, 0);    // point, spot
    Animated<glm::vec3> color = glm::vec3(1, 1, 1);
    std::optional<Animated<float>> kelvin;  // colour temperature; replaces `color` when set
    Animated<float> intensity = 1.0f;
    std::optional<Animated<float>> range;  // point, spot: the light fades to nothing here
    // Spot cone half-angles from the axis, degrees (KHR_lights_punctual's defaults).
    Animated<float> inner_angle = 0.0f;
    Animated<float> outer_angle = 45.0f;
    bool shadows = false;
    int shadow_resolution = 0;  // texels per side (per cube face); 0 picks the type's default
    Animated<float> shadow_softness = 1.0f;  // percentage-closer filter radius, in texels
    Animated<float> shadow_bias = 1.0f;      // scales the automatic depth bias and normal offset
    // `direction` is in the camera's frame (x right, y up, z towards the
    // viewer) at every frame: the default key light of a scene without
    // `lights:` follows the camera.
    bool camera_relative = false;
    SourceLocation where;
};

// The light a scene without a `lights:` key gets (seed 001 starts with one
// light; docs/references.md): directional, white, intensity 1, travelling
// from above and to the left of the camera towards the scene.
LightDesc default_key_light();

// Values the scene sets on an object's material; unset ones keep what the
// mesh file says (or the defaults for primitives).
struct MaterialDesc {
    std::optional<Animated<glm::vec3>> color;
    std::optional<Animated<float>> ambient, diffuse, specular, shininess;
    // A file the material reads, resolved against the scene file, with
    // where the scene names it and its key (for errors reading it).
    struct Map {
        std::string path;
        SourceLocation at;
        std::string key;
    };
    std::optional<Map> texture;         // the base colour map
    std::optional<Wrap> wrap;           // both axes
    std::optional<glm::vec2> uv_scale;  // texture repeats across the surface
    std::optional<bool> double_sided;
    std::optional<glm::vec3> emissive;   // linear RGB added to the shaded colour
    std::optional<bool> unlit;           // the colour alone, without lights
    std::optional<bool> shadow_catcher;  // only the shadows on it, over the background
    std::optional<glm::vec2> fade;       // [start, end]: fades into the background between
    // The physically based terms (style pbr, docs/pbr.md).
    std::optional<Animated<float>> metallic, roughness;
    // The material's number keys that do not animate (material_parser.cpp's
    // table: ior, clearcoat, ...), each with the value the scene gives, laid
    // over the file's material in the order given.
    std::vector<std::pair<float Material::*, float>> constants;
    std::vector<std::pair<glm::vec3 Material::*, glm::vec3>> colors;  // the same for colours
    std::optional<Map> normal_map, occlusion_map, metal_rough_map, emissive_map;

    // The paths of every map the material reads.
    std::vector<std::string> map_paths() const {
        std::vector<std::string> paths;
        for (const auto* map :
             {&texture, &normal_map, &occlusion_map, &metal_rough_map, &emissive_map})
            if (*map) paths.push_back((*map)->path);
        return paths;
    }
};

// Which keys apply to which type: docs/scene-format.md, "Primitives". The
// values are the primitive builder's own record (shapes/primitives.hpp).
struct PrimitiveDesc {
    PrimitiveSpec spec;
    SourceLocation where;
};

struct SpinDesc {
    glm::vec3 axis = {0, 1, 0};
    float turns = 1;  // over the frame range
};

// A cloth grid simulated as a mass-spring sheet (docs/cloth.md): the
// simulation's own records (cloth/cloth_params.hpp) as the keys set them,
// with gravity in world space and no frame duration yet (anim/cloth_scene.hpp
// turns them into the cloth's local space at the scene's fps), plus the
// keyed wind.
struct ClothDesc {
    ClothParams params;
    ClothPins pins;
    // Keyable values (seed 004 keys "the wind and the parameters"); `params`
    // holds their values at the first key.
    Animated<float> mass = 0.3f, stiffness = 100.0f, friction = 0.1f, damping = 0.05f;
    // The wind, in world space; keyable: the key frames of seed 004.
    Animated<glm::vec3> wind_direction = glm::vec3(1, 0, 0);
    Animated<float> wind_strength = 5.0f;  // m/s
    Animated<float> gust = 0.3f;           // 0..1
    int seed = 1;
    SourceLocation where;
};

// Which animations stored in a glTF file play, and how. Several play
// together, each on the nodes it drives (Blender writes one per object).
struct AnimationChoiceDesc {
    std::vector<std::string> names;  // names, indices as text, or "all"
    double speed = 1;                // playback rate; negative plays backwards
    double offset = 0;               // seconds into the animation at the scene's first frame
    bool loop = true;                // repeat; otherwise hold the last pose
    SourceLocation where;
};

struct ObjectDesc {
    std::string name;
    std::string mesh;  // resolved path, empty for primitives
    SourceLocation mesh_at;
    std::optional<PrimitiveDesc> primitive;
    Animated<glm::vec3> translate = glm::vec3(0, 0, 0);
    Animated<glm::vec3> rotate = glm::vec3(0, 0, 0);  // Euler degrees, applied X then Y then Z
    Animated<glm::vec3> scale = glm::vec3(1, 1, 1);
    MaterialDesc material;
    // The scene's style with this object's `style:` values applied; unset
    // means the scene's style as it is.
    std::optional<StyleDesc> style;
    std::optional<SpinDesc> spin;
    std::optional<AnimationChoiceDesc> animation;  // glTF files only
    std::optional<ClothDesc> cloth;                // the object is a simulated cloth grid
    bool visible = true;
    bool cast_shadows = true;     // appears in the lights' shadow maps
    bool receive_shadows = true;  // shadows darken it
    // `lights:` the glTF file's KHR_lights_punctual lights join the scene's,
    // their intensities times this; unset: the file's lights are not used.
    std::optional<float> file_lights;
    SourceLocation where;
};

// How far facet trusts the files a scene loads (docs/scene-format.md,
// `assets`): paths named inside meshes, per-file size, texture memory.
struct AssetSettings {
    bool allow_paths_outside = false;
    uint64_t max_file_bytes = AssetPathPolicy{}.max_file_bytes;
    uint64_t texture_budget_bytes = kDefaultTextureBudget;
    bool operator==(const AssetSettings&) const = default;
};

// What reading meshes under `settings` may touch: their folders, the file
// size limit, and `budget` for their textures (sized by the settings'
// budget). The one way a reading is set up: a scene's world, and the
// turntable's survey of a model, which its world then reuses only when
// both were read under equal settings.
inline AssetContext asset_context(const AssetSettings& settings, TextureBudget& budget,
                                  unsigned threads) {
    AssetContext assets;
    assets.paths.allow_outside = settings.allow_paths_outside;
    assets.paths.max_file_bytes = settings.max_file_bytes;
    assets.textures = &budget;
    assets.threads = threads;
    return assets;
}

// The light that surrounds the scene (docs/pbr.md, "Environment"): an
// image, a colour or facet's studio, lighting the `pbr` model.
struct EnvironmentDesc {
    enum class Source { studio, color, file, none };
    Source source = Source::studio;
    glm::vec3 color{1.0f};  // Source::color: linear RGB radiance
    std::string file;       // Source::file: an equirectangular .hdr or .exr
    SourceLocation file_at;
    Animated<float> intensity = 1.0f;
    Animated<float> rotation = 0.0f;  // degrees about +Y
    // Turned with the camera about +Y as well (its view's heading added to
    // `rotation`), so light and background stay put in the image as the
    // camera circles: a product turntable's fixed studio.
    bool follow_camera = false;
    // Shown behind the scene instead of the background colour, blurred
    // this much (0 sharp .. 1 the roughest level).
    bool background = false;
    float background_blur = 0.0f;
    SourceLocation where;
};

// A scene facet built instead of reading it from a file (`facet render
// MODEL`, docs/turntables.md): what the manifest records of its making.
struct BuiltScene {
    std::string text_sha256;   // of the YAML text facet made and read
    std::string model_sha256;  // of the model file's bytes
    // The turntable's options as resolved (name, value), defaults included.
    std::vector<std::pair<std::string, std::string>> options;
};

struct SceneDesc {
    std::string path;       // the scene file as given (a built scene: the model's)
    std::string sha256;     // of the text that was read: the manifest's scene_sha256
    std::string name;       // its stem, used in output paths
    std::string directory;  // where relative paths resolve
    OutputDesc output;
    StyleDesc style;
    std::vector<CameraDesc> cameras;  // at least one; names unique
    std::vector<LightDesc> lights;
    std::vector<ObjectDesc> objects;
    AssetSettings assets;
    // The scene's `environment:`; without one, a `pbr` style is lit by the
    // studio and the other styles by their lights alone.
    std::optional<EnvironmentDesc> environment;
    // `variant:` (KHR_materials_variants): the colourway the models are
    // drawn in, `all` for a run of each (job/render_job.hpp,
    // variant_runs), "" for their default materials.
    std::string variant;
    SourceLocation variant_at;
    // Values read but without effect, with where they are (printed by the CLI).
    Warnings warnings;
    // Set when facet made the scene rather than reading it from `path`.
    std::optional<BuiltScene> built;
};

// `variant:` means "all", a run of each variant.
inline constexpr const char* kAllVariants = "all";

// Throws invalid_input at the scene's `variant:` (or the option that set
// it) when it names a variant none of `declared` (the variants the scene's
// models declare) is, listing them; and for `all` when `one_at_a_time`
// (a command that renders one variant, such as preview).
void check_variant(const SceneDesc& scene, const std::vector<std::string>& declared,
                   bool one_at_a_time);

// One `-D key.path=value` (or a command-line option turned into one).
struct Override {
    std::string path;    // dotted, list items by index: objects.0.material.color
    std::string value;   // YAML text
    std::string origin;  // how the user wrote it, for error messages
};

// `text` as a double-quoted YAML scalar that reads back as exactly `text`
// (quotes, backslashes and control characters escaped by yaml-cpp's
// emitter): every piece of YAML facet writes from a user's words (-D values
// from the command line and the preview panel, job templates) goes
// through it.
std::string yaml_quoted(const std::string& text);

// One `-D` as the user typed it, "key.path=value" (split at the first '='),
// -> Override; throws facet::Error (invalid_input) without a key or a '='.
// The value is checked when the override is applied to a scene.
Override parse_define(const std::string& text);

struct SceneOptions {
    std::vector<Override> overrides;
    // Folders searched for style presets by name, in order.
    std::vector<std::string> style_dirs;
};

// Reads and checks a scene file. Throws facet::Error (exit code 2) naming
// file, line, column and key for anything wrong; for a file that is a mesh
// (`facet render MESH` makes its turntable) or neither a scene nor a mesh,
// an error that says so.
SceneDesc load_scene(const std::string& path, const SceneOptions& options);

// Reads and checks a scene given as YAML text, as load_scene reads a file:
// its name, folder (where relative paths resolve) and output folder are
// those of `path`; errors in the text name `text_name`.
SceneDesc load_scene_text(const std::string& text, const std::string& text_name,
                          const std::string& path, const SceneOptions& options);

// What a file given where a scene is expected holds: a scene (a .yaml or
// .yml file, or text that is no mesh), a mesh facet reads (by its bytes,
// else by its name: assets/mesh_format.hpp), or neither (other binary
// data). A file that cannot be read is a scene, unless its name says mesh:
// reading it then says why not.
enum class SceneInputKind { scene, mesh, neither };
SceneInputKind scene_input_kind(const std::string& path);

// Reads a style preset file.
StyleDesc load_style_file(const std::string& path, const std::vector<std::string>& style_dirs);

// The preset as one YAML mapping with its `extends` chain applied (each
// layer's keys over its parent's, mappings merged key by key), for `facet
// styles NAME`. Checks the preset as load_style_file does.
std::string resolved_style_yaml(const std::string& path,
                                const std::vector<std::string>& style_dirs);

// The style keys of `file` (a preset file; with `key` "style", the scene
// file's inline `style:` mapping) with `style.*` overrides applied to them,
// as YAML text, `extends:` kept: a tweaked style written back without
// losing its own keys (facet preview). Comments are not kept.
std::string style_yaml_with_overrides(const std::string& file, const std::string& key,
                                      const std::vector<Override>& overrides);

// The preset files found in the given folders: name -> path, first folder wins.
std::vector<std::pair<std::string, std::string>> list_style_presets(
    const std::vector<std::string>& style_dirs);

}  // namespace facet
