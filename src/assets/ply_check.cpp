#include "assets/ply_check.hpp"

#include <cstring>
#include <map>
#include <sstream>

#include "core/error.hpp"

namespace facet {
namespace {

// The header must end within this: real headers are a few hundred bytes.
constexpr size_t kMaxHeaderBytes = 64 * 1024;
// A list longer than this is not a polygon any reader would keep.
constexpr uint64_t kMaxListLength = 1 << 16;

[[noreturn]] void bad(const std::string& path, const std::string& what) {
    throw Error(ExitCode::invalid_input, path + ": PLY " + what);
}

// Bytes of each scalar type, under both of the format's spellings.
int type_size(const std::string& type) {
    static const std::map<std::string, int> sizes = {
        {"char", 1},   {"int8", 1},    {"uchar", 1},  {"uint8", 1},  {"short", 2}, {"int16", 2},
        {"ushort", 2}, {"uint16", 2},  {"int", 4},    {"int32", 4},  {"uint", 4},  {"uint32", 4},
        {"float", 4},  {"float32", 4}, {"double", 8}, {"float64", 8}};
    const auto it = sizes.find(type);
    return it == sizes.end() ? 0 : it->second;
}

struct Property {
    int size = 0;        // a scalar's, or a list's items
    int count_size = 0;  // a list's length: 0 for a scalar
    std::string count_type, item_type;
    // A face's vertex list: its items must be below this (the vertex
    // count), as assimp indexes with them unchecked. 0: not checked.
    uint64_t index_limit = 0;
};

struct Element {
    std::string name;
    uint64_t count = 0;
    std::vector<Property> properties;
};

struct Header {
    std::string format;  // ascii, binary_little_endian, binary_big_endian
    std::vector<Element> elements;
    size_t data_start = 0;
};

Header parse_header(const std::vector<uint8_t>& bytes, const std::string& path) {
    const size_t scan = std::min(bytes.size(), kMaxHeaderBytes);
    const std::string head(bytes.begin(), bytes.begin() + static_cast<long>(scan));
    if (head.compare(0, 3, "ply") != 0) bad(path, "file does not start with 'ply'");
    size_t end = head.find("\nend_header");
    if (end == std::string::npos)
        bad(path, "header does not end (no end_header in its first 64 KiB)");
    ++end;
    // The line is end_header and nothing else: assimp's reader, given more
    // on it ("end_header#0 0 0"), never finds the header's end and loops.
    size_t after = end + std::strlen("end_header");
    if (after < head.size() && head[after] == '\r') ++after;
    if (after >= head.size() || head[after] != '\n')
        bad(path, "header's end_header line holds more than end_header");
    Header h;
    h.data_start = after + 1;
    std::istringstream lines(head.substr(0, end));
    std::string line;
    int number = 0;
    while (std::getline(lines, line)) {
        ++number;
        std::istringstream words(line);
        std::string word;
        words >> word;
        const std::string at = "header line " + std::to_string(number) + ": ";
        if (word == "ply" && number > 1) bad(path, at + "'ply' again inside the header");
        if (word.empty() || word == "ply" || word == "comment" || word == "obj_info") continue;
        if (word == "format") {
            // Exactly one, as "format TYPE 1.0": with two, or a version
            // assimp reads otherwise, it could read the data in another
            // format than the one checked here, past the end of its buffers.
            std::string version, extra;
            if (!h.format.empty()) bad(path, at + "a second format line");
            words >> h.format >> version;
            if (h.format != "ascii" && h.format != "binary_little_endian" &&
                h.format != "binary_big_endian")
                bad(path, at + "unknown format '" + h.format + "'");
            if (version != "1.0" || words >> extra)
                bad(path, at + "the format line must end with version 1.0");
        } else if (word == "element") {
            Element e;
            long double count = -1;
            if (!(words >> e.name >> count) || count < 0 || count > 1e12)
                bad(path, at + "an element needs a name and a count");
            e.count = static_cast<uint64_t>(count);
            h.elements.push_back(e);
        } else if (word == "property") {
            if (h.elements.empty()) bad(path, at + "a property before any element");
            Property p;
            std::string type;
            words >> type;
            if (type == "list") {
                std::string item;
                words >> p.count_type >> item;
                p.item_type = item;
                std::string name;
                words >> name;
                if (name == "vertex_indices" || name == "vertex_index") {
                    for (const Element& e : h.elements)
                        if (e.name == "vertex") p.index_limit = e.count;
                    // Faces before their vertices: no index can be right.
                    if (!p.index_limit) p.index_limit = UINT64_MAX;
                }
                p.count_size = type_size(p.count_type);
                p.size = type_size(item);
                if (!p.count_size || !p.size || p.count_type == "float" ||
                    p.count_type == "float32" || p.count_type == "double" ||
                    p.count_type == "float64")
                    bad(path, at + "unknown list types '" + p.count_type + " " + item + "'");
            } else {
                p.size = type_size(type);
                if (!p.size) bad(path, at + "unknown type '" + type + "'");
            }
            h.elements.back().properties.push_back(p);
        }
        // Other lines are skipped, as readers do: Blender 2.4 wrote its
        // comment without the keyword.
    }
    if (h.format.empty()) bad(path, "header has no format line");
    return h;
}

bool is_signed(const std::string& type) {
    return type == "char" || type == "int8" || type == "short" || type == "int16" ||
           type == "int" || type == "int32";
}

uint64_t read_count(const uint8_t* at, int size, bool big_endian, bool signed_type) {
    uint64_t value = 0;
    for (int i = 0; i < size; ++i) {
        const int byte = big_endian ? i : size - 1 - i;
        value = (value << 8) | at[byte];
    }
    // Signed counts: a negative one is as wrong as a huge one.
    if (signed_type && (value >> (8 * size - 1)) & 1) return UINT64_MAX;
    return value;
}

void check_binary(const std::vector<uint8_t>& bytes, const Header& h, const std::string& path) {
    const bool big_endian = h.format == "binary_big_endian";
    size_t at = h.data_start;
    for (const Element& e : h.elements) {
        // Every instance takes at least a byte, unless it has no properties.
        if (!e.properties.empty() && e.count > bytes.size() - at)
            bad(path, "element '" + e.name + "' declares more instances than the file holds");
        for (uint64_t i = 0; i < e.count; ++i)
            for (const Property& p : e.properties) {
                if (p.count_size == 0) {
                    if (bytes.size() - at < static_cast<size_t>(p.size))
                        bad(path, "element '" + e.name + "' ends early, at instance " +
                                      std::to_string(i) + " of " + std::to_string(e.count));
                    at += static_cast<size_t>(p.size);
                    continue;
                }
                if (bytes.size() - at < static_cast<size_t>(p.count_size))
                    bad(path, "element '" + e.name + "' ends early, at instance " +
                                  std::to_string(i) + " of " + std::to_string(e.count));
                const uint64_t length =
                    read_count(&bytes[at], p.count_size, big_endian, is_signed(p.count_type));
                at += static_cast<size_t>(p.count_size);
                if (length > kMaxListLength)
                    bad(path, "element '" + e.name + "' has a list of " +
                                  (length == UINT64_MAX ? std::string("negative")
                                                        : std::to_string(length)) +
                                  " items");
                if ((bytes.size() - at) / static_cast<size_t>(p.size) < length)
                    bad(path, "element '" + e.name + "' ends early, at instance " +
                                  std::to_string(i) + " of " + std::to_string(e.count));
                if (p.index_limit && p.item_type.find("float") == std::string::npos &&
                    p.item_type != "double")
                    for (uint64_t k = 0; k < length; ++k)
                        if (read_count(&bytes[at + k * static_cast<size_t>(p.size)], p.size,
                                       big_endian, is_signed(p.item_type)) >= p.index_limit)
                            bad(path, "element '" + e.name + "' instance " + std::to_string(i) +
                                          " refers to a vertex past the " +
                                          std::to_string(p.index_limit) + " there are");
                at += static_cast<size_t>(length) * static_cast<size_t>(p.size);
            }
    }
}

void check_ascii(const std::vector<uint8_t>& bytes, const Header& h, const std::string& path) {
    size_t at = h.data_start;
    // The next whitespace-separated word, as a number; false at the end.
    auto space = [&](size_t i) {
        return bytes[i] == ' ' || bytes[i] == '\t' || bytes[i] == '\r' || bytes[i] == '\n';
    };
    auto next_number = [&](double& value) {
        while (at < bytes.size() && space(at)) ++at;
        if (at >= bytes.size()) return false;
        const size_t start = at;
        while (at < bytes.size() && !space(at)) ++at;
        const std::string word(bytes.begin() + static_cast<long>(start),
                               bytes.begin() + static_cast<long>(at));
        char* end = nullptr;
        value = std::strtod(word.c_str(), &end);
        if (end != word.c_str() + word.size())
            bad(path, "data has '" + word.substr(0, 40) + "' where a number belongs");
        return true;
    };
    for (const Element& e : h.elements) {
        if (!e.properties.empty() && e.count > (bytes.size() - at) / 2 + 1)
            bad(path, "element '" + e.name + "' declares more instances than the file holds");
        for (uint64_t i = 0; i < e.count; ++i)
            for (const Property& p : e.properties) {
                double value = 0;
                const std::string early = "element '" + e.name + "' ends early, at instance " +
                                          std::to_string(i) + " of " + std::to_string(e.count);
                if (!next_number(value)) bad(path, early);
                if (p.count_size == 0) continue;
                if (!(value >= 0 && value <= static_cast<double>(kMaxListLength)) ||
                    value != static_cast<double>(static_cast<uint64_t>(value)))
                    bad(path, "element '" + e.name + "' has a list length that is not 0 to " +
                                  std::to_string(kMaxListLength));
                const uint64_t length = static_cast<uint64_t>(value);
                for (uint64_t k = 0; k < length; ++k) {
                    if (!next_number(value)) bad(path, early);
                    if (p.index_limit &&
                        !(value >= 0 && value < static_cast<double>(p.index_limit)))
                        bad(path, "element '" + e.name + "' instance " + std::to_string(i) +
                                      " refers to a vertex past the " +
                                      std::to_string(p.index_limit) + " there are");
                }
            }
    }
}

}  // namespace

void check_ply(const std::vector<uint8_t>& bytes, const std::string& path) {
    const Header header = parse_header(bytes, path);
    if (header.format == "ascii")
        check_ascii(bytes, header, path);
    else
        check_binary(bytes, header, path);
}

}  // namespace facet
