#include "assets/mesh_format.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <string_view>
#include <vector>

#include "core/input_file.hpp"

namespace facet {
namespace {

struct FormatNames {
    MeshFormat format;
    const char* name;
    std::vector<std::string_view> extensions;  // lower case, with the dot
};

const std::array<FormatNames, 8> kFormats = {{
    {MeshFormat::gltf, "glTF (.gltf)", {".gltf"}},
    {MeshFormat::glb, "glTF binary (.glb)", {".glb"}},
    {MeshFormat::obj, "OBJ", {".obj"}},
    {MeshFormat::stl, "STL", {".stl"}},
    {MeshFormat::ply, "PLY", {".ply"}},
    {MeshFormat::fbx, "FBX", {".fbx"}},
    {MeshFormat::collada, "Collada (.dae)", {".dae"}},
    {MeshFormat::max3ds, "3DS", {".3ds"}},
}};

std::string_view as_text(std::span<const uint8_t> bytes) {
    return {reinterpret_cast<const char*>(bytes.data()), bytes.size()};
}

// The text after a UTF-8 byte order mark and leading white space.
std::string_view trimmed_start(std::string_view text) {
    if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);
    while (!text.empty() && std::isspace(static_cast<unsigned char>(text.front())))
        text.remove_prefix(1);
    return text;
}

bool starts_with(std::string_view text, std::string_view prefix) {
    return text.substr(0, prefix.size()) == prefix;
}

uint32_t little_endian_u32(std::span<const uint8_t> bytes, size_t at) {
    return uint32_t(bytes[at]) | uint32_t(bytes[at + 1]) << 8 | uint32_t(bytes[at + 2]) << 16 |
           uint32_t(bytes[at + 3]) << 24;
}

// The statements an OBJ file is made of (Wavefront's list, with the
// free-form geometry ones that readers skip).
bool is_obj_statement(std::string_view word) {
    static const std::array<std::string_view, 30> kWords = {
        "v",    "vt",    "vn",     "vp",     "f",        "l",       "p",    "o",
        "g",    "s",     "mtllib", "usemtl", "cstype",   "deg",     "bmat", "step",
        "curv", "curv2", "surf",   "parm",   "trim",     "hole",    "scrv", "sp",
        "end",  "con",   "mg",     "bevel",  "c_interp", "d_interp"};
    return std::find(kWords.begin(), kWords.end(), word) != kWords.end();
}

// OBJ: every statement line of the sample begins with an OBJ statement
// (comments and blank lines aside) and at least one is a vertex. A YAML
// scene fails at its first key (`output:`), so the two are never confused.
// Only whole lines are judged: the sample may end in the middle of one.
bool looks_like_obj(std::string_view text, bool whole_file) {
    if (!whole_file) {
        const size_t last_newline = text.find_last_of('\n');
        if (last_newline == std::string_view::npos) return false;
        text = text.substr(0, last_newline);
    }
    bool vertex = false;
    while (!text.empty()) {
        const size_t end = std::min(text.find('\n'), text.size());
        std::string_view line = trimmed_start(text.substr(0, end));
        text.remove_prefix(std::min(end + 1, text.size()));
        if (line.empty() || line.front() == '#') continue;
        size_t word_end = 0;
        while (word_end < line.size() && !std::isspace(static_cast<unsigned char>(line[word_end])))
            ++word_end;
        const std::string_view word = line.substr(0, word_end);
        if (!is_obj_statement(word)) return false;
        vertex = vertex || (word == "v" && word_end < line.size());
    }
    return vertex;
}

std::optional<MeshFormat> binary_format(std::span<const uint8_t> head, uint64_t file_size) {
    const std::string_view text = as_text(head);
    if (starts_with(text, "glTF")) return MeshFormat::glb;
    if (starts_with(text, "Kaydara FBX Binary")) return MeshFormat::fbx;
    // 3DS: the main chunk (0x4D4D) and its length, which is the whole file's.
    if (head.size() >= 6 && head[0] == 0x4D && head[1] == 0x4D &&
        little_endian_u32(head, 2) == file_size)
        return MeshFormat::max3ds;
    // Binary STL: an 80-byte header, a triangle count, then 50 bytes per
    // triangle, exactly (its header may begin with "solid" too).
    if (head.size() >= 84 && file_size == 84 + 50 * uint64_t(little_endian_u32(head, 80)))
        return MeshFormat::stl;
    return std::nullopt;
}

std::optional<MeshFormat> text_format(std::span<const uint8_t> head, uint64_t file_size) {
    const std::string_view whole = as_text(head);
    if (whole.find('\0') != std::string_view::npos) return std::nullopt;
    const std::string_view text = trimmed_start(whole);
    if (starts_with(text, "ply\n") || starts_with(text, "ply\r")) return MeshFormat::ply;
    if (starts_with(text, "solid") && (text.find("facet") != std::string_view::npos ||
                                       text.find("endsolid") != std::string_view::npos))
        return MeshFormat::stl;
    if (starts_with(text, "; FBX")) return MeshFormat::fbx;
    if (starts_with(text, "<") && text.find("<COLLADA") != std::string_view::npos)
        return MeshFormat::collada;
    // glTF's JSON: an object with the required "asset" member. (A scene may
    // be written as a JSON-like YAML mapping too, but has no "asset".)
    if (starts_with(text, "{") && text.find("\"asset\"") != std::string_view::npos)
        return MeshFormat::gltf;
    if (looks_like_obj(text, head.size() >= file_size)) return MeshFormat::obj;
    return std::nullopt;
}

}  // namespace

std::string mesh_format_name(MeshFormat format) {
    for (const FormatNames& f : kFormats)
        if (f.format == format) return f.name;
    return "mesh";
}

std::string_view mesh_format_extension(MeshFormat format) {
    for (const FormatNames& f : kFormats)
        if (f.format == format) return f.extensions.front().substr(1);
    return "";
}

std::string mesh_formats_read() {
    return "glTF (.gltf, .glb), OBJ (.obj), STL (.stl), PLY (.ply), FBX (.fbx), Collada (.dae) "
           "and 3DS (.3ds)";
}

std::optional<MeshFormat> mesh_format_of_bytes(std::span<const uint8_t> head, uint64_t file_size) {
    if (const auto binary = binary_format(head, file_size)) return binary;
    return text_format(head, file_size);
}

std::optional<MeshFormat> mesh_format_of_name(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    for (const FormatNames& f : kFormats)
        if (std::find(f.extensions.begin(), f.extensions.end(), ext) != f.extensions.end())
            return f.format;
    return std::nullopt;
}

std::optional<MeshFormat> recognise_mesh_file(const std::string& path) {
    // Only a regular file is opened: a FIFO or a device could block or
    // never end, and the loader reports what stands in the way.
    if (input_file_problem(path).empty()) {
        std::error_code ec;
        const uint64_t size = std::filesystem::file_size(path, ec);
        std::ifstream in(path, std::ios::binary);
        if (!ec && in) {
            std::vector<uint8_t> head(
                static_cast<size_t>(std::min<uint64_t>(size, kMeshSniffBytes)));
            in.read(reinterpret_cast<char*>(head.data()),
                    static_cast<std::streamsize>(head.size()));
            head.resize(static_cast<size_t>(in.gcount()));
            if (const auto format = mesh_format_of_bytes(head, size)) return format;
        }
    }
    return mesh_format_of_name(path);
}

}  // namespace facet
