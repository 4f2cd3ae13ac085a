#include "job/file_metadata.hpp"

#include <cstdio>

#include "core/version.hpp"

namespace facet {
namespace {

std::string matrix_text(const glm::mat4& m) {
    std::string text;
    char number[32];
    for (int column = 0; column < 4; ++column)
        for (int row = 0; row < 4; ++row) {
            // %.9g round-trips a float exactly.
            std::snprintf(number, sizeof number, "%.9g", static_cast<double>(m[column][row]));
            if (!text.empty()) text += ' ';
            text += number;
        }
    return text;
}

std::vector<std::pair<std::string, std::string>> facts_list(const FileFacts& f) {
    // The version but not the commit: a rebuild must not change every file.
    return {{"Software", "facet " + build_info().version},
            {"facet:scene", f.scene},
            {"facet:camera", f.camera},
            {"facet:frame", std::to_string(f.frame)},
            {"facet:style", f.style},
            {"facet:view", matrix_text(f.view)},
            {"facet:projection", matrix_text(f.projection)}};
}

}  // namespace

std::vector<PngText> png_metadata(const FileFacts& facts) {
    std::vector<PngText> out;
    for (auto& [key, value] : facts_list(facts)) out.push_back({key, value});
    return out;
}

std::vector<ExrAttribute> exr_metadata(const FileFacts& facts) {
    std::vector<ExrAttribute> out;
    for (auto& [key, value] : facts_list(facts)) out.push_back({key, value});
    return out;
}

}  // namespace facet
