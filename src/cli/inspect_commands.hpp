#pragma once
// The commands that look without rendering: `info` (a mesh), `styles`
// (the presets, or one resolved), and the JSON forms of them and of
// `validate`'s report, for scripts.
#include <string>

#include "core/diagnostics.hpp"

namespace facet {

int info_command(const std::string& path, bool allow_outside, bool json, unsigned threads = 0);

// `facet styles [NAME] [--json]`.
int styles_command(const std::string& name, bool json);

// The JSON `validate --json` prints: facts of a valid scene, or the error;
// with the warnings in both cases. Each problem has file, line, column,
// key, message and, for command-line values, origin.
struct ValidateFacts {
    std::string scene, style, shading;
    size_t objects = 0, triangles = 0, lights = 0;
    int width = 0, height = 0;
    std::vector<int> frames;
    std::vector<std::string> variants;  // checked, one run each; none without `variant:`
};
std::string validate_json(const ValidateFacts& facts, const Warnings& warnings);
std::string validate_error_json(const Error& error, const Warnings& warnings);

}  // namespace facet
