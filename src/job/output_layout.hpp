#pragma once
// Where a render job's files go and what they are named, settled once per
// job (job/render_job.hpp, JobPlan).
#include <string>
#include <vector>

#include "output/output_path.hpp"
#include "scene/scene_desc.hpp"

namespace facet {

// One file of a frame: a pass name (or "multilayer") and a format.
struct PassFile {
    std::string pass, format;
};

// Where a run's files go: the output folder, the name template, the files
// each frame gets (job/pass_files.hpp, frame_files), and the folder
// (relative to the output folder) that holds manifest.json.
struct OutputLayout {
    std::string root;
    std::string template_text;
    OutputTemplate names;
    std::vector<PassFile> frame_files;
    std::string manifest_dir;
};

// The fields one of the run's files is named from.
inline OutputNameFields file_fields(const SceneDesc& scene, const std::string& camera,
                                    const std::string& pass, int frame, const std::string& ext) {
    return {scene.name, camera, pass, frame, ext, scene.variant};
}

}  // namespace facet
