// OBJ geometry statements read in parallel chunks (assets/obj_parse.hpp).
//
// Two passes over the chunks: the first counts each chunk's lines and
// v, vt and vn statements, so that the second knows, for every statement,
// its line number and how many vertices precede it. A relative index
// (f -1 -2 -3) is then resolved in the chunk that holds it, and each
// chunk writes its vertices straight into the file's arrays.
#include "assets/obj_parse.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstring>
#include <limits>
#include <memory>

#include "core/input_file.hpp"
#include "core/thread_pool.hpp"

namespace facet {
namespace {

// Chunks are cut by size alone (never by thread count), so the parse is
// the same on any machine; a megabyte is some 30 000 lines, enough to
// make a chunk's fixed costs small.
constexpr size_t kChunkBytes = size_t(1) << 20;

bool is_blank(char c) {
    return c == ' ' || c == '\t';
}

// An ASCII letter (std::isalpha in the "C" locale, without its call).
bool is_letter(char c) {
    const char lower = static_cast<char>(c | 0x20);
    return lower >= 'a' && lower <= 'z';
}

// 'word', for messages. Built by appending: GCC 12 at -O3 warns falsely
// (-Wrestrict, GCC bug 105329) about "literal" + std::string.
std::string quoted(std::string_view word) {
    std::string text;
    text += '\'';
    text += word;
    text += '\'';
    return text;
}

// Calls visit(line) for each line of `text`, without its LF or CRLF.
template <class Visit>
void for_each_line(std::string_view text, Visit&& visit) {
    size_t pos = 0;
    while (pos < text.size()) {
        const void* found = std::memchr(text.data() + pos, '\n', text.size() - pos);
        const size_t end = found
                               ? static_cast<size_t>(static_cast<const char*>(found) - text.data())
                               : text.size();
        size_t stop = end;
        if (stop > pos && text[stop - 1] == '\r') --stop;
        visit(text.substr(pos, stop - pos));
        pos = end + 1;
    }
}

// Whether the text has line ends other than LF and CRLF (a lone CR, as old
// Mac files have) or NUL bytes, which end a line's data.
bool needs_line_cleanup(std::string_view text) {
    if (std::memchr(text.data(), '\0', text.size())) return true;
    for (size_t pos = text.find('\r'); pos != std::string_view::npos;
         pos = text.find('\r', pos + 1))
        if (pos + 1 == text.size() || text[pos + 1] != '\n') return true;
    return false;
}

// The text with each lone CR made a LF and each line cut at its first NUL.
std::string clean_lines(std::string_view text) {
    std::string out;
    out.reserve(text.size());
    bool cut = false;
    for (size_t i = 0; i < text.size(); ++i) {
        char c = text[i];
        if (c == '\r' && (i + 1 == text.size() || text[i + 1] != '\n')) c = '\n';
        if (c == '\n') cut = false;
        if (c == '\0') cut = true;
        if (!cut) out += c;
    }
    return out;
}

// [begin, end) of each chunk: about kChunkBytes each, cut after a LF.
std::vector<std::pair<size_t, size_t>> cut_chunks(std::string_view text) {
    std::vector<std::pair<size_t, size_t>> chunks;
    size_t begin = 0;
    while (begin < text.size()) {
        size_t end = std::min(text.size(), begin + kChunkBytes);
        if (end < text.size()) {
            const size_t lf = text.find('\n', end - 1);
            end = lf == std::string_view::npos ? text.size() : lf + 1;
        }
        chunks.emplace_back(begin, end);
        begin = end;
    }
    return chunks;
}

enum class Keyword {
    other,  // comments, blank lines, and statements facet does not read (o, s, vw, curv...)
    position,
    uv,
    normal,
    parameter,  // vp
    face,
    line_element,  // l
    free_form,     // curv, curv2, surf and their statements: curves and surfaces
    point,         // p
    use_material,
    material_library,
    group,
};

struct Statement {
    Keyword keyword = Keyword::other;
    size_t args = 0;  // where the arguments start: after the keyword and one blank
};

// What a line states. A keyword must be followed by a blank ("v" alone is
// nothing), except usemtl, which without a name selects no material.
Statement classify(std::string_view line) {
    size_t i = 0;
    while (i < line.size() && is_blank(line[i])) ++i;
    size_t end = i;
    while (end < line.size() && !is_blank(line[end])) ++end;
    const std::string_view word = line.substr(i, end - i);
    // As other readers, "usemtlName" is read as "usemtl Name".
    if (word.substr(0, 6) == "usemtl") return {Keyword::use_material, i + 6};
    if (end == line.size() || word.empty()) return {};
    struct Name {
        std::string_view word;
        Keyword keyword;
    };
    static constexpr Name kNames[] = {
        {"v", Keyword::position},      {"vt", Keyword::uv},
        {"vn", Keyword::normal},       {"vp", Keyword::parameter},
        {"f", Keyword::face},          {"l", Keyword::line_element},
        {"p", Keyword::point},         {"mtllib", Keyword::material_library},
        {"g", Keyword::group},         {"curv", Keyword::free_form},
        {"curv2", Keyword::free_form}, {"surf", Keyword::free_form},
    };
    for (const Name& n : kNames)
        if (word == n.word) return {n.keyword, end + 1};
    return {};
}

// What the first pass finds in a chunk.
struct ChunkCounts {
    size_t lines = 0, positions = 0, uvs = 0, normals = 0;
    bool needs_cleanup = false;  // needs_line_cleanup
};

ChunkCounts count_chunk(std::string_view chunk) {
    ChunkCounts counts;
    counts.needs_cleanup = needs_line_cleanup(chunk);
    if (counts.needs_cleanup) return counts;
    for_each_line(chunk, [&](std::string_view line) {
        ++counts.lines;
        switch (classify(line).keyword) {
            case Keyword::position:
                ++counts.positions;
                break;
            case Keyword::uv:
                ++counts.uvs;
                break;
            case Keyword::normal:
                ++counts.normals;
                break;
            default:
                break;
        }
    });
    return counts;
}

// A kind of thing read but not drawn as written: where it first happens,
// and how often.
struct Occurrences {
    int line = 0, column = 0;
    std::string token;
    size_t count = 0;

