#include "job/contact_sheet.hpp"

#include <cmath>

#include "core/thread_pool.hpp"
#include "job/labels.hpp"
#include "render/frame_renderer.hpp"

namespace facet {
namespace {

constexpr int kLabelScale = 2;  // font pixels per unit: legible at 320 px cells
constexpr int kPadding = 6;     // pixels around each label
const glm::vec4 kSheetBackground(0.9f, 0.9f, 0.9f, 1.0f);
const glm::vec3 kLabelColor(0.02f, 0.02f, 0.02f);

// A cell's label as drawn: at kLabelScale if it fits the cell, else at
// scale 1, else cut and ended with "..", so that it never runs into the
// next cell.
struct FittedLabel {
    std::string text;
    int scale;
};
FittedLabel fit_label(const std::string& label, int cell_width) {
    const int room = cell_width - 2 * kPadding;
    if (label_width(label, kLabelScale) <= room) return {label, kLabelScale};
    if (label_width(label, 1) <= room) return {label, 1};
    std::string text = label;
    while (text.size() > 1 && label_width(text + "..", 1) > room) text.pop_back();
    return {text + "..", 1};
}

}  // namespace

ColorImage render_contact_sheet(const SheetRequest& request) {
    const int count = static_cast<int>(request.cells.size());
    const int columns = request.columns > 0
                            ? request.columns
                            : static_cast<int>(std::ceil(std::sqrt(static_cast<double>(count))));
    const int rows = (count + columns - 1) / columns;
    const int label_band = label_height(kLabelScale) + 2 * kPadding;
    const int pitch_x = request.cell_width, pitch_y = request.cell_height + label_band;
    ColorImage sheet(columns * pitch_x, rows * pitch_y, kSheetBackground);

    ThreadPool pool(request.threads);
    for (int c = 0; c < count; ++c) {
        const SheetCell& cell = request.cells[static_cast<size_t>(c)];
        SceneOptions options = request.options;
        options.overrides.insert(options.overrides.end(), cell.overrides.begin(),
                                 cell.overrides.end());
        // Appended piece by piece: GCC 12 at -O3 warns falsely (-Wrestrict,
        // GCC bug 105329) about "literal" + std::string.
        std::string size = "[";
        size += std::to_string(request.cell_width);
        size += ", ";
        size += std::to_string(request.cell_height);
        size += "]";
        options.overrides.push_back({"output.size", size, "sheet cell size"});
        const SceneDesc scene = load_scene(request.scene, options);
        const World world = build_world(scene, request.threads);
        FrameRenderer renderer(scene, world, pool);
        FrameImages images;
        const int frame = request.frame != 0 ? request.frame : scene.output.frames.front();
        renderer.render(frame, 0, images);
        if (!scene.output.display.is_identity())
            images.color = apply_display_transform(images.color, scene.output.display);

        const int x0 = (c % columns) * pitch_x, y0 = (c / columns) * pitch_y;
        for (int y = 0; y < request.cell_height; ++y)
            for (int x = 0; x < request.cell_width; ++x)
                sheet.at(x0 + x, y0 + y) = to_float(images.color.at(x, y));
        const FittedLabel label = fit_label(cell.label, request.cell_width);
        const int text_width = label_width(label.text, label.scale);
        draw_label(sheet, x0 + std::max(kPadding, (request.cell_width - text_width) / 2),
                   y0 + request.cell_height + kPadding, label.text, kLabelColor, label.scale);
    }
    return sheet;
}

}  // namespace facet
