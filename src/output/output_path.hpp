#pragma once
// Output file name templates (docs/output-naming.md): "{scene}/{pass}.{frame}.{ext}"
// names each file a run writes, relative to the output folder. A template is
// parsed and checked once, then expanded for every (frame, camera, pass, ext).
#include <string>
#include <vector>

#include "core/enum_names.hpp"

namespace facet {

// The default reproduces the names facet has always written: <scene>/color.0001.png.
inline constexpr const char* kDefaultOutputTemplate = "{scene}/{pass}.{frame}.{ext}";
// The default when one run renders several cameras: a folder per camera.
inline constexpr const char* kMultiCameraOutputTemplate = "{scene}/{camera}/{pass}.{frame}.{ext}";
// The defaults for one of several variants' runs (`variant: all`): a folder
// per variant, each with its run's manifest, and in it one per camera.
inline constexpr const char* kMultiVariantOutputTemplate = "{scene}/{variant}/{pass}.{frame}.{ext}";
inline constexpr const char* kMultiVariantCameraOutputTemplate =
    "{scene}/{variant}/{camera}/{pass}.{frame}.{ext}";

// Zero padding of {frame} when the template gives no width.
inline constexpr int kDefaultFramePadding = 4;

enum class Placeholder { scene, camera, pass, frame, ext, variant };

// The names written between braces.
inline constexpr EnumName<Placeholder> kPlaceholders[] = {
    {Placeholder::scene, "scene"}, {Placeholder::camera, "camera"},
    {Placeholder::pass, "pass"},   {Placeholder::frame, "frame"},
    {Placeholder::ext, "ext"},     {Placeholder::variant, "variant"}};

struct TemplateSegment {
    enum class Kind {
        literal,      // `text`, copied as is; never contains '/'
        placeholder,  // `placeholder`, replaced by its field
        separator,    // '/' between two path components
    };
    Kind kind = Kind::literal;
    std::string text;
    Placeholder placeholder = Placeholder::scene;
    int frame_padding = kDefaultFramePadding;  // digits, for Placeholder::frame only
};

struct OutputTemplate {
    std::string text;  // as the user wrote it, for messages
    std::vector<TemplateSegment> segments;

    bool uses(Placeholder placeholder) const;
};

// The values one output file is named from.
struct OutputNameFields {
    std::string scene;   // scene file stem
    std::string camera;  // camera name
    std::string pass;    // color, depth, ...
    int frame = 0;
    std::string ext;      // png, exr
    std::string variant;  // the run's KHR_materials_variants variant ("" for none)
};

// Parses and checks a template. Throws facet::Error (invalid_input) naming the
// template and the offending text for: an empty template, an unknown
// placeholder (with the closest known name), an unclosed '{' or a stray '}',
// a bad frame padding (width must be 1..9), an absolute path, a '..' or '.'
// component, an empty component ("a//b") or a missing file name ("a/").
OutputTemplate parse_output_template(const std::string& text);

// The file's path relative to the output folder. Throws facet::Error (invalid_input)
// when a field the template uses would leave the output folder or break the
// path apart: empty, "." or "..", or containing '/'.
std::string expand(const OutputTemplate& output_template, const OutputNameFields& fields);

// Throws facet::Error (invalid_input) naming two (frame, camera, pass, ext)
// combinations that expand to the same file, or one that would overwrite
// manifest.json. Run it before rendering anything. Each combination is
// expanded once and looked up in a hash set, so long frame lists are cheap.
// `variant` is the run's, as OutputNameFields::variant.
void check_unique_outputs(const OutputTemplate& output_template, const std::string& scene,
                          const std::vector<std::string>& cameras,
                          const std::vector<std::string>& passes,
                          const std::vector<std::string>& exts, const std::vector<int>& frames,
                          const std::string& variant = "");

// Where manifest.json goes, relative to the output folder ("" is the output
// folder itself): the leading directory components of the template that hold
// only literals, {scene} and {variant} (a run renders one), and {camera} too
// when `single_camera` says one camera is rendered. Those components are
// expanded from `fixed` (scene, variant and camera); the file name component
// never counts.
//   {scene}/{pass}.{frame}.{ext}                       -> "<scene>"
//   renders/{scene}/{camera}/f####.{ext}, one camera   -> "renders/<scene>/<camera>"
//   {pass}/{frame}.{ext}                               -> ""
std::string manifest_directory(const OutputTemplate& output_template, const OutputNameFields& fixed,
                               bool single_camera);

// Whether manifest_directory's folder names the variant: runs of several
// variants need it, for each has a manifest of its own.
bool manifest_directory_names_variant(const OutputTemplate& output_template, bool single_camera);

// `output_path` (relative to the output folder, as from expand) made relative
// to `manifest_dir` (as from manifest_directory), for the manifest's `path`
// entries. Throws facet::Error (invalid_input) if the file is not inside it.
std::string path_relative_to_manifest(const std::string& output_path,
                                      const std::string& manifest_dir);

}  // namespace facet