    void add(int at_line, int at_column) {
        if (count++ == 0) {
            line = at_line;
            column = at_column;
        }
    }
    void add(int at_line, int at_column, std::string_view at_token) {
        if (count == 0) token = at_token;
        add(at_line, at_column);
    }
    void add(const Occurrences& later) {
        if (count == 0)
            *this = later;
        else
            count += later.count;
    }
};

// The things a chunk counts for warnings.
struct ChunkNotes {
    Occurrences short_faces, missing_uvs, missing_normals, empty_groups;
    Occurrences lines_and_points, curves_and_surfaces;

    void add(const ChunkNotes& later) {
        lines_and_points.add(later.lines_and_points);
        curves_and_surfaces.add(later.curves_and_surfaces);
        short_faces.add(later.short_faces);
        missing_uvs.add(later.missing_uvs);
        missing_normals.add(later.missing_normals);
        empty_groups.add(later.empty_groups);
    }
};

// A number in a vertex statement. Other readers give 0 for a word that is
// not a number ("-", "."), and so does this; a leading '+' is allowed.
// A number too small for a float is 0; one too large is refused (nullopt).
std::optional<float> read_coordinate(std::string_view word) {
    const char* first = word.data();
    const char* last = first + word.size();
    if (first < last && *first == '+') {
        ++first;
        if (first < last && (*first == '+' || *first == '-')) return 0.0f;
    }
    float value = 0;
    const auto [stop, error] = std::from_chars(first, last, value);
    // "1e" or "2.5e+" has no exponent's digits: not a number, as for "-".
    if (error == std::errc() && stop < last && (*stop == 'e' || *stop == 'E')) return 0.0f;
    if (error == std::errc()) return value;
    if (error == std::errc::invalid_argument) return 0.0f;
    const bool negative = first < last && *first == '-';
    double wide = 0;
    if (std::from_chars(first, last, wide).ec == std::errc()) {
        if (std::abs(wide) < 1) return negative ? -0.0f : 0.0f;
        return std::nullopt;
    }
    const bool tiny =
        word.find("e-") != std::string_view::npos || word.find("E-") != std::string_view::npos;
    if (tiny) return negative ? -0.0f : 0.0f;
    return std::nullopt;
}

// An index field of a face corner as atoi-based readers take it: an
// optional sign and digits, the rest of the field up to '/' skipped.
// 0 when there are no digits (0 is no index in OBJ) or too many.
int64_t read_index_field(const char*& p, const char* end) {
    const char* first = p;
    if (first < end && *first == '+') ++first;
    int32_t value = 0;
    const auto [stop, error] = std::from_chars(first, end, value);
    p = error == std::errc() ? stop : first;
    while (p < end && *p != '/') ++p;
    return error == std::errc() ? value : 0;
}

// The raw indices of one corner word ("7", "7/3", "7//2", "7/3/2");
// nullopt when one of them is missing or 0.
struct RawCorner {
    int64_t position = 0, uv = 0, normal = 0;
};

std::optional<RawCorner> read_corner(std::string_view word) {
    const char* p = word.data();
    const char* end = p + word.size();
    RawCorner c;
    c.position = read_index_field(p, end);
    if (c.position == 0) return std::nullopt;
    if (p < end && *p == '/') {
        ++p;
        if (p < end && *p == '/') {
            ++p;
            c.normal = read_index_field(p, end);
            if (c.normal == 0) return std::nullopt;
        } else {
            c.uv = read_index_field(p, end);
            if (c.uv == 0) return std::nullopt;
            if (p < end && *p == '/') {
                ++p;
                c.normal = read_index_field(p, end);
                if (c.normal == 0) return std::nullopt;
            }
        }
    }
    if (p < end) return std::nullopt;  // a fourth field: "1/2/3/4"
    return c;
}

// A raw OBJ index made zero-based: positive ones count from the file's
// first element, negative ones back from the last one before the statement.
int64_t resolve_index(int64_t raw, size_t before) {
    return raw > 0 ? raw - 1 : static_cast<int64_t>(before) + raw;
}

// The file's totals and this chunk's place among the chunks.
struct ChunkPlace {
    size_t first_line = 0;  // lines before the chunk
    ChunkCounts before;     // v, vt and vn statements before the chunk
    ChunkCounts own;        // in the chunk, as the first pass counted them
    ChunkCounts total;      // in the whole file
};

// Parses one chunk (the second pass).
class ChunkParser {
  public:
    ChunkParser(const std::string& path, const ChunkPlace& place, ObjGeometry& file)
        : path_(path), place_(place), file_(file), counts_(place.before), limit_(place.before) {
        limit_.positions += place.own.positions;
        limit_.uvs += place.own.uvs;
        limit_.normals += place.own.normals;
    }

