// `output:` of a scene -> OutputDesc (docs/scene-format.md, "output"):
// size, frames, passes and formats, samples, the display transform, the
// texture filter, file naming and compression.
#include <cmath>

#include "core/frame_range.hpp"
#include "core/limits.hpp"
#include "scene/scene_desc.hpp"
#include "scene/yaml_field.hpp"

namespace facet {
namespace {

constexpr EnumName<TextureFilter> kTextureFilters[] = {{TextureFilter::anisotropic, "anisotropic"},
                                                       {TextureFilter::trilinear, "trilinear"}};

PassSet parse_passes(const Field& f) {
    const std::vector<std::string_view> names(kPassNames.begin(), kPassNames.end());
    PassSet passes;
    auto add = [&](const Field& item) {
        const std::string name = item.text();
        const std::optional<Pass> pass = pass_from_name(name);
        if (!pass) item.fail_not_one_of(name, names);
        passes.add(*pass);
    };
    if (f.is_sequence())
        for (size_t i = 0; i < f.size(); ++i) add(f[i]);
    else
        add(f);
    if (passes.empty()) f.fail("must name at least one pass");
    return passes;
}

// Position and motion have no 8-bit view: a run that writes only PNG
// cannot hold them.
void check_pass_formats(const Field& f, const OutputDesc& out) {
    if (out.write_exr) return;
    for (Pass p : {Pass::position, Pass::motion})
        if (out.writes(p)) {
            const Field& at = f.has("formats") ? f["formats"] : f["passes"];
            at.fail("the " + std::string(pass_name(p)) +
                    " pass is written only as EXR: add exr to output.formats");
        }
}

ExrCompression parse_exr_compression_name(const Field& f) {
    const std::vector<std::string_view> names(kExrCompressionNames.begin(),
                                              kExrCompressionNames.end());
    const std::string name = f.text();
    for (size_t i = 0; i < names.size(); ++i)
        if (names[i] == name) return static_cast<ExrCompression>(i);
    f.fail_not_one_of(name, names);
}

// A method name for every file, or a mapping of pass names (and `default`,
// for the passes not named and multilayer files) to method names.
ExrCompressionChoice parse_exr_compression(const Field& f) {
    ExrCompressionChoice choice;
    choice.per_pass = {};  // what the key says replaces the default, depth's too
    if (!f.is_map()) {
        choice.all = parse_exr_compression_name(f);
        return choice;
    }
    std::vector<std::string_view> keys(kPassNames.begin(), kPassNames.end());
    keys.push_back("default");
    for (const std::string& key : f.keys()) {
        if (key == "default") {
            choice.all = parse_exr_compression_name(f[key]);
            continue;
        }
        const std::optional<Pass> pass = pass_from_name(key);
        if (!pass) f.key(key).fail_not_one_of(key, keys);
        choice.per_pass[static_cast<size_t>(*pass)] = parse_exr_compression_name(f[key]);
    }
    return choice;
}

}  // namespace

OutputDesc parse_output(const Field& f) {
    OutputDesc out;
    out.where = f.where();
    f.check_keys({"size", "frames", "fps", "passes", "formats", "background", "samples",
                  "png_compression", "depth_range", "path", "normals", "exr", "exposure", "tonemap",
                  "exr_compression", "texture_filter"});
    if (f.has("path")) {
        out.path = f["path"].text();
        out.path_at = f["path"].where();
    }
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
        } catch (const Error& e) {
            frames.fail(e.detail());
        }
    }
    if (f.has("fps")) out.fps = f["fps"].number(0.001, 1000);
    if (f.has("passes")) out.passes = parse_passes(f["passes"]);
    if (f.has("formats")) {
        auto formats = f["formats"].choices({"png", "exr"});
        if (formats.empty()) f["formats"].fail("must name at least one format");
        out.write_png = out.write_exr = false;
        for (auto& fmt : formats) (fmt == "png" ? out.write_png : out.write_exr) = true;
    }
    check_pass_formats(f, out);
    if (f.has("texture_filter"))
        out.texture_filter = f["texture_filter"].choice_of(kTextureFilters);
    if (f.has("normals"))
        out.normals_in_camera_space = f["normals"].choice({"world", "camera"}) == "camera";
    if (f.has("exr"))
        out.exr_multilayer = f["exr"].choice({"separate", "multilayer"}) == "multilayer";
    if (f.has("background")) out.background = f["background"].background();
    if (f.has("samples")) {
        out.samples = f["samples"].integer(1, 25);
        const int side = out.samples_per_side();
        if (side * side != out.samples) f["samples"].fail("must be a square: 1, 4, 9, 16 or 25");
        if (out.width * side > kMaxImageSide || out.height * side > kMaxImageSide)
            f["samples"].fail("the supersampled image (" + std::to_string(out.width * side) + "x" +
                              std::to_string(out.height * side) + ") would be larger than " +
                              std::to_string(kMaxImageSide) + " on a side");
    }
    if (f.has("exposure")) out.display.exposure = static_cast<float>(f["exposure"].number(-20, 20));
    if (f.has("tonemap")) out.display.tonemap = f["tonemap"].choice_of(kTonemaps);
    if (f.has("png_compression")) out.png_compression = f["png_compression"].integer(0, 9);
    if (f.has("exr_compression")) out.exr_compression = parse_exr_compression(f["exr_compression"]);
    if (f.has("depth_range")) out.depth_range = f["depth_range"].distance_range();
    return out;
}

}  // namespace facet
