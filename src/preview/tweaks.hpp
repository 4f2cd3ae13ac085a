#pragma once
// Values changed in the preview's panel. Each is an override of one key
// path, as -D writes it, so the preview renders them through the scene
// reader's own checks, and they leave as -D arguments or a style file that
// gives the same image in `facet render`.
#include <map>
#include <string>
#include <variant>
#include <vector>

#include <glm/vec3.hpp>

#include "scene/scene_desc.hpp"

namespace facet {

using TweakValue = std::variant<float, int, glm::vec3, std::string>;
// Key path ("style.alpha", "lights.0.color") -> value; ordered by path.
using Tweaks = std::map<std::string, TweakValue>;

// The shortest text that reads back as the same float, and a vector of three.
std::string yaml_number(float value);
std::string yaml_vector(const glm::vec3& value);
std::string yaml_value(const TweakValue& value);

std::vector<Override> tweak_overrides(const Tweaks& tweaks);

// "-D 'style.alpha=0.3' -D 'lights.0.color=[1, 0.9, 0.8]'", quoted for a
// POSIX shell.
std::string define_arguments(const std::vector<Override>& overrides);

// The text of a style preset to write to `target` with the panel's
// style.* values:
// - `target` is the scene's own style file, or the scene's style is
//   written inline: that style's own keys with the values over them;
// - else a preset that extends the scene's style (or the preset chosen in
//   the panel; by name when found in `style_dirs`) with the values nested
//   as a style file nests them.
// Other tweaks (lights, wind) are scene values, listed in a comment.
// Throws facet::Error for a target the scene's style extends (every style
// that extends it would change, or it would extend itself).
std::string style_file_yaml(const SceneDesc& scene, const Tweaks& tweaks,
                            const std::vector<std::string>& style_dirs, const std::string& target);

}  // namespace facet
