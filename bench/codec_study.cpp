#include "codec_study.hpp"

#include <cstdio>
#include <functional>
#include <vector>

#include "bench_common.hpp"
#include "core/sha256.hpp"
#include "output/encoders.hpp"

namespace facet_bench {
namespace {

struct Codec {
    std::string file, codec;
    double raw_bytes;
    std::function<std::vector<uint8_t>()> encode;
};

std::vector<Codec> codecs(const facet::FrameImages& images) {
    const facet::HalfColorImage& color = images.color;
    const facet::DepthImage& depth = images.depth;
    const double color_png_raw = 3.0 * color.width * color.height;  // RGB8 (opaque frames)
    const double depth_png_raw = 2.0 * depth.width * depth.height;  // grey16
    const double color_exr_raw = 8.0 * color.width * color.height;  // RGBA half
    const double depth_exr_raw = 4.0 * depth.width * depth.height;  // Z float
    std::vector<Codec> list;
    list.push_back({"colour PNG", "level 1", color_png_raw,
                    [&] { return facet::encode_png_color(color, 1); }});
    list.push_back({"depth PNG", "level 1", depth_png_raw, [&] {
                        return facet::encode_png(
                            facet::png_depth_samples(depth, images.depth_view_range), 1);
                    }});
    for (size_t i = 0; i < facet::kExrCompressionNames.size(); ++i) {
        const auto c = static_cast<facet::ExrCompression>(i);
        const std::string name(facet::kExrCompressionNames[i]);
        list.push_back({"colour EXR", name, color_exr_raw,
                        [&, c] { return facet::encode_exr_color(color, {}, c); }});
        list.push_back({"depth EXR", name, depth_exr_raw,
                        [&, c] { return facet::encode_exr_depth(depth, {}, c); }});
    }
    return list;
}

}  // namespace

std::string codec_table_header() {
    return "| scene | file | codec | raw MB | ms | MB/s | ratio | SHA-256 ms |\n"
           "|---|---|---|---:|---:|---:|---:|---:|\n";
}

std::string codec_rows(const std::string& scene_name, const facet::FrameImages& images,
                       int repeats) {
    std::string rows;
    for (const Codec& c : codecs(images)) {
        std::vector<double> ms, hash_ms;
        std::vector<uint8_t> bytes;
        for (int r = 0; r < repeats; ++r) {
            const auto t0 = Clock::now();
            bytes = c.encode();
            const auto t1 = Clock::now();
            const std::string digest = facet::sha256_hex(bytes);
            ms.push_back(ms_since(t0, t1));
            hash_ms.push_back(ms_since(t1, Clock::now()));
        }
        const double mb = c.raw_bytes / 1e6, t = median(ms);
        char line[256];
        std::snprintf(line, sizeof line, "| %s | %s | %s | %.1f | %.1f | %.0f | %.2f | %.1f |\n",
                      scene_name.c_str(), c.file.c_str(), c.codec.c_str(), mb, t, mb / (t / 1e3),
                      c.raw_bytes / static_cast<double>(bytes.size()), median(hash_ms));
        rows += line;
    }
    return rows;
}

}  // namespace facet_bench
