#pragma once
// facet preview (docs/preview.md): a window that renders the scene as it
// is edited. The preview module is the only user of SDL2 and Dear ImGui;
// the render pipeline knows nothing of it.
#include "preview/preview_state.hpp"

namespace facet {

// Throws facet::Error (invalid_input, exit code 2) when neither DISPLAY
// nor WAYLAND_DISPLAY is set: checked before anything else is done.
void require_display();

// Opens the window and runs until it is closed. Throws facet::Error
// (invalid_input, exit code 2) when there is no display to open it on.
int run_preview(const PreviewOptions& options);

}  // namespace facet
