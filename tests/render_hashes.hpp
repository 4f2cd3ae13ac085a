#pragma once
// Renders frames of a scene through a whole run (files and manifest) and
// returns what the manifest records, for determinism tests.
#include <map>
#include <string>
#include <vector>

#include "job/render_job.hpp"
#include "output/manifest.hpp"
#include "support.hpp"

namespace facet::test {

// (frame, pass, format) -> sha256 of the file: the passes asked for (colour
// and depth unless told), PNG and EXR; `style` replaces the scene's if set;
// `more_overrides` (-D) after those.
inline std::map<std::string, std::string> render_hashes(
    const std::string& scene_file, unsigned threads, std::vector<int> frames,
    const std::string& out, int samples = 1, const std::string& passes = "[color, depth]",
    const std::string& style = "", const std::vector<Override>& more_overrides = {}) {
    SceneOptions options;
    options.style_dirs = {facet::test::styles_dir()};
    options.overrides.push_back({"output.passes", passes, "test"});
    if (!style.empty()) options.overrides.push_back({"style", style, "test"});
    options.overrides.push_back({"output.formats", "[png, exr]", "test"});
    options.overrides.push_back({"output.samples", std::to_string(samples), "test"});
    options.overrides.insert(options.overrides.end(), more_overrides.begin(), more_overrides.end());
    SceneDesc scene = load_scene(source_path(scene_file), options);
    World world = build_world(scene);
    RenderOptions ro;
    ro.threads = threads;
    ro.frames = std::move(frames);
    ro.out_dir = out;
    RenderResult result = render_scene(scene, world, ro, nullptr);
    Manifest manifest = read_manifest(result.manifest_path);
    std::map<std::string, std::string> hashes;
    for (const auto& f : manifest.files)
        hashes[std::to_string(f.frame) + "/" + f.pass + "/" + f.format] = f.sha256;
    return hashes;
}

}  // namespace facet::test
