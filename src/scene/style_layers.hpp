#pragma once
// Internal to the scene module: building styles layer by layer.
#include <string>
#include <vector>

#include "scene/style_desc.hpp"

namespace facet {

class Field;

struct StyleContext {
    std::vector<std::string> style_dirs;  // where presets are found by name
    std::string base_dir;                 // where relative preset paths resolve
};

// Sets on `style` the keys the mapping names (after loading what it
// `extends:`). `visiting` holds the preset files being loaded, to catch loops.
void apply_style_layer(const Field& f, StyleDesc& style, const StyleContext& context,
                       std::vector<std::string>& visiting);

// `style:` in a scene or an object: a preset name, a path, or a mapping.
StyleDesc parse_style_field(const Field& field, const StyleContext& context);

}  // namespace facet
