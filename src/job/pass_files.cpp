#include "job/pass_files.hpp"

#include <algorithm>

namespace facet {
namespace {

// Channels `names` of an image whose pixels hold them in that order.
template <typename Pixel>
void add_channels(std::vector<ExrChannel>& out, const Image<Pixel>& image,
                  const std::string& prefix, std::initializer_list<const char*> names,
                  ExrSample type) {
    const uint8_t* base = reinterpret_cast<const uint8_t*>(image.pixels.data());
    const size_t bytes = exr_sample_bytes(type);
    const size_t row = sizeof(Pixel) * static_cast<size_t>(image.width);
    size_t offset = 0;
    for (const char* name : names) {
        out.push_back({prefix + name, type, base + offset, sizeof(Pixel), row});
        offset += bytes;
    }
}

const Image<Rgba16F>& rgba_image(Pass pass, const FrameImages& images) {
    return pass == Pass::alpha ? images.alpha : pass == Pass::lines ? images.lines : images.color;
}

}  // namespace

std::optional<PngSamples> png_view_samples(Pass pass, const OutputDesc& out,
                                           const FrameImages& images, glm::vec2 depth_range) {
    switch (pass) {
        case Pass::color:
        case Pass::alpha:
        case Pass::lines:
            // PNG is for looking at: it gets the exposure and tone curve
            // (EXR stays scene-linear).
            if (!out.display.is_identity())
                return png_color_samples(
                    apply_display_transform(rgba_image(pass, images), out.display));
            return png_color_samples(rgba_image(pass, images));
        case Pass::depth:
            return png_depth_samples(images.depth, depth_range);
        case Pass::normal:
            return png_normal_samples(images.surface.normal);
        case Pass::object_id:
            return png_id_samples(images.surface.object_id);
        case Pass::material_id:
            return png_id_samples(images.surface.material_id);
        case Pass::uv:
            return png_uv_samples(images.surface.uv);
        case Pass::position:
        case Pass::motion:
            break;
    }
    return std::nullopt;
}

std::vector<uint8_t> encode_png_view(Pass pass, const OutputDesc& out, const FrameImages& images,
                                     const PassFileFacts& facts) {
    const std::optional<PngSamples> samples =
        png_view_samples(pass, out, images, facts.depth_range);
    if (!samples) return {};
    return encode_png(*samples, out.png_compression, facts.png_text);
}

std::vector<ExrChannel> exr_pass_channels(Pass pass, const FrameImages& images, bool layered) {
    std::vector<ExrChannel> c;
    const SurfacePassImages& s = images.surface;
    // The colour's channels are R, G, B, A; the other RGBA passes keep
    // their own layer in a multilayer file, as Nuke and Blender name them.
    const std::string rgba_prefix = layered ? std::string(pass_name(pass)) + "." : "";
    switch (pass) {
        case Pass::color:
            add_channels(c, images.color, "", {"R", "G", "B", "A"}, ExrSample::half);
            break;
        case Pass::alpha:
        case Pass::lines:
            add_channels(c, rgba_image(pass, images), rgba_prefix, {"R", "G", "B", "A"},
                         ExrSample::half);
            break;
        case Pass::depth:
            add_channels(c, images.depth, "", {"Z"}, ExrSample::float32);
            break;
        case Pass::normal:
            add_channels(c, s.normal, "N.", {"X", "Y", "Z"}, ExrSample::float32);
            break;
        case Pass::object_id:
            add_channels(c, s.object_id, "object_id.", {"id"}, ExrSample::uint32);
            break;
        case Pass::material_id:
            add_channels(c, s.material_id, "material_id.", {"id"}, ExrSample::uint32);
            break;
        case Pass::uv:
            add_channels(c, s.uv, "uv.", {"U", "V"}, ExrSample::float32);
            break;
        case Pass::position:
            add_channels(c, s.position, "P.", {"X", "Y", "Z"}, ExrSample::float32);
            break;
        case Pass::motion:
            add_channels(c, s.motion, "motion.", {"X", "Y"}, ExrSample::float32);
            break;
    }
    return c;
}

std::vector<ManifestId> pass_ids(const SceneDesc& scene, const World& world) {
    std::vector<ManifestId> ids;
    if (scene.output.writes(Pass::object_id))
        for (size_t o = 0; o < scene.objects.size(); ++o)
            ids.push_back({"object_id", static_cast<uint32_t>(o + 1), scene.objects[o].name, ""});
    if (scene.output.writes(Pass::material_id)) {
        size_t first_of_object = 0;
        for (size_t m = 0; m < world.materials.size(); ++m) {
            const uint32_t object = world.material_object[m];
            if (m == 0 || world.material_object[m - 1] != object) first_of_object = m;
            const std::string& owner = scene.objects[object].name;
            std::string name = world.materials[m].name;
            if (name.empty()) name = owner + ":" + std::to_string(m - first_of_object);
            ids.push_back({"material_id", static_cast<uint32_t>(m + 1), name, owner});
        }
    }
    return ids;
}

uint64_t encoding_bytes(const OutputDesc& out) {
    const uint64_t pixels = static_cast<uint64_t>(out.width) * out.height;
    uint64_t largest = 0;
    for (const PassFile& file : frame_files(out)) {
        uint64_t bytes = 0;
        if (file.format == "png") {
            bytes = 4 * pixels * (file.pass == "depth" ? 2 : 4);
        } else if (file.pass == "multilayer") {
            for (const Pass pass : kAllPasses)
                if (out.writes(pass)) bytes += pixels * frame_image_pixel_bytes(pass);
            bytes *= written_by_facet(out.exr_compression.all) ? 1 : 2;
        } else {
            const Pass pass = *pass_from_name(file.pass);
            bytes = pixels * frame_image_pixel_bytes(pass) *
                    (written_by_facet(out.exr_compression.of(pass)) ? 1 : 2);
        }
        largest = std::max(largest, bytes);
    }
    return largest;
}

std::vector<PassFile> frame_files(const OutputDesc& out) {
    std::vector<PassFile> files;
    for (Pass pass : kAllPasses) {
        if (!out.writes(pass)) continue;
        const std::string name(pass_name(pass));
        if (out.write_png && !pass_is_exr_only(pass)) files.push_back({name, "png"});
        if (out.write_exr && !out.exr_multilayer) files.push_back({name, "exr"});
    }
    if (out.write_exr && out.exr_multilayer) files.push_back({"multilayer", "exr"});
    return files;
}

void encode_frame_files(
    const OutputDesc& out, std::span<const PassFile> files, const FrameImages& images,
    const PassFileFacts& facts,
    const std::function<void(const PassFile&, const std::vector<uint8_t>&)>& write) {
    const int width = images.color.width, height = images.color.height;
    std::vector<ExrChannel> layers;
    for (const PassFile& file : files) {
        if (file.pass == "multilayer") {
            for (Pass pass : kAllPasses)
                if (out.writes(pass)) {
                    const std::vector<ExrChannel> c = exr_pass_channels(pass, images, true);
                    layers.insert(layers.end(), c.begin(), c.end());
                }
            write(file,
                  encode_exr(width, height, layers, facts.exr_attributes, out.exr_compression.all));
            continue;
        }
        const Pass pass = *pass_from_name(file.pass);
        if (file.format == "png")
            write(file, encode_png_view(pass, out, images, facts));
        else
            write(file, encode_exr(width, height, exr_pass_channels(pass, images, false),
                                   facts.exr_attributes, out.exr_compression.of(pass)));
    }
}

}  // namespace facet
