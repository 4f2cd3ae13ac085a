#pragma once
// The statements of a Wavefront OBJ file that make its geometry (v, vt,
// vn, f, usemtl, mtllib), read in chunks that split the text at line
// boundaries, in parallel. The chunks are cut by the text's size alone and
// joined in file order, so the result is the same for any thread count.
// Materials are left to the caller: usemtl and mtllib come back as
// statements in file order (assets/obj_loader.cpp).
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "core/diagnostics.hpp"
#include "core/error.hpp"

namespace facet {

class ThreadPool;

// One corner of a face: zero-based indices into the file's positions,
// texture coordinates and normals. uv and normal are -1 where the corner
// names none, or one the file does not have (a warning says so); position
// is always valid.
struct ObjCorner {
    int32_t position = -1;
    int32_t uv = -1;
    int32_t normal = -1;
};

// The faces of one chunk of the file, in file order; each has at least
// three corners (shorter ones are not surfaces, and are counted in a
// warning instead).
struct ObjFaceChunk {
    std::vector<ObjCorner> corners;
    std::vector<uint32_t> corner_counts;  // per face
};

// A usemtl or mtllib statement, in file order.
struct ObjStatement {
    enum class Kind { material_library, use_material };
    Kind kind = Kind::use_material;
    int line = 0;
    size_t faces_before = 0;  // the file's faces before it
    // mtllib: the rest of the line, as written; usemtl: the material's
    // name, its words joined by single spaces.
    std::string text;
};

struct ObjGeometry {
    std::vector<glm::vec3> positions;
    std::vector<glm::vec2> uvs;  // as written: v = 0 at the bottom of the image
    std::vector<glm::vec3> normals;
    std::vector<ObjFaceChunk> faces;
    std::vector<ObjStatement> statements;
    // What is read but not drawn as written, each naming its first line.
    Warnings warnings;
    // The first statement that cannot be read, if any: the caller reads
    // the material statements before its line (a refused material library
    // there is the error to report), then throws it.
    std::optional<Error> error;
    int error_line = 0;

    size_t face_count() const;
};

// Parses OBJ text (UTF-8, without a byte order mark; lines end in LF, CRLF
// or CR) from the file `path` (named in messages). With a pool, the chunks
// are parsed on its threads; the result is the same without one.
ObjGeometry parse_obj_geometry(std::string_view text, const std::string& path,
                               ThreadPool* pool = nullptr);

}  // namespace facet
