#pragma once
// Contact sheets: one frame of a scene rendered once per cell, each cell
// with its own overrides (a style, or a value of one parameter), laid out
// on a labelled grid (`facet sheet`, docs/styles.md).
#include <string>
#include <vector>

#include "core/image.hpp"
#include "scene/scene_desc.hpp"

namespace facet {

struct SheetCell {
    std::string label;
    std::vector<Override> overrides;  // on top of SheetRequest::options
};

struct SheetRequest {
    std::string scene;
    SceneOptions options;  // applied to every cell
    std::vector<SheetCell> cells;
    int frame = 0;  // 0: the scene's first frame
    int cell_width = 320, cell_height = 240;
    int columns = 0;  // 0: about square
    unsigned threads = 0;
};

// Renders every cell and assembles the sheet (linear RGBA). Scene errors of
// a cell name the cell's overrides, as the command line's -D do.
ColorImage render_contact_sheet(const SheetRequest& request);

}  // namespace facet