    void parse(std::string_view chunk) {
        // Room for the corners of a file of triangles ("f 1/1 2/2 3/3" is
        // some 20 bytes), so that the vector seldom moves.
        faces.corners.reserve(chunk.size() / 6);
        faces.corner_counts.reserve(chunk.size() / 20);
        size_t line_index = 0;
        for_each_line(chunk, [&](std::string_view line) {
            if (error) return;
            line_ = static_cast<int>(place_.first_line + ++line_index);
            parse_line(line);
        });
        // A file read twice may have changed in between: its vertices
        // would not be where the first pass put them.
        changed =
            !error && (line_index != place_.own.lines || counts_.positions != limit_.positions ||
                       counts_.uvs != limit_.uvs || counts_.normals != limit_.normals);
    }

    ObjFaceChunk faces;
    std::vector<ObjStatement> statements;
    ChunkNotes notes;
    std::optional<Error> error;
    int error_line = 0;
    bool changed = false;  // the chunk is not what the first pass counted

  private:
    void fail(size_t column, const std::string& message) {
        error = Error(ExitCode::invalid_input,
                      SourceLocation{path_, line_, static_cast<int>(column) + 1, ""}, "", message);
        error_line = line_;
    }

    void parse_line(std::string_view line) {
        const Statement s = classify(line);
        switch (s.keyword) {
            case Keyword::position: {
                float xyz[3] = {0, 0, 0};
                if (read_numbers(line, s.args, xyz, 3) && counts_.positions < limit_.positions)
                    file_.positions[counts_.positions] = {xyz[0], xyz[1], xyz[2]};
                ++counts_.positions;
                break;
            }
            case Keyword::uv: {
                float uv[2] = {0, 0};
                if (read_numbers(line, s.args, uv, 2) && counts_.uvs < limit_.uvs)
                    file_.uvs[counts_.uvs] = {uv[0], uv[1]};
                ++counts_.uvs;
                break;
            }
            case Keyword::normal: {
                float xyz[3] = {0, 0, 0};
                if (read_numbers(line, s.args, xyz, 3) && counts_.normals < limit_.normals)
                    file_.normals[counts_.normals] = {xyz[0], xyz[1], xyz[2]};
                ++counts_.normals;
                break;
            }
            case Keyword::parameter:
                read_numbers(line, s.args, nullptr, 0);
                break;
            case Keyword::face:
                read_face(line, s.args);
                break;
            case Keyword::line_element:
            case Keyword::point:
                notes.lines_and_points.add(line_, 1);
                check_corners(line, s.args);
                break;
            case Keyword::free_form:
                notes.curves_and_surfaces.add(line_, 1);
                break;
            case Keyword::use_material:
                use_material(line, s.args);
                break;
            case Keyword::material_library:
                statements.push_back({ObjStatement::Kind::material_library, line_,
                                      faces.corner_counts.size(),
                                      std::string(line.substr(s.args))});
                break;
            case Keyword::group:
                if (line.find_first_not_of(" \t", s.args) == std::string_view::npos)
                    notes.empty_groups.add(line_, 1);
                break;
            case Keyword::other:
                break;
        }
    }

