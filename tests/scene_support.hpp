#pragma once
// Helpers shared by the scene file tests (test_scene_*.cpp): loading with the
// repository's style presets, expecting an error, and finding where in a
// scene's text an error should point.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include "core/error.hpp"
#include "scene/scene_desc.hpp"
#include "support.hpp"

namespace facet::test {

inline const std::string kMinimalObjects = "objects:\n  - primitive: cube\n";

// "line:column" (1-based) of the first occurrence of `needle` in `text`,
// plus `offset` characters; counted here from the text itself.
inline std::string line_col(const std::string& text, const std::string& needle, size_t offset = 0) {
    size_t at = text.find(needle);
    REQUIRE(at != std::string::npos);
    at += offset;
    int line = 1, column = 1;
    for (size_t i = 0; i < at; ++i) {
        if (text[i] == '\n') {
            ++line;
            column = 1;
        } else {
            ++column;
        }
    }
    return std::to_string(line) + ":" + std::to_string(column);
}

inline SceneOptions with_styles() {
    SceneOptions options;
    options.style_dirs = {facet::test::styles_dir()};
    return options;
}

inline SceneDesc load(const std::string& path, SceneOptions options = with_styles()) {
    return load_scene(path, options);
}

// Loads the scene, expecting an invalid-input error; returns its message.
inline std::string load_error(const std::string& path,
                              const SceneOptions& options = with_styles()) {
    try {
        load_scene(path, options);
    } catch (const Error& e) {
        CHECK(e.code() == ExitCode::invalid_input);
        return e.what();
    }
    FAIL("load_scene accepted " << path);
    return {};
}

// The error must name file:line:column and the key (quoted, as the message writes it).
inline void check_error_at(const std::string& message, const std::string& file,
                           const std::string& where, const std::string& key) {
    INFO("message: " << message);
    CHECK_THAT(message, Catch::Contains(file + ":" + where + ":"));
    if (!key.empty()) CHECK_THAT(message, Catch::Contains("'" + key + "'"));
}

inline bool close_to(float a, float b, float eps = 1e-5f) {
    return std::fabs(a - b) <= eps;
}

}  // namespace facet::test
