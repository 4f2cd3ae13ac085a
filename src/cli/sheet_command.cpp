#include "cli/sheet_command.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <tuple>

#include <CLI/CLI.hpp>

#include "cli/commands.hpp"
#include "cli/option_values.hpp"
#include "cli/render_args.hpp"
#include "core/display_transform.hpp"
#include "core/error.hpp"
#include "job/contact_sheet.hpp"
#include "output/atomic_file.hpp"
#include "output/encoders.hpp"
#include "scene/scene_desc.hpp"
#include "video/video_encoder.hpp"

namespace facet {
namespace {

// The sheet as a JPEG, from the 8-bit sRGB values its PNG would hold
// (through half floats, as the PNG writer rounds).
std::vector<uint8_t> sheet_jpeg(const ColorImage& sheet) {
    std::vector<uint8_t> rgb(static_cast<size_t>(sheet.width) * sheet.height * 3);
    for (size_t p = 0; p < sheet.pixels.size(); ++p) {
        const glm::vec4 c = to_float(to_half(sheet.pixels[p]));
        for (int i = 0; i < 3; ++i) rgb[p * 3 + i] = display_byte(c[i]);
    }
    return encode_jpeg(sheet.width, sheet.height, rgb);
}

// Cells keep the scene's aspect ratio unless given both sides: a 4:3 cell
// would crop a 16:9 scene and push its model against the cell's edges.
std::pair<int, int> sheet_cell_size(const std::string& size, const OutputDesc& scene) {
    constexpr int kDefaultCellWidth = 320;
    if (size.find_first_of("xX") != std::string::npos) return parse_size(size, "--size");
    const int width =
        size.empty()
            ? kDefaultCellWidth
            : parse_whole_number(size, "--size", 1, 4096,
                                 "WIDTHxHEIGHT or WIDTH from 1 to 4096 (e.g. 320x180 or 320)");
    const int height = std::max(
        1, static_cast<int>(std::lround(static_cast<double>(width) * scene.height / scene.width)));
    return {width, height};
}

}  // namespace

int sheet_command(const SheetArgs& args) {
    SheetRequest request;
    request.scene = args.scene;
    request.options.style_dirs = default_style_dirs();
    for (const auto& d : args.defines) request.options.overrides.push_back(parse_define(d));
    std::string output = args.output;
    if (output.empty())
        output = (std::filesystem::path("out") /
                  (std::filesystem::path(args.scene).stem().string() + "-sheet.png"))
                     .string();
    // The file is written in the format its name says; the sheet writes PNG only.
    std::string extension = std::filesystem::path(output).extension().string();
    for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    const bool jpeg = extension == ".jpg" || extension == ".jpeg";
    if (extension != ".png" && !jpeg)
        fail_input(command_line("-o " + output), "",
                   "a contact sheet is written as PNG or JPEG; name the file *.png, *.jpg or "
                   "*.jpeg");
    const OutputDesc scene_output = load_scene(args.scene, request.options).output;
    const std::vector<int> frames = resolve_frames(args.frames, scene_output);
    std::tie(request.cell_width, request.cell_height) = sheet_cell_size(args.size, scene_output);
    if (frames.size() > 1)
        fail_input(command_line("--frames"), "", "a contact sheet shows one frame; give -f N");
    request.frame = frames.empty() ? 0 : frames.front();
    request.columns = args.columns;
    request.threads = args.threads;

    std::vector<std::string> styles =
        parse_list(args.styles, "--styles", "comma-separated preset names or all");
    if (args.styles == "all") {
        styles.clear();
        for (const auto& preset : list_style_presets(default_style_dirs()))
            styles.push_back(preset.first);
    }
    std::string vary_key;
    std::vector<std::string> values;
    if (!args.vary.empty()) {
        const size_t eq = args.vary.find('=');
        if (eq == std::string::npos || eq == 0 || eq + 1 == args.vary.size())
            fail_input(command_line("--vary " + args.vary), "",
                       "expected key.path=v1,v2,..., e.g. style.cels=2,3,4");
        vary_key = args.vary.substr(0, eq);
        values = parse_list(std::string_view(args.vary).substr(eq + 1), "--vary",
                            "comma-separated values after key.path= (e.g. style.cels=2,3,4)");
    }
    if (styles.empty() && values.empty())
        fail_input(command_line("sheet"), "",
                   "give --styles a,b,... (or all) and/or --vary key=v1,v2");
    if (styles.empty()) styles.push_back("");
    if (values.empty()) values.push_back("");
    for (const std::string& style : styles)
        for (const std::string& value : values) {
            SheetCell cell;
            if (!style.empty()) {
                cell.overrides.push_back({"style", style, "--styles " + style});
                cell.label = style;
            }
            if (!value.empty()) {
                cell.overrides.push_back({vary_key, value, "--vary " + vary_key + "=" + value});
                const std::string leaf = vary_key.substr(vary_key.rfind('.') + 1);
                cell.label += (cell.label.empty() ? "" : ", ") + leaf + "=" + value;
            }
            request.cells.push_back(cell);
        }

    const ColorImage sheet = render_contact_sheet(request);
    const auto parent = std::filesystem::path(output).parent_path();
    if (!parent.empty()) make_directories(parent.string());
    write_file_atomically(output, jpeg ? sheet_jpeg(sheet) : encode_png_color(sheet, 6));
    if (!args.quiet)
        std::printf("wrote %s (%s)\n", output.c_str(),
                    count_of(request.cells.size(), "cell", "cells").c_str());
    return 0;
}

CLI::App* add_sheet_command(CLI::App& app, SheetArgs& args) {
    CLI::App* cmd = app.add_subcommand(
        "sheet", "Render one frame with each style or parameter value into a labelled grid PNG");
    cmd->add_option("scene", args.scene, "Scene file (YAML)")->required();
    cmd->add_option("--styles", args.styles, "Presets, comma-separated, or 'all'");
    cmd->add_option("--vary", args.vary,
                    "One value per cell: key.path=v1,v2,... (e.g. style.cels=2,3,4,6)");
    add_frame_options(cmd, args.frames);
    cmd->add_option("--size,--cell", args.size,
                    "Cell size WIDTHxHEIGHT, or WIDTH with the scene's aspect ratio (default 320)");
    add_whole_number_option(cmd, "--columns", args.columns, 0, 64,
                            "Cells per row (default: about square)");
    add_output_option(cmd, args.output, "PNG to write (default out/SCENE-sheet.png)");
    add_threads_option(cmd, args.threads);
    add_define_option(cmd, args.defines);
    add_quiet_flag(cmd, args.quiet);
    return cmd;
}

}  // namespace facet