    // Reads the words of a vertex statement after `from`: the first `count`
    // into `out`. Every word before a comment must be a finite number
    // (letters other than an exponent's e have no place in one); false
    // after an error.
    bool read_numbers(std::string_view line, size_t from, float* out, int count) {
        int index = 0;
        size_t i = from;
        while (i < line.size()) {
            while (i < line.size() && is_blank(line[i])) ++i;
            if (i == line.size() || line[i] == '#') break;
            size_t end = i;
            while (end < line.size() && !is_blank(line[end])) ++end;
            const std::string_view word = line.substr(i, end - i);
            const std::string_view number = word.substr(0, word.find('#'));
            for (char c : number)
                if (is_letter(c) && c != 'e' && c != 'E') {
                    fail(i, quoted(word) + " is not a finite number, which vertex data must be");
                    return false;
                }
            if (index < count) {
                const std::optional<float> value = read_coordinate(number);
                if (!value) {
                    fail(i, quoted(word) + " is too large for a float");
                    return false;
                }
                out[index] = *value;
            }
            ++index;
            if (number.size() < word.size()) break;  // a comment follows
            i = end;
        }
        return true;
    }

    // Calls visit(word, column) for each blank-separated word after `from`.
    template <class Visit>
    static void for_each_word(std::string_view line, size_t from, Visit&& visit) {
        size_t i = from;
        while (i < line.size()) {
            while (i < line.size() && is_blank(line[i])) ++i;
            if (i == line.size()) break;
            size_t end = i;
            while (end < line.size() && !is_blank(line[end])) ++end;
            if (!visit(line.substr(i, end - i), i)) return;
            i = end;
        }
    }

    void fail_not_index(std::string_view word, size_t column) {
        fail(column, quoted(word) +
                         " is not a vertex reference: OBJ counts vertices from 1, or back from -1");
    }

    // l and p statements are not drawn, but a reference that is no index
    // makes the file unreadable, as it does in a face.
    void check_corners(std::string_view line, size_t from) {
        for_each_word(line, from, [&](std::string_view word, size_t column) {
            if (read_corner(word)) return true;
            fail_not_index(word, column);
            return false;
        });
    }

