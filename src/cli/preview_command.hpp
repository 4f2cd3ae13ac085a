#pragma once
// `facet preview SCENE`: the live window (preview/preview.hpp, docs/preview.md).
#include "cli/render_args.hpp"

namespace CLI {
class App;
}

namespace facet {

CLI::App* add_preview_command(CLI::App& app, RenderArgs& args);
int preview_command(const RenderArgs& args);

}  // namespace facet
