// How `facet compare` judges each kind of image (docs/regression.md,
// "Metrics"): EXR colour at one exposure per sequence, alpha apart from
// colour, normals by angle, ids exactly, the flicker figure, and the
// thresholds' rules. Folders with manifests are made here from synthetic
// images, so each case changes exactly one thing.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>

#include "compare/compare_run.hpp"
#include "compare/judge.hpp"
#include "compare/thresholds.hpp"
#include "compare_support.hpp"
#include "output/manifest.hpp"
#include "scene/thresholds_file.hpp"

using namespace facet;
using namespace facet::test;

namespace {

// A run's folder: files written with write(), then the manifest.
struct RunFolder {
    std::string dir;
    Manifest manifest;

    explicit RunFolder(std::string path) : dir(std::move(path)) {
        std::filesystem::create_directories(dir);
        manifest.scene = "synthetic.yaml";
        manifest.style = "none";
        manifest.width = 64;
        manifest.height = 48;
    }
    void write(int frame, const std::string& pass, const std::string& format,
               const std::vector<uint8_t>& bytes) {
        const std::string name = pass + "." + std::to_string(frame) + "." + format;
        write_bytes(dir + "/" + name, bytes);
        manifest.frames.push_back({frame, "main", 0, 0});
        manifest.files.push_back({frame, "main", pass, format, name, ""});
    }
    void finish() { write_manifest(dir + "/manifest.json", manifest); }
};

// A smooth HDR test image: a ramp from 0 to `peak` with a bright spot.
HalfColorImage hdr_image(float peak, float scale_x = 1) {
    HalfColorImage image(64, 48);
    for (int y = 0; y < 48; ++y)
        for (int x = 0; x < 64; ++x) {
            const float v = peak * (0.05f + 0.9f * x * scale_x / 63.0f) * (0.5f + 0.5f * y / 47.0f);
            image.at(x, y) = to_half(glm::vec4(v, 0.8f * v, 0.6f * v, 1));
        }
    return image;
}

CompareReport compare_folders(const std::string& ref, const std::string& candidate,
                              CompareThresholds thresholds = default_thresholds()) {
    CompareRequest request;
    request.ref = ref;
    request.candidate = candidate;
    request.thresholds = std::move(thresholds);
    return run_compare(request);
}

const FileResult& frame_result(const CompareReport& report, int frame) {
    for (const FileResult& r : report.files)
        if (r.key.frame == frame) return r;
    throw std::runtime_error("no such frame");
}

CompareImage plane(int w, int h, int channels, float value) {
    CompareImage image;
    image.width = w;
    image.height = h;
    image.channels = channels;
    image.samples.assign(static_cast<size_t>(w) * h * channels, value);
    return image;
}

}  // namespace

TEST_CASE("compare kinds: EXR colour is judged at one exposure for the whole sequence",
          "[compare]") {
    TempDir dir("compare-exposure");
    RunFolder ref(dir.file("ref")), candidate(dir.file("new"));
    // Frame 1 is bright, frame 2 a thousand times darker.
    ref.write(1, "color", "exr", encode_exr_color(hdr_image(4.0f)));
    ref.write(2, "color", "exr", encode_exr_color(hdr_image(0.004f)));
    // NEW: frame 1 0.5% brighter (under the 1% relative threshold); frame
    // 2 with an absolute change of 2e-5, 10% of its own light, but well
    // under 1% of the sequence's white.
    HalfColorImage dark = hdr_image(0.004f);
    for (auto& p : dark.pixels) p = to_half(to_float(p) + glm::vec4(2e-5f, 2e-5f, 2e-5f, 0));
    candidate.write(1, "color", "exr", encode_exr_color(hdr_image(4.0f * 1.005f)));
    candidate.write(2, "color", "exr", encode_exr_color(dark));
    ref.finish();
    candidate.finish();
    const CompareReport pass = compare_folders(ref.dir, candidate.dir);
    REQUIRE(pass.sequences.size() == 1);
    // One white point: frame 1's 99.9th percentile luminance, near its peak.
    CHECK(pass.sequences[0].white > 2.5);
    CHECK(pass.sequences[0].white < 4.0);
    CHECK(frame_result(pass, 1).outcome == Outcome::warn);
    CHECK(frame_result(pass, 2).outcome != Outcome::fail);
    CHECK(compare_exit_code(pass) == 0);

    // 2% brighter fails.
    RunFolder brighter(dir.file("brighter"));
    brighter.write(1, "color", "exr", encode_exr_color(hdr_image(4.0f * 1.02f)));
    brighter.write(2, "color", "exr", encode_exr_color(hdr_image(0.004f)));
    brighter.finish();
    const CompareReport fail = compare_folders(ref.dir, brighter.dir);
    CHECK(frame_result(fail, 1).outcome == Outcome::fail);
    CHECK(compare_exit_code(fail) == 3);
}