    void read_face(std::string_view line, size_t from) {
        const size_t first = faces.corners.size();
        struct BadPosition {
            std::string_view word;
            size_t column = 0;
            int64_t raw = 0;
        };
        std::optional<BadPosition> bad;
        for_each_word(line, from, [&](std::string_view word, size_t column) {
            const std::optional<RawCorner> raw = read_corner(word);
            if (!raw) {
                fail_not_index(word, column);
                return false;
            }
            ObjCorner c;
            const int64_t position = resolve_index(raw->position, counts_.positions);
            if (position < 0 || position >= static_cast<int64_t>(place_.total.positions)) {
                if (!bad) bad = BadPosition{word, column, raw->position};
            } else {
                c.position = static_cast<int32_t>(position);
            }
            c.uv = optional_index(raw->uv, counts_.uvs, place_.total.uvs, word, column,
                                  notes.missing_uvs);
            c.normal = optional_index(raw->normal, counts_.normals, place_.total.normals, word,
                                      column, notes.missing_normals);
            faces.corners.push_back(c);
            return true;
        });
        if (error) return;
        const size_t count = faces.corners.size() - first;
        if (count < 3) {  // a point or a line: not a surface, whatever its indices
            faces.corners.resize(first);
            notes.short_faces.add(line_, 1);
            return;
        }
        if (bad) {
            fail_bad_position(*bad);
            return;
        }
        faces.corner_counts.push_back(static_cast<uint32_t>(count));
    }

    template <class Bad>
    void fail_bad_position(const Bad& bad) {
        const std::string word = quoted(bad.word) + " ";
        const std::string have = std::to_string(place_.total.positions);
        if (bad.raw > 0)
            fail(bad.column, word + "refers to vertex " + std::to_string(bad.raw) +
                                 ", but the file has " + have);
        else
            fail(bad.column, word + "counts back past the first vertex: " +
                                 std::to_string(counts_.positions) + " precede it");
    }

    // A texture coordinate or normal index, zero-based; -1 when the corner
    // gives none or one the file does not have (counted in `missing`).
    int32_t optional_index(int64_t raw, size_t before, size_t total, std::string_view word,
                           size_t column, Occurrences& missing) {
        if (raw == 0) return -1;
        const int64_t index = resolve_index(raw, before);
        if (index >= 0 && index < static_cast<int64_t>(total)) return static_cast<int32_t>(index);
        missing.add(line_, static_cast<int>(column) + 1, word);
        return -1;
    }

    // usemtl NAME: the name's words joined by single spaces (names may
    // contain spaces: "newmtl Hard Shiny Plastic White", assimp issue #545).
    void use_material(std::string_view line, size_t from) {
        std::string name;
        for_each_word(line, from, [&](std::string_view word, size_t) {
            if (!name.empty()) name += ' ';
            name += word;
            return true;
        });
        statements.push_back(
            {ObjStatement::Kind::use_material, line_, faces.corner_counts.size(), std::move(name)});
    }

