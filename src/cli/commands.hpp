#pragma once
// The facet command line (the only CLI11 user).
#include <string>
#include <vector>

#include "scene/scene_desc.hpp"

namespace facet {

int run_command_line(int argc, char** argv);

// Folders searched for style presets by name: $FACET_STYLE_PATH (colon
// separated), then the styles/ folder facet was built with.
std::vector<std::string> default_style_dirs();

}  // namespace facet