TEST_CASE("compare kinds: the flicker figure and the worst frame of a sequence", "[compare]") {
    TempDir dir("compare-flicker");
    RunFolder ref(dir.file("ref")), candidate(dir.file("new"));
    for (int frame = 1; frame <= 4; ++frame) {
        // REF moves smoothly; NEW's frame 3 jumps in brightness and back.
        const float scale = 1.0f + 0.01f * frame;
        ref.write(frame, "color", "exr", encode_exr_color(hdr_image(1.0f, scale)));
        candidate.write(frame, "color", "exr",
                        encode_exr_color(hdr_image(frame == 3 ? 1.3f : 1.0f, scale)));
    }
    ref.finish();
    candidate.finish();
    const CompareReport report = compare_folders(ref.dir, candidate.dir);
    REQUIRE(report.sequences.size() == 1);
    const SequenceResult& s = report.sequences[0];
    CHECK(s.worst_frame == 3);
    CHECK(s.flicker > 0.02);
    CHECK((s.flicker_frame == 3 || s.flicker_frame == 4));
    // Frames 1 and 2 are identical; frame 2 is decoded as frame 3's
    // neighbour, frame 1 is not decoded at all.
    CHECK_FALSE(frame_result(report, 1).decoded);
    CHECK(frame_result(report, 3).change_new.has_value());
    CHECK(std::abs(*frame_result(report, 3).change_new - *frame_result(report, 3).change_ref) >
          0.02);
}

TEST_CASE("compare kinds: alpha is judged apart from colour", "[compare]") {
    CompareImage ref = plane(32, 32, 3, 0.5f), candidate = plane(32, 32, 3, 0.5f);
    ref.alpha.assign(32 * 32, 1.0f);
    candidate.alpha = ref.alpha;
    // Alpha changes in a block; colour stays.
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x) candidate.alpha[y * 32 + x] = 0.5f;
    JudgeInputs in;
    in.tolerance = default_thresholds().defaults.at(ImageKind::color);
    in.alpha_tolerance = default_thresholds().defaults.at(ImageKind::alpha);
    Judgement j = judge_images(ref, candidate, in);
    CHECK(j.outcome == Outcome::fail);
    CHECK(j.pixels.outcome == Outcome::pass);
    REQUIRE(j.alpha);
    CHECK(j.alpha->pixels_failed == 64);
    CHECK(j.alpha->reason.find("alpha: 64 pixels") == 0);

    // Colour under alpha 0 in both images is not part of the picture.
    CompareImage clear_ref = plane(32, 32, 3, 0.2f), clear_new = plane(32, 32, 3, 0.9f);
    clear_ref.alpha.assign(32 * 32, 0.0f);
    clear_new.alpha = clear_ref.alpha;
    j = judge_images(clear_ref, clear_new, in);
    CHECK(j.outcome == Outcome::pass);
    CHECK(j.pixels.stats.pixels == 0);
}