    const std::string& path_;
    const ChunkPlace& place_;
    ObjGeometry& file_;
    ChunkCounts counts_;  // v, vt and vn statements before the current line
    ChunkCounts limit_;   // before the next chunk: the chunk writes below these
    int line_ = 0;
};

Warning line_warning(const std::string& path, const Occurrences& o, const std::string& message) {
    Warning w;
    w.where = SourceLocation{path, o.line, o.column, ""};
    w.message = message;
    return w;
}

// The chunks' notes as warnings, each naming its first place and how many
// more there are.
void add_warnings(const ChunkNotes& notes, const std::string& path, ObjGeometry& file) {
    auto note = [&](const Occurrences& o, const std::string& message) {
        if (o.count == 0) return;
        const std::string more =
            o.count == 1 ? "" : " (and " + std::to_string(o.count - 1) + " more)";
        file.warnings.push_back(line_warning(path, o, message + more));
    };
    note(notes.short_faces,
         "a face of fewer than three corners is not a surface, and is not drawn");
    note(notes.missing_uvs, quoted(notes.missing_uvs.token) +
                                " names a texture coordinate the file does not have: the "
                                "corner has none");
    note(notes.missing_normals, quoted(notes.missing_normals.token) +
                                    " names a normal the file does not have: its part's "
                                    "normals are computed");
    note(notes.lines_and_points,
         "line ('l') and point ('p') elements are not drawn: facet draws faces only");
    note(notes.curves_and_surfaces,
         "free-form curves and surfaces (curv, curv2, surf) are not drawn: facet reads "
         "polygon faces only");
    note(notes.empty_groups, "'g' without a group name");
}

// Each chunk's place from the first pass's counts; the file's arrays
// made room for every vertex.
std::vector<ChunkPlace> place_chunks(const std::vector<ChunkCounts>& counts,
                                     const std::string& path, ObjGeometry& file) {
    std::vector<ChunkPlace> places(counts.size());
    ChunkPlace running;
    for (size_t i = 0; i < counts.size(); ++i) {
        places[i] = running;
        places[i].own = counts[i];
        running.first_line += counts[i].lines;
        running.before.positions += counts[i].positions;
        running.before.uvs += counts[i].uvs;
        running.before.normals += counts[i].normals;
    }
    const ChunkCounts total = running.before;
    for (ChunkPlace& p : places) p.total = total;
    constexpr size_t kMaxIndex = std::numeric_limits<int32_t>::max();
    if (total.positions > kMaxIndex || total.uvs > kMaxIndex || total.normals > kMaxIndex)
        throw Error(ExitCode::invalid_input, path + ": more vertices than an OBJ index can count");
    file.positions.resize(total.positions);
    file.uvs.resize(total.uvs);
    file.normals.resize(total.normals);
    return places;
}

// The chunks' faces, statements and notes joined in file order.
void join_chunks(std::vector<ChunkParser>& parsers, const std::string& path, ObjGeometry& file) {
    ChunkNotes notes;
    size_t faces_before = 0;
    for (ChunkParser& parser : parsers) {
        if (parser.changed)
            throw Error(ExitCode::io_failure, path + ": the OBJ file changed while it was read");
        if (parser.error && !file.error) {
            file.error = parser.error;
            file.error_line = parser.error_line;
        }
        notes.add(parser.notes);
        for (ObjStatement& s : parser.statements) {
            s.faces_before += faces_before;
            file.statements.push_back(std::move(s));
        }
        faces_before += parser.faces.corner_counts.size();
        file.faces.push_back(std::move(parser.faces));
    }
    add_warnings(notes, path, file);
}

// Parses the text; text with lone CRs or NULs is cleaned first
// (clean_lines), which the first pass finds.
ObjGeometry parse_text(std::string_view text, const std::string& path, ThreadPool* pool) {
    const std::vector<std::pair<size_t, size_t>> chunks = cut_chunks(text);
    auto chunk_text = [&](size_t i) {
        return text.substr(chunks[i].first, chunks[i].second - chunks[i].first);
    };
    std::vector<ChunkCounts> counts(chunks.size());
    run_each(pool, chunks.size(), [&](size_t i) { counts[i] = count_chunk(chunk_text(i)); });
    for (const ChunkCounts& c : counts) {
        if (!c.needs_cleanup) continue;
        const std::string cleaned = clean_lines(text);
        return parse_text(cleaned, path, pool);
    }
    ObjGeometry file;
    const std::vector<ChunkPlace> places = place_chunks(counts, path, file);
    std::vector<ChunkParser> parsers;
    parsers.reserve(chunks.size());
    for (size_t i = 0; i < chunks.size(); ++i) parsers.emplace_back(path, places[i], file);
    run_each(pool, chunks.size(), [&](size_t i) { parsers[i].parse(chunk_text(i)); });
    join_chunks(parsers, path, file);
    return file;
}

}  // namespace

size_t ObjGeometry::face_count() const {
    size_t n = 0;
    for (const ObjFaceChunk& chunk : faces) n += chunk.corner_counts.size();
    return n;
}

ObjGeometry parse_obj_geometry(std::string_view text, const std::string& path, ThreadPool* pool) {
    return parse_text(text, path, pool);
}

}  // namespace facet
