// Movies of a run (docs/video.md), decoded back with FFmpeg's libraries:
// frame count, size, and the first frame against the first PNG.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>

#include "output/encoders.hpp"
#include "support.hpp"
#include "video/video_encoder.hpp"
#include "video_reader.hpp"

using namespace facet::test;
using Catch::Matchers::Contains;

namespace {

std::string render_small(const TempDir& dir, const std::string& extra = "") {
    const RunResult r =
        run_facet("render '" + source_path("tests/scenes/shapes.yaml") +
                  "' --size 47x31 --frames 1-3 --passes color --formats png -q -o '" +
                  dir.file("out") + "' " + extra);
    if (r.exit_code != 0) throw std::runtime_error(r.output);
    return dir.file("out/shapes");
}

// Mean absolute difference, in 8-bit codes, between the movie's first frame
// and the first PNG, over the PNG's pixels.
double first_frame_error(const facet::VideoSummary& movie, const std::string& png_path) {
    const facet::DecodedPng png = facet::read_png(png_path);
    double sum = 0;
    for (int y = 0; y < png.height; ++y)
        for (int x = 0; x < png.width; ++x)
            for (int c = 0; c < 3; ++c)
                sum += std::abs(
                    double(
                        png.samples[(static_cast<size_t>(y) * png.width + x) * png.channels + c]) -
                    movie.first_frame_rgb[(static_cast<size_t>(y) * movie.width + x) * 3 + c]);
    return sum / (png.width * png.height * 3.0);
}

}  // namespace

TEST_CASE("video: render --video writes an H.264 MP4 of the colour frames", "[video]") {
    TempDir dir("video-mp4");
    const std::string movie = dir.file("shapes.mp4");
    const std::string run = render_small(dir, "--video '" + movie + "'");
    const facet::VideoSummary v = facet::read_video(movie);
    CHECK(v.codec == "h264");
    CHECK(v.frames == 3);
    // 4:2:0 needs even sides: the odd frame is padded by its edge pixels.
    CHECK(v.width == 48);
    CHECK(v.height == 32);
    CHECK(v.fps == Approx(24));
    const double error = first_frame_error(v, run + "/color.0001.png");
    INFO("mean error " << error << " codes");
    CHECK(error < 6);

    // The same frames give the same bytes, whether made by render or video.
    const std::string again = dir.file("again.mp4");
    REQUIRE(run_facet("video '" + run + "' '" + again + "' -q").exit_code == 0);
    CHECK(read_file(movie) == read_file(again));
}

TEST_CASE("video: facet video makes GIF and WebM from a run, deterministically", "[video]") {
    TempDir dir("video-gif");
    const std::string run = render_small(dir);
    const std::string gif = dir.file("shapes.gif");
    const RunResult made = run_facet("video '" + run + "' '" + gif + "' --fps 12");
    INFO(made.output);
    REQUIRE(made.exit_code == 0);
    CHECK_THAT(made.output, Contains("3 frames, 47x31, 12 fps, GIF"));
    const facet::VideoSummary g = facet::read_video(gif);
    CHECK(g.codec == "gif");
    CHECK(g.frames == 3);
    CHECK(g.width == 47);
    CHECK(g.height == 31);
    const double error = first_frame_error(g, run + "/color.0001.png");
    INFO("mean error " << error << " codes");
    CHECK(error < 4);  // one 256-colour palette for a few flat-shaded frames

    const std::string webm = dir.file("shapes.webm");
    REQUIRE(run_facet("video '" + run + "' '" + webm + "' -q").exit_code == 0);
    const facet::VideoSummary w = facet::read_video(webm);
    CHECK(w.codec.find("vp9") != std::string::npos);
    CHECK(w.frames == 3);

    // The same frames give the same bytes.
    const std::string again = dir.file("again.gif");
    REQUIRE(run_facet("video '" + run + "' '" + again + "' --fps 12 -q").exit_code == 0);
    CHECK(read_file(gif) == read_file(again));
    const std::string webm_again = dir.file("again.webm");
    REQUIRE(run_facet("video '" + run + "' '" + webm_again + "' -q").exit_code == 0);
    CHECK(read_file(webm) == read_file(webm_again));
}

TEST_CASE("video: bad names and missing runs fail without touching an old movie", "[video]") {
    TempDir dir("video-errors");
    const std::string old_movie = write_text(dir.file("old.mp4"), "an older movie");
    const RunResult no_run = run_facet("video '" + dir.path() + "' '" + old_movie + "'");
    CHECK(no_run.exit_code == 4);
    CHECK_THAT(no_run.output, Contains("no manifest.json"));
    CHECK(read_file(old_movie) == "an older movie");
    const RunResult avi = run_facet("video '" + dir.path() + "' movie.avi");
    CHECK(avi.exit_code == 2);
    CHECK_THAT(avi.output, Contains(".mp4, .webm or .gif"));
    // render checks the movie's name before rendering anything.
    const RunResult render =
        run_facet("render '" + source_path("tests/scenes/shapes.yaml") +
                  "' -f 1 --size 32x24 -o '" + dir.file("out") + "' --video x.mov");
    CHECK(render.exit_code == 2);
    CHECK_FALSE(std::filesystem::exists(dir.file("out")));
}

TEST_CASE("video: --video-only keeps the movie and no images", "[video]") {
    TempDir dir("video-only");
    const std::string movie = dir.file("movies/shapes.gif");
    const RunResult r = run_facet("render '" + source_path("tests/scenes/shapes.yaml") +
                                  "' --size 40x30 --frames 1-2 -q --video '" + movie +
                                  "' --video-only -o '" + dir.file("out") + "'");
    INFO(r.output);
    REQUIRE(r.exit_code == 0);
    CHECK(facet::read_video(movie).frames == 2);
    CHECK_FALSE(std::filesystem::exists(dir.file("out")));
    // Nothing but the movie is left beside it.
    int entries = 0;
    for (const auto& e : std::filesystem::directory_iterator(dir.file("movies"))) {
        INFO(e.path());
        ++entries;
    }
    CHECK(entries == 1);
}