TEST_CASE("compare kinds: normals by angle, ids exactly", "[compare]") {
    const CompareThresholds t = default_thresholds();
    auto tilted = [](double degrees) {
        CompareImage n = plane(16, 16, 3, 0.0f);
        const double a = degrees * 3.14159265358979323846 / 180;
        for (size_t p = 0; p < 256; ++p) {
            n.samples[p * 3] = static_cast<float>(std::sin(a));
            n.samples[p * 3 + 2] = static_cast<float>(std::cos(a));
        }
        return n;
    };
    JudgeInputs normal;
    normal.kind = ImageKind::normal;
    normal.tolerance = t.defaults.at(ImageKind::normal);
    CHECK(judge_images(tilted(0), tilted(0.5), normal).outcome == Outcome::warn);
    const Judgement far = judge_images(tilted(0), tilted(2), normal);
    CHECK(far.outcome == Outcome::fail);
    CHECK(far.pixels.stats.max == Approx(2.0).margin(1e-3));

    JudgeInputs id;
    id.kind = ImageKind::id;
    id.tolerance = t.defaults.at(ImageKind::id);
    // Ids 7 | 9 split at column 8; NEW moves the split by one column: an
    // edge tie, forgiven by the position tolerance.
    CompareImage ids = plane(16, 16, 1, 7.0f), moved = plane(16, 16, 1, 7.0f);
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 16; ++x) {
            ids.samples[y * 16 + x] = x < 8 ? 7.0f : 9.0f;
            moved.samples[y * 16 + x] = x < 9 ? 7.0f : 9.0f;
        }
    Judgement tie = judge_images(ids, moved, id);
    CHECK(tie.pixels.pixels_failed == 0);
    CHECK(tie.pixels.forgiven_by_position == 16);
    // An id that does not appear nearby fails, whatever its value.
    moved.samples[5 * 16 + 3] = 8.0f;
    CHECK(judge_images(ids, moved, id).pixels.pixels_failed == 1);
    id.tolerance.position = 0;
    CHECK(judge_images(ids, moved, id).pixels.pixels_failed == 17);
}

TEST_CASE("compare kinds: threshold overrides and their errors", "[compare]") {
    CompareThresholds t = default_thresholds();
    CHECK(apply_threshold_override(t, "color.hard_fail=0.1").empty());
    CHECK(t.defaults.at(ImageKind::color).hard_fail == 0.1);
    CHECK(apply_threshold_override(t, "side.color.fail=0.05").empty());
    // A camera keeps only what it changes: later defaults still reach it.
    CHECK(apply_threshold_override(t, "color.fail_percent=1").empty());
    CHECK(tolerance_for(t, "side", ImageKind::color).fail == 0.05);
    CHECK(tolerance_for(t, "side", ImageKind::color).fail_percent == 1);
    CHECK(tolerance_for(t, "front", ImageKind::color).fail == t.defaults.at(ImageKind::color).fail);

    CHECK(apply_threshold_override(t, "color.hardfail=1").find("did you mean 'hard_fail'") !=
          std::string::npos);
    CHECK(apply_threshold_override(t, "colour.fail=1").find("did you mean 'color'") !=
          std::string::npos);
    // Numbers are read as every command-line number is (core/number_text.hpp).
    for (const char* bad : {"color.fail=abc", "color.fail=nan", "color.fail= 0.1",
                            "color.fail=0.1x", "color.fail=0x1p-3", "color.fail="}) {
        INFO(bad);
        CHECK(apply_threshold_override(t, bad).find("expected a number, got '") !=
              std::string::npos);
    }
    CHECK(apply_threshold_override(t, "color.fail_percent=150").find("from 0 to 100") !=
          std::string::npos);
    CHECK(apply_threshold_override(t, "depth.position=1.5").find("whole number") !=
          std::string::npos);
    CHECK(apply_threshold_override(t, "color.fail=-1").find("at least 0") != std::string::npos);
}

