#include "output/output_path.hpp"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <string_view>
#include <unordered_map>

#include "core/error.hpp"
#include "core/number_text.hpp"
#include "core/suggest.hpp"

namespace facet {
namespace {

// Wider frame numbers than this are not padding but a typo.
constexpr int kMaxFramePadding = 9;

constexpr const char* kManifestName = "manifest.json";

[[noreturn]] void fail(const std::string& text, const std::string& message) {
    throw Error(ExitCode::invalid_input, "output template '" + text + "': " + message);
}

// 'text', in quotes. Built by appending, because GCC 12 at -O3 warns falsely
// (-Wrestrict, GCC bug 105329) about some "literal" + std::string expressions.
std::string quoted(std::string_view text) {
    std::string out;
    out.reserve(text.size() + 2);
    out += '\'';
    out += text;
    out += '\'';
    return out;
}

std::string known_placeholders() {
    std::string list;
    for (const auto& [placeholder, name] : kPlaceholders) {
        if (!list.empty()) list += ", ";
        list += '{' + std::string(name) + '}';
    }
    return list + ", {frame:06}, ####";
}

// The known placeholder the user probably meant, or "" if none is close.
std::string closest_placeholder(const std::string& typed) {
    return closest_name(typed, names_of(kPlaceholders));
}

[[noreturn]] void fail_unknown_placeholder(const std::string& text, const std::string& name) {
    std::string message = "unknown placeholder '{" + name + "}'";
    if (const std::string closest = closest_placeholder(name); !closest.empty())
        message += "; did you mean '{" + closest + "}'?";
    fail(text, message + " (known: " + known_placeholders() + ")");
}

int parse_frame_padding(const std::string& text, const std::string& spec,
                        const std::string& whole_placeholder) {
    const std::optional<long long> width = read_whole_number(spec);
    if (!width || *width < 1 || *width > kMaxFramePadding)
        fail(text, "bad frame padding '" + whole_placeholder +
                       "': the width must be a number from 1 to " +
                       std::to_string(kMaxFramePadding) + ", as in {frame:04} or {frame:4}");
    return static_cast<int>(*width);
}

TemplateSegment placeholder_segment(Placeholder placeholder, int frame_padding) {
    TemplateSegment segment;
    segment.kind = TemplateSegment::Kind::placeholder;
    segment.placeholder = placeholder;
    segment.frame_padding = frame_padding;
    return segment;
}

// Parses the text between '{' and '}'.
TemplateSegment parse_placeholder(const std::string& text, const std::string& inside) {
    const std::string whole = "{" + inside + "}";
    size_t colon = inside.find(':');
    std::string name = inside.substr(0, colon);
    const std::optional<Placeholder> p = value_of(kPlaceholders, name);
    if (!p) fail_unknown_placeholder(text, name);
    if (colon == std::string::npos) return placeholder_segment(*p, kDefaultFramePadding);
    if (*p != Placeholder::frame)
        fail(text, "'" + whole + "' has a padding width, but only {frame} takes one");
    return placeholder_segment(*p, parse_frame_padding(text, inside.substr(colon + 1), whole));
}

using Component = std::vector<const TemplateSegment*>;

// The segments of each '/'-separated path component, in order.
std::vector<Component> split_components(const OutputTemplate& output_template) {
    std::vector<Component> components(1);
    for (const TemplateSegment& segment : output_template.segments) {
        if (segment.kind == TemplateSegment::Kind::separator)
            components.emplace_back();
        else
            components.back().push_back(&segment);
    }
    return components;
}

std::string literal_text(const Component& component) {
    std::string text;
    for (const TemplateSegment* segment : component) {
        if (segment->kind != TemplateSegment::Kind::literal) return {};
        text += segment->text;
    }
    return text;
}

// The parser's checks on the shape of the path.
void check_components(const OutputTemplate& output_template) {
    const std::string& text = output_template.text;
    std::vector<Component> components = split_components(output_template);
    if (components.back().empty())
        fail(text, "ends in '/' so it names no file; add a file name such as {pass}.{frame}.{ext}");
    for (const Component& component : components) {
        if (component.empty())
            fail(text, "has an empty path component ('//'); remove the extra '/'");
        std::string literal = literal_text(component);
        if (literal == "..")
            fail(text, "'..' would leave the output folder; names must stay inside it");
        if (literal == ".") fail(text, "has a '.' path component; remove it");
    }
}

std::string format_frame(int frame, int padding) {
    // Via long long so that the most negative int has a magnitude too.
    long long magnitude = std::llabs(static_cast<long long>(frame));
    std::string digits = std::to_string(magnitude);
    if (digits.size() < static_cast<size_t>(padding))
        digits.insert(0, static_cast<size_t>(padding) - digits.size(), '0');
    return frame < 0 ? "-" + digits : digits;
}

const std::string& field_value(Placeholder placeholder, const OutputNameFields& fields) {
    switch (placeholder) {
        case Placeholder::scene:
            return fields.scene;
        case Placeholder::camera:
            return fields.camera;
        case Placeholder::pass:
            return fields.pass;
        case Placeholder::ext:
            return fields.ext;
        case Placeholder::variant:
            return fields.variant;
        case Placeholder::frame:
            break;
    }
    throw std::logic_error("field_value: the frame is a number");
}

void append_segment(std::string& out, const TemplateSegment& segment,
                    const OutputNameFields& fields, const std::string& text) {
    switch (segment.kind) {
        case TemplateSegment::Kind::literal:
            out += segment.text;
            return;
        case TemplateSegment::Kind::separator:
            out += '/';
            return;
        case TemplateSegment::Kind::placeholder:
            break;
    }
    if (segment.placeholder == Placeholder::frame) {
        out += format_frame(fields.frame, segment.frame_padding);
        return;
    }
    const std::string& value = field_value(segment.placeholder, fields);
    // A '/' from a value would add directories the template does not have.
    if (value.find('/') != std::string::npos)
        fail(text, "{" + std::string(name_of(kPlaceholders, segment.placeholder)) + "} is '" +
                       value + "', which contains '/'; rename it");
    out += value;
}

// The checks of the parser, again on the expanded path: a value may be
// empty or "..", or make a component "..".
void check_expanded_path(const std::string& path, const std::string& text) {
    size_t start = 0;
    while (true) {
        size_t slash = path.find('/', start);
        std::string_view component(path.data() + start,
                                   (slash == std::string::npos ? path.size() : slash) - start);
        if (component.empty() || component == "." || component == "..")
            fail(text, "expands to '" + path + "', which has an empty, '.' or '..' path " +
                           "component; check the scene, camera, pass and variant names");
        if (slash == std::string::npos) return;
        start = slash + 1;
    }
}

std::string describe(int frame, const std::string& camera, const std::string& pass,
                     const std::string& ext) {
    return "frame " + std::to_string(frame) + ", camera '" + camera + "', pass '" + pass +
           "', ext '" + ext + "'";
}

}  // namespace

bool OutputTemplate::uses(Placeholder placeholder) const {
    return std::any_of(segments.begin(), segments.end(), [&](const TemplateSegment& segment) {
        return segment.kind == TemplateSegment::Kind::placeholder &&
               segment.placeholder == placeholder;
    });
}

OutputTemplate parse_output_template(const std::string& text) {
    if (text.empty()) fail(text, "is empty; the default is " + std::string(kDefaultOutputTemplate));
    if (text.front() == '/')
        fail(text, "is an absolute path; names are relative to the output folder (--out)");

    OutputTemplate result;
    result.text = text;
    auto append_literal = [&](char c) {
        if (result.segments.empty() ||
            result.segments.back().kind != TemplateSegment::Kind::literal)
            result.segments.push_back(TemplateSegment{});
        result.segments.back().text += c;
    };

    size_t i = 0;
    while (i < text.size()) {
        char c = text[i];
        if (c == '/') {
            result.segments.push_back(TemplateSegment{TemplateSegment::Kind::separator, "/"});
            ++i;
        } else if (c == '{') {
            // A placeholder never spans '/' or holds another '{', so either
            // means the '{' was left open.
            size_t close = text.find_first_of("{}/", i + 1);
            if (close == std::string::npos || text[close] != '}') {
                std::string unclosed =
                    text.substr(i, close == std::string::npos ? close : close - i);
                fail(text, quoted(unclosed) + " has no closing '}'");
            }
            result.segments.push_back(parse_placeholder(text, text.substr(i + 1, close - i - 1)));
            i = close + 1;
        } else if (c == '}') {
            fail(text, "'}' at character " + std::to_string(i + 1) + " has no opening '{'");
        } else if (c == '#') {
            size_t run_end = text.find_first_not_of('#', i);
            if (run_end == std::string::npos) run_end = text.size();
            int width = static_cast<int>(run_end - i);
            if (width > kMaxFramePadding)
                fail(text, "bad frame padding '" + text.substr(i, run_end - i) + "': at most " +
                               std::to_string(kMaxFramePadding) + " '#'");
            result.segments.push_back(placeholder_segment(Placeholder::frame, width));
            i = run_end;
        } else {
            append_literal(c);
            ++i;
        }
    }
    check_components(result);
    return result;
}

std::string expand(const OutputTemplate& output_template, const OutputNameFields& fields) {
    std::string path;
    for (const TemplateSegment& segment : output_template.segments)
        append_segment(path, segment, fields, output_template.text);
    check_expanded_path(path, output_template.text);
    return path;
}

void check_unique_outputs(const OutputTemplate& output_template, const std::string& scene,
                          const std::vector<std::string>& cameras,
                          const std::vector<std::string>& passes,
                          const std::vector<std::string>& exts, const std::vector<int>& frames,
                          const std::string& variant) {
    if (cameras.empty() || passes.empty() || exts.empty() || frames.empty()) return;
    const std::string& text = output_template.text;

    OutputNameFields fixed{scene, cameras.front(), "", 0, "", variant};
    std::string manifest_dir = manifest_directory(output_template, fixed, cameras.size() == 1);
    std::string manifest_path =
        manifest_dir.empty() ? kManifestName : manifest_dir + "/" + kManifestName;

    // Every combination has an index; the set maps each path to the first
    // combination that expanded to it.
    struct Combination {
        size_t camera, pass, ext, frame;
    };
    auto combination_at = [&](size_t index) {
        Combination c;
        c.frame = index % frames.size();
        index /= frames.size();
        c.ext = index % exts.size();
        index /= exts.size();
        c.pass = index % passes.size();
        c.camera = index / passes.size();
        return c;
    };
    auto describe_at = [&](const Combination& c) {
        return describe(frames[c.frame], cameras[c.camera], passes[c.pass], exts[c.ext]);
    };

    const size_t total = cameras.size() * passes.size() * exts.size() * frames.size();
    std::unordered_map<std::string, size_t> first_writer;
    first_writer.reserve(total);
    for (size_t index = 0; index < total; ++index) {
        Combination c = combination_at(index);
        OutputNameFields fields{scene,           cameras[c.camera], passes[c.pass],
                                frames[c.frame], exts[c.ext],       variant};
        std::string path = expand(output_template, fields);
        if (path == manifest_path)
            fail(text, "writes '" + path + "' for " + describe_at(c) +
                           ", which would overwrite the run's manifest; rename the file");
        auto [existing, inserted] = first_writer.emplace(std::move(path), index);
        if (inserted) continue;

        Combination a = combination_at(existing->second);
        // The same combination listed twice (e.g. a frame repeated) writes one file.
        bool same_camera = cameras[a.camera] == cameras[c.camera];
        bool same_pass = passes[a.pass] == passes[c.pass];
        bool same_ext = exts[a.ext] == exts[c.ext];
        bool same_frame = frames[a.frame] == frames[c.frame];
        if (same_camera && same_pass && same_ext && same_frame) continue;

        // Name the placeholder that would tell the two apart.
        std::string hint;
        auto suggest = [&](bool same, Placeholder p, const std::string& example) {
            if (same || output_template.uses(p)) return;
            hint += hint.empty() ? "; add " : " and ";
            hint += example;
        };
        suggest(same_frame, Placeholder::frame, "{frame} or ####");
        suggest(same_camera, Placeholder::camera, "{camera}");
        suggest(same_pass, Placeholder::pass, "{pass}");
        suggest(same_ext, Placeholder::ext, "{ext}");
        if (hint.empty())
            hint =
                "; the placeholders run together, so separate them with a character such as "
                "'.' or '_'";
        fail(text, "writes '" + existing->first + "' for both " + describe_at(a) + " and " +
                       describe_at(c) + hint);
    }
}

namespace {

// The components of manifest_directory's folder, in order.
std::vector<Component> manifest_components(const OutputTemplate& output_template,
                                           bool single_camera) {
    std::vector<Component> components = split_components(output_template);
    components.pop_back();  // the file name
    std::vector<Component> fixed;
    for (const Component& component : components) {
        bool fixed_for_run = std::all_of(component.begin(), component.end(), [&](auto* segment) {
            if (segment->kind == TemplateSegment::Kind::literal) return true;
            if (segment->placeholder == Placeholder::scene) return true;
            if (segment->placeholder == Placeholder::variant) return true;
            return segment->placeholder == Placeholder::camera && single_camera;
        });
        if (!fixed_for_run) break;
        fixed.push_back(component);
    }
    return fixed;
}

}  // namespace

bool manifest_directory_names_variant(const OutputTemplate& output_template, bool single_camera) {
    for (const Component& component : manifest_components(output_template, single_camera))
        for (const TemplateSegment* segment : component)
            if (segment->kind == TemplateSegment::Kind::placeholder &&
                segment->placeholder == Placeholder::variant)
                return true;
    return false;
}

std::string manifest_directory(const OutputTemplate& output_template, const OutputNameFields& fixed,
                               bool single_camera) {
    std::string directory;
    for (const Component& component : manifest_components(output_template, single_camera)) {
        if (!directory.empty()) directory += '/';
        for (const TemplateSegment* segment : component)
            append_segment(directory, *segment, fixed, output_template.text);
    }
    if (!directory.empty()) check_expanded_path(directory, output_template.text);
    return directory;
}

std::string path_relative_to_manifest(const std::string& output_path,
                                      const std::string& manifest_dir) {
    if (manifest_dir.empty()) return output_path;
    if (output_path.size() > manifest_dir.size() + 1 &&
        output_path.compare(0, manifest_dir.size(), manifest_dir) == 0 &&
        output_path[manifest_dir.size()] == '/')
        return output_path.substr(manifest_dir.size() + 1);
    throw Error(ExitCode::invalid_input, "output file '" + output_path +
                                             "' is not inside the manifest's folder '" +
                                             manifest_dir + "'");
}

}  // namespace facet
