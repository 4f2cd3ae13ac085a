#include "cli/video_command.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <set>

#include "cli/options.hpp"
#include "core/display_transform.hpp"
#include "core/error.hpp"
#include "core/plain_text.hpp"
#include "output/atomic_file.hpp"
#include "output/encoders.hpp"
#include "output/manifest.hpp"
#include "video/video_encoder.hpp"

namespace facet {
namespace {

namespace fs = std::filesystem;

// The colour frames of one camera, PNG where the run wrote PNG.
std::vector<ManifestFile> colour_files(const Manifest& m, const std::string& folder,
                                       const std::string& camera_asked) {
    std::set<std::string> cameras;
    for (const ManifestFile& f : m.files)
        if (f.pass == "color") cameras.insert(f.camera);
    if (cameras.empty())
        throw Error(ExitCode::invalid_input,
                    folder + ": the run wrote no colour pass (give --passes color)");
    std::string camera = camera_asked;
    if (camera.empty()) {
        if (cameras.size() > 1) {
            fail_input(command_line("video"), "",
                       "the run has several cameras (" + comma_list(cameras) +
                           "); choose one with --camera");
        }
        camera = *cameras.begin();
    } else if (!cameras.count(camera)) {
        fail_input(command_line("--camera " + camera), "",
                   "the run has no colour frames of camera '" + camera + "'");
    }
    const bool has_png = std::any_of(m.files.begin(), m.files.end(), [&](const ManifestFile& f) {
        return f.pass == "color" && f.camera == camera && f.format == "png";
    });
    std::vector<ManifestFile> files;
    std::set<int> frames;  // that have a colour file of the camera in either format
    for (const ManifestFile& f : m.files)
        if (f.pass == "color" && f.camera == camera) {
            frames.insert(f.frame);
            if (f.format == (has_png ? "png" : "exr")) files.push_back(f);
        }
    // Every frame in the movie, none skipped: a frame with only the other
    // format is a manifest no run writes.
    for (int frame : frames)
        if (std::none_of(files.begin(), files.end(),
                         [&](const ManifestFile& f) { return f.frame == frame; }))
            throw Error(ExitCode::invalid_input,
                        folder + "/manifest.json: frame " + std::to_string(frame) + " of camera '" +
                            camera + "' has no colour " + (has_png ? "PNG" : "EXR") +
                            ", which its other frames have: the movie would skip it");
    std::sort(files.begin(), files.end(),
              [](const ManifestFile& a, const ManifestFile& b) { return a.frame < b.frame; });
    return files;
}

// 8-bit sRGB RGB of a colour file: PNG values as they are (alpha left
// out; the PNG writer applied the scene's exposure and tone curve), EXR
// colour through that display transform, clamped and encoded as sRGB, as
// the PNG writer does.
std::vector<uint8_t> frame_rgb(const std::string& path, const std::string& format,
                               const DisplayTransform& display, int& width, int& height) {
    std::vector<uint8_t> rgb;
    if (format == "png") {
        const DecodedPng png = read_png(path);
        width = png.width;
        height = png.height;
        const int colour = png.channels >= 3 ? 3 : 1;
        rgb.resize(static_cast<size_t>(width) * height * 3);
        for (size_t p = 0; p < rgb.size() / 3; ++p)
            for (int c = 0; c < 3; ++c) {
                const uint16_t v = png.samples[p * png.channels + (colour == 3 ? c : 0)];
                rgb[p * 3 + c] = png.bit_depth == 16 ? narrow_to_byte(v) : static_cast<uint8_t>(v);
            }
        return rgb;
    }
    const DecodedExr exr = read_exr(path);
    width = exr.width;
    height = exr.height;
    const size_t pixels = static_cast<size_t>(width) * height;
    rgb.resize(pixels * 3);
    const std::vector<float>* channel[4] = {};
    for (int c = 0; c < 4; ++c) {
        const std::string name(1, "RGBA"[c]);
        const auto it = std::find(exr.channel_names.begin(), exr.channel_names.end(), name);
        if (it != exr.channel_names.end())
            channel[c] = &exr.channels[static_cast<size_t>(it - exr.channel_names.begin())];
        else if (c < 3)
            throw Error(ExitCode::io_failure, path + ": no " + name + " channel");
    }
    const float gain = exposure_gain(display);
    for (size_t p = 0; p < pixels; ++p) {
        glm::vec4 colour(1.0f);
        for (int c = 0; c < 4; ++c)
            if (channel[c]) colour[c] = (*channel[c])[p];
        colour = display_color(colour, display, gain);
        for (int c = 0; c < 3; ++c) rgb[p * 3 + static_cast<size_t>(c)] = display_byte(colour[c]);
    }
    return rgb;
}

const char* codec_name(VideoFormat f) {
    return f == VideoFormat::mp4 ? "H.264" : f == VideoFormat::webm ? "VP9" : "GIF";
}

}  // namespace

std::string uneven_frames_warning(const std::vector<int>& frames) {
    for (size_t i = 2; i < frames.size(); ++i)
        if (frames[i] - frames[i - 1] != frames[1] - frames[0])
            return "the frames are not evenly spaced; the movie plays them at equal intervals";
    return "";
}

void check_movie_name(const std::string& movie) {
    if (!video_format_for(movie))
        fail_input(command_line(movie), "", "a movie is named .mp4, .webm or .gif");
}

int video_command(const VideoArgs& args) {
    check_movie_name(args.movie);
    const VideoFormat format = *video_format_for(args.movie);
    const std::string manifest_path = (fs::path(args.output_dir) / "manifest.json").string();
    std::error_code ec;
    if (!fs::is_regular_file(manifest_path, ec))
        throw Error(ExitCode::io_failure, args.output_dir +
                                              ": no manifest.json (facet render -o OUT writes "
                                              "into OUT/SCENE/)");
    const Manifest m = read_manifest(manifest_path);
    std::vector<ManifestFile> files = colour_files(m, args.output_dir, args.camera);
    if (!args.frames.empty())
        std::erase_if(files, [&](const ManifestFile& f) {
            return std::find(args.frames.begin(), args.frames.end(), f.frame) == args.frames.end();
        });
    if (files.empty())
        throw Error(ExitCode::invalid_input,
                    args.output_dir + ": no colour frames to make a movie of");
    // Frames every k-th frame of the animation play at fps / k, so the
    // movie keeps the animation's speed; uneven gaps cannot, and are said.
    std::vector<int> frames;
    for (const ManifestFile& f : files) frames.push_back(f.frame);
    const std::string uneven = uneven_frames_warning(frames);
    const int step = frames.size() > 1 ? frames[1] - frames[0] : 0;
    double fps = args.fps > 0 ? args.fps : m.fps;
    if (args.fps <= 0 && uneven.empty() && step > 1) fps /= step;
    if (!uneven.empty() && !args.quiet && !args.spacing_reported)
        std::fprintf(stderr, "facet: warning: %s\n", uneven.c_str());
    std::unique_ptr<VideoEncoder> encoder;
    int width = 0, height = 0;
    for (const ManifestFile& f : files) {
        int w = 0, h = 0;
        const std::vector<uint8_t> rgb =
            frame_rgb((fs::path(args.output_dir) / f.path).string(), f.format, m.display, w, h);
        if (!encoder) {
            width = w;
            height = h;
            encoder = std::make_unique<VideoEncoder>(format, w, h, fps);
        } else if (w != width || h != height) {
            throw Error(ExitCode::invalid_input, f.path + ": frame of another size");
        }
        encoder->add_frame(rgb);
    }
    const std::vector<uint8_t> bytes = encoder->finish();
    const auto parent = fs::path(args.movie).parent_path();
    if (!parent.empty()) make_directories(parent.string());
    write_file_atomically(args.movie, bytes);
    // 4:2:0 movies are coded at even sides (video_encoder.hpp).
    const bool even_sides = format != VideoFormat::gif;
    const int coded_w = even_sides ? (width + 1) / 2 * 2 : width;
    const int coded_h = even_sides ? (height + 1) / 2 * 2 : height;
    if (!args.quiet)
        std::printf("wrote %s (%s, %dx%d%s, %g fps, %s)\n", args.movie.c_str(),
                    count_of(files.size(), "frame", "frames").c_str(), coded_w, coded_h,
                    coded_w != width || coded_h != height ? " padded to even sides" : "", fps,
                    codec_name(format));
    return 0;
}

}  // namespace facet
