// Keyframe tracks in YAML (docs/scene-format.md, "Animation"):
//   rotate: { keys: { 1: [0, 0, 0], 72: [0, 360, 0] }, interpolation: linear }
#include <algorithm>
#include <cmath>
#include <functional>
#include <numeric>

#include "core/number_text.hpp"
#include "scene/yaml_field.hpp"

namespace facet {
namespace {

// Frame numbers and seconds beyond this are typos, and would lose precision.
constexpr double kMaxKeyTime = 1e7;

using ValueReader = std::function<glm::dvec4(const Field&)>;

constexpr EnumName<TrackInterpolation> kInterpolations[] = {
    {TrackInterpolation::step, "step"},         {TrackInterpolation::linear, "linear"},
    {TrackInterpolation::smooth, "smooth"},     {TrackInterpolation::ease_in, "ease_in"},
    {TrackInterpolation::ease_out, "ease_out"}, {TrackInterpolation::ease_in_out, "ease_in_out"},
    {TrackInterpolation::bezier, "bezier"}};
constexpr EnumName<TrackExtrapolation> kExtrapolations[] = {{TrackExtrapolation::hold, "hold"},
                                                            {TrackExtrapolation::cycle, "cycle"},
                                                            {TrackExtrapolation::linear, "linear"}};
constexpr EnumName<RotationPath> kRotationPaths[] = {{RotationPath::automatic, "auto"},
                                                     {RotationPath::shortest, "shortest"},
                                                     {RotationPath::angles, "angles"}};

double parse_key_time(const Field& key, bool seconds) {
    const std::string text = key.text();
    // Read as every number facet is given (core/number_text.hpp).
    const std::optional<double> t = read_finite_number(text);
    if (!t || std::abs(*t) > kMaxKeyTime)
        key.fail(std::string("a key must be ") +
                 (seconds ? "a time in seconds" : "a frame number") + ", got '" + text + "'");
    return *t;
}

std::shared_ptr<const Track> parse_track(const Field& f, int components, const ValueReader& read,
                                         bool rotation, double min, double max) {
    f.check_keys(rotation
                     ? std::initializer_list<const char*>{"keys", "time", "interpolation", "bezier",
                                                          "extrapolation", "rotation"}
                     : std::initializer_list<const char*>{"keys", "time", "interpolation", "bezier",
                                                          "extrapolation"});
    auto track = std::make_shared<Track>();
    track->where = f.where();
    track->components = components;
    track->min = min;
    track->max = max;
    if (f.has("time")) track->seconds = f["time"].boolean();

    Field keys = f.require("keys");
    keys.expect_map();
    std::vector<std::string> names = keys.keys();
    if (names.empty()) keys.fail("a track needs at least one key");
    struct Key {
        double time;
        glm::dvec4 value;
        Field at;
    };
    std::vector<Key> parsed;
    for (const std::string& name : names) {
        Field key = keys.key(name);
        parsed.push_back({parse_key_time(key, track->seconds), read(keys[name]), key});
    }
    std::stable_sort(parsed.begin(), parsed.end(),
                     [](const Key& a, const Key& b) { return a.time < b.time; });
    for (size_t i = 1; i < parsed.size(); ++i)
        if (parsed[i].time == parsed[i - 1].time)
            parsed[i].at.fail("two keys at the same " +
                              std::string(track->seconds ? "time" : "frame"));
    for (const Key& k : parsed) {
        track->times.push_back(k.time);
        track->values.push_back(k.value);
        track->at.push_back(k.at.where());
    }

    if (f.has("interpolation"))
        track->interpolation = f["interpolation"].choice_of(kInterpolations);
    if (f.has("bezier")) {
        if (track->interpolation != TrackInterpolation::bezier)
            f["bezier"].fail("bezier handles need `interpolation: bezier`");
        Field b = f["bezier"];
        if (!b.is_sequence() || b.size() != 4) b.fail("must be [x1, y1, x2, y2]");
        // x1 and x2 outside [0, 1] would make the timing curve run backwards
        // in time (CSS Easing Functions Level 1 has the same rule).
        track->bezier = {b[0].number(0, 1), b[1].number(-10, 10), b[2].number(0, 1),
                         b[3].number(-10, 10)};
    } else if (track->interpolation == TrackInterpolation::bezier) {
        f["interpolation"].fail("`interpolation: bezier` needs `bezier: [x1, y1, x2, y2]`");
    }
    if (f.has("extrapolation")) {
        Field e = f["extrapolation"];
        if (e.is_map()) {
            e.check_keys({"before", "after"});
            if (e.has("before")) track->before = e["before"].choice_of(kExtrapolations);
            if (e.has("after")) track->after = e["after"].choice_of(kExtrapolations);
        } else {
            track->before = track->after = e.choice_of(kExtrapolations);
        }
    }
    if (rotation && f.has("rotation")) track->rotation = f["rotation"].choice_of(kRotationPaths);
    return track;
}

template <typename T>
Animated<T> animated(const Field& f, int components, const ValueReader& read, bool rotation,
                     double min, double max, T (*to_value)(const glm::dvec4&)) {
    if (!f.is_track()) return Animated<T>(to_value(read(f)));
    Animated<T> result;
    result.track = parse_track(f, components, read, rotation, min, max);
    result.value = to_value(result.track->values.front());
    return result;
}

float to_float(const glm::dvec4& v) {
    return static_cast<float>(v.x);
}
glm::vec3 to_vec3(const glm::dvec4& v) {
    return glm::vec3(v);
}

}  // namespace

Animated<float> Field::animated_number(double min, double max) const {
    return animated<float>(
        *this, 1, [&](const Field& f) { return glm::dvec4(f.number(min, max), 0, 0, 0); }, false,
        min, max, to_float);
}

Animated<glm::vec3> Field::animated_vec3() const {
    return animated<glm::vec3>(
        *this, 3, [](const Field& f) { return glm::dvec4(glm::dvec3(f.vec3()), 0); }, false, -1e30,
        1e30, to_vec3);
}

Animated<glm::vec3> Field::animated_color3() const {
    // Colours never go negative, even where smooth keys overshoot.
    return animated<glm::vec3>(
        *this, 3, [](const Field& f) { return glm::dvec4(glm::dvec3(f.color3()), 0); }, false, 0,
        1e30, to_vec3);
}

Animated<glm::vec3> Field::animated_direction() const {
    return animated<glm::vec3>(
        *this, 3,
        [](const Field& f) {
            glm::vec3 v = f.vec3();
            if (v.x == 0 && v.y == 0 && v.z == 0) f.fail("direction must not be [0, 0, 0]");
            return glm::dvec4(glm::dvec3(v), 0);
        },
        false, -1e30, 1e30, to_vec3);
}

Animated<glm::vec3> Field::animated_scale() const {
    return animated<glm::vec3>(
        *this, 3,
        [](const Field& f) {
            glm::vec3 v =
                f.is_scalar() ? glm::vec3(static_cast<float>(f.number(-1e7, 1e7))) : f.vec3();
            if (v.x == 0 || v.y == 0 || v.z == 0) f.fail("scale must not be zero on any axis");
            return glm::dvec4(glm::dvec3(v), 0);
        },
        false, -1e30, 1e30, to_vec3);
}

Animated<glm::vec3> Field::animated_rotation() const {
    return animated<glm::vec3>(
        *this, 3, [](const Field& f) { return glm::dvec4(glm::dvec3(f.vec3()), 0); }, true, -1e30,
        1e30, to_vec3);
}

}  // namespace facet
