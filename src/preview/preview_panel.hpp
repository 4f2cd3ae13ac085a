#pragma once
// The preview's control panel (Dear ImGui): time, camera, style, lights,
// wind and the pass shown. Draws into the current ImGui frame.
#include "preview/preview_state.hpp"

namespace facet {

// Draws the panel at x..x+width of a window `height` tall; edits `state`
// and returns the action of a button pressed, if any.
PreviewAction draw_preview_panel(PreviewState& state, float x, float width, float height);

}  // namespace facet