TEST_CASE("compare kinds: a thresholds file with errors names file, line and column", "[compare]") {
    TempDir dir("compare-thresholds");
    const std::string good = write_text(dir.file("good.yaml"), R"(version: 1
color: { fail: 0.02, fail_percent: 0.05 }
cameras:
  side:
    depth: { position: 2 }
masks:
  - { rect: [0, 0, 10, 5], camera: side, kind: color }
diff_scale: 4
)");
    const CompareThresholds t = load_thresholds_file(good);
    CHECK(t.defaults.at(ImageKind::color).fail == 0.02);
    CHECK(tolerance_for(t, "side", ImageKind::depth).position == 2);
    REQUIRE(t.masks.size() == 1);
    CHECK(t.masks[0].width == 10);
    CHECK(t.diff_scale == 4);

    const std::string key = write_text(dir.file("key.yaml"), "color:\n  hardfail: 0.1\n");
    require_error([&] { load_thresholds_file(key); }, ExitCode::invalid_input, "key.yaml:2:3");
    require_error([&] { load_thresholds_file(key); }, ExitCode::invalid_input, "hard_fail");
    const std::string range = write_text(dir.file("range.yaml"), "depth:\n  position: 1.5\n");
    require_error([&] { load_thresholds_file(range); }, ExitCode::invalid_input, "range.yaml:2:13");
    const std::string rect = write_text(dir.file("rect.yaml"), "masks:\n  - { rect: [1, 2, 3] }\n");
    require_error([&] { load_thresholds_file(rect); }, ExitCode::invalid_input, "rect.yaml:2:");
    const std::string version = write_text(dir.file("version.yaml"), "version: 2\n");
    require_error([&] { load_thresholds_file(version); }, ExitCode::invalid_input, "version");

    // The command line exits with 2, before comparing anything.
    const RunResult r =
        run_facet("compare '" + dir.path() + "' '" + dir.path() + "' --thresholds '" + key + "'");
    CHECK(r.exit_code == 2);
    CHECK(r.output.find("key.yaml:2:3") != std::string::npos);
    const RunResult o = run_facet("compare a b -t color.hardfail=1");
    CHECK(o.exit_code == 2);
    CHECK(o.output.find("did you mean 'hard_fail'") != std::string::npos);
}

TEST_CASE("compare kinds: masked pixels play no part in SSIM, NaN colour fails", "[compare]") {
    CompareImage ref = plane(64, 64, 3, 0.5f), candidate = plane(64, 64, 3, 0.5f);
    for (int y = 20; y < 30; ++y)
        for (int x = 20; x < 30; ++x)
            for (int c = 0; c < 3; ++c) candidate.samples[(y * 64 + x) * 3 + c] = 1.0f;
    std::vector<uint8_t> mask(64 * 64, 1);
    for (int y = 20; y < 30; ++y)
        for (int x = 20; x < 30; ++x) mask[y * 64 + x] = 0;
    JudgeInputs in;
    in.tolerance = default_thresholds().defaults.at(ImageKind::color);
    in.alpha_tolerance = default_thresholds().defaults.at(ImageKind::alpha);
    CHECK(judge_images(ref, candidate, in).outcome == Outcome::fail);
    in.mask = mask;
    const Judgement masked = judge_images(ref, candidate, in);
    CHECK(masked.outcome == Outcome::pass);
    REQUIRE(masked.ssim);
    CHECK(*masked.ssim == 1.0);

    // One NaN pixel among 4096 is under fail_percent as a difference, but a
    // colour that is not a number is a broken render.
    CompareImage broken = plane(64, 64, 3, 0.5f);
    broken.samples[100] = std::nanf("");
    JudgeInputs exr;
    exr.kind = ImageKind::color_float;
    exr.tolerance = default_thresholds().defaults.at(ImageKind::color_float);
    exr.tolerance.fail_percent = 1;
    const Judgement nan = judge_images(plane(64, 64, 3, 0.5f), broken, exr);
    CHECK(nan.outcome == Outcome::fail);
    CHECK(nan.pixels.reason.find("not finite") != std::string::npos);
}
