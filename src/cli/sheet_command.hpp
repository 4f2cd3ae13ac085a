#pragma once
// `facet sheet`: one frame of a scene in a labelled grid, a cell per style
// or per value of one key (docs/styles.md, "Contact sheets").
#include <string>
#include <vector>

#include "cli/options.hpp"

namespace CLI {
class App;
}

namespace facet {

struct SheetArgs {
    std::string scene;
    std::string styles;     // comma-separated, or "all"
    std::string vary;       // key=v1,v2,...
    FrameSelection frames;  // one frame
    std::string size;       // of a cell: WIDTHxHEIGHT, or WIDTH with the scene's aspect ratio
    int columns = 0;
    std::string output;
    unsigned threads = 0;
    std::vector<std::string> defines;
    bool quiet = false;
};

CLI::App* add_sheet_command(CLI::App& app, SheetArgs& args);
int sheet_command(const SheetArgs& args);

}  // namespace facet
