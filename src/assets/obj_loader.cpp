// Wavefront OBJ + MTL: the geometry through facet's own parallel reader
// (assets/obj_parse.hpp), the materials through tinyobjloader's MTL reader
// (assets/obj_materials.hpp).
#include <algorithm>
#include <array>
#include <atomic>
#include <limits>
#include <map>
#include <tuple>

#include <glm/geometric.hpp>

#include "assets/corner_weld.hpp"
#include "assets/mesh.hpp"
#include "assets/obj_materials.hpp"
#include "assets/obj_parse.hpp"
#include "assets/polygon_triangulation.hpp"
#include "core/error.hpp"
#include "core/input_file.hpp"
#include "core/thread_pool.hpp"

namespace facet {
namespace {

// OBJ files rarely say which edges are sharp; this angle separates the
// edges of a cube from the facets of a tessellated sphere.
constexpr float kObjCreaseDegrees = 60.0f;

// Files smaller than this are read on the calling thread: starting
// threads would cost more than it saves.
constexpr size_t kParallelBytes = size_t(4) << 20;

void append_utf8(std::string& out, uint32_t u) {
    if (u < 0x80) {
        out += static_cast<char>(u);
    } else if (u < 0x800) {
        out += static_cast<char>(0xC0 | (u >> 6));
        out += static_cast<char>(0x80 | (u & 0x3F));
    } else if (u < 0x10000) {
        out += static_cast<char>(0xE0 | (u >> 12));
        out += static_cast<char>(0x80 | ((u >> 6) & 0x3F));
        out += static_cast<char>(0x80 | (u & 0x3F));
    } else {
        out += static_cast<char>(0xF0 | (u >> 18));
        out += static_cast<char>(0x80 | ((u >> 12) & 0x3F));
        out += static_cast<char>(0x80 | ((u >> 6) & 0x3F));
        out += static_cast<char>(0x80 | (u & 0x3F));
    }
}

// UTF-16 text (after its byte order mark) as UTF-8.
std::string utf16_to_utf8(const std::vector<uint8_t>& raw, bool big_endian) {
    std::string out;
    out.reserve(raw.size() / 2);
    auto unit = [&](size_t i) -> uint32_t {
        return big_endian ? (raw[i] << 8) | raw[i + 1] : raw[i] | (raw[i + 1] << 8);
    };
    for (size_t i = 2; i + 1 < raw.size(); i += 2) {
        uint32_t u = unit(i);
        if (u >= 0xD800 && u <= 0xDBFF && i + 3 < raw.size()) {
            uint32_t low = unit(i + 2);
            if (low >= 0xDC00 && low <= 0xDFFF) {
                u = 0x10000 + ((u - 0xD800) << 10) + (low - 0xDC00);
                i += 2;
            }
        }
        append_utf8(out, u);
    }
    return out;
}

// The pool for a file of `bytes`, or none: small files are read on the
// calling thread.
void start_threads(size_t bytes, const AssetContext& context, std::optional<ThreadPool>& threads) {
    if (bytes >= kParallelBytes && context.threads != 1) threads.emplace(context.threads);
}

// The file's geometry. Some exporters write UTF-16 with a byte order mark
// (assimp's box_UTF16BE.obj), which would otherwise read as an empty
// model: that is converted first.
ObjGeometry parse_file(const MeshFile& file, const AssetContext& context,
                       std::optional<ThreadPool>& threads) {
    const std::vector<uint8_t>& bytes = file.bytes;
    const size_t size = bytes.size();
    const bool be = size >= 2 && bytes[0] == 0xFE && bytes[1] == 0xFF;
    const bool le = size >= 2 && bytes[0] == 0xFF && bytes[1] == 0xFE;
    if (be || le) {
        const std::string text = utf16_to_utf8(bytes, be);
        start_threads(text.size(), context, threads);
        return parse_obj_geometry(text, file.path, threads ? &*threads : nullptr);
    }
    const bool utf8_mark = size >= 3 && bytes[0] == 0xEF && bytes[1] == 0xBB && bytes[2] == 0xBF;
    const size_t offset = utf8_mark ? 3 : 0;
    start_threads(size - offset, context, threads);
    const std::string_view text(reinterpret_cast<const char*>(bytes.data()) + offset,
                                size - offset);
    return parse_obj_geometry(text, file.path, threads ? &*threads : nullptr);
}

// Where the material changes: from the face `first_face` on, faces have
// `material`.
struct MaterialChange {
    size_t first_face = 0;
    uint32_t material = 0;
};

// Reads the file's material statements in order: each library as its
// mtllib comes, each usemtl against the libraries read before it. When
// the geometry has an error, the statements before it are read first, so
// that a library refused earlier in the file is the error reported.
std::vector<MaterialChange> read_material_statements(const ObjGeometry& geometry,
                                                     ObjMaterials& materials, Warnings& warnings,
                                                     uint32_t no_material) {
    std::vector<MaterialChange> changes;
    for (const ObjStatement& s : geometry.statements) {
        if (geometry.error && s.line >= geometry.error_line) break;
        if (s.kind == ObjStatement::Kind::material_library) {
            materials.read_libraries(s, warnings);
        } else {
            const std::optional<uint32_t> found = materials.find(s, warnings);
            changes.push_back({s.faces_before, found ? *found : no_material});
        }
    }
    if (geometry.error) throw *geometry.error;
    return changes;
}

// The triangles of one part, as the file's corners, three per triangle.
struct PartCorners {
    std::vector<ObjCorner> corners;
    size_t room = 0;  // corners of its triangles, counted before they are made
};

// The triangles of one face, as corner numbers within the face.
void triangulate_face(const ObjGeometry& geometry, const ObjCorner* face, size_t count,
                      std::vector<ObjCorner>& out) {
    if (count == 3) {
        out.insert(out.end(), face, face + 3);
        return;
    }
    std::vector<glm::dvec3> outline(count);
    for (size_t k = 0; k < count; ++k) outline[k] = geometry.positions[face[k].position];
    for (const auto& triangle : triangulate_polygon(outline))
        for (size_t corner : triangle) out.push_back(face[corner]);
}

// Calls visit(material, corners, count, faces) in file order for runs of
// `faces` faces of `count` corners each and one material: a chunk of
// triangles alone comes in runs up to the next change of material (copied
// whole), any other chunk face by face.
template <class Visit>
void for_each_run(const ObjGeometry& geometry, const std::vector<MaterialChange>& changes,
                  uint32_t no_material, Visit&& visit) {
    size_t face = 0, next_change = 0;
    uint32_t material = no_material;
    for (const ObjFaceChunk& chunk : geometry.faces) {
        const size_t faces = chunk.corner_counts.size();
        // Every face has three corners or more: three each when they add up so.
        const bool triangles = chunk.corners.size() == 3 * faces;
        size_t offset = 0;
        for (size_t f = 0; f < faces;) {
            for (; next_change < changes.size() && changes[next_change].first_face <= face;
                 ++next_change)
                material = changes[next_change].material;
            size_t run = 1;
            if (triangles) {
                const size_t next_face = next_change < changes.size()
                                             ? changes[next_change].first_face
                                             : std::numeric_limits<size_t>::max();
                run = std::min(faces - f, next_face - face);
            }
            const uint32_t count = chunk.corner_counts[f];
            visit(material, &chunk.corners[offset], count, run);
            offset += count * run;
            f += run;
            face += run;
        }
    }
}

// The faces sorted into one part per material (std::map: parts come out in
// the order of their materials), triangulated, in file order. Each part's
// room is counted first: its vector never moves.
std::map<uint32_t, PartCorners> sort_faces(const ObjGeometry& geometry,
                                           const std::vector<MaterialChange>& changes,
                                           uint32_t no_material) {
    std::map<uint32_t, PartCorners> parts;
    // The part of the face before: materials change seldom, so the map is
    // searched only when they do.
    uint32_t last_material = no_material;
    PartCorners* part = nullptr;
    auto part_of = [&](uint32_t material) -> PartCorners& {
        if (!part || material != last_material) part = &parts[material];
        last_material = material;
        return *part;
    };
    for_each_run(geometry, changes, no_material,
                 [&](uint32_t material, const ObjCorner*, size_t count, size_t faces) {
                     part_of(material).room += faces * 3 * (count - 2);
                 });
    for (auto& [material, p] : parts) p.corners.reserve(p.room);
    for_each_run(geometry, changes, no_material,
                 [&](uint32_t material, const ObjCorner* corners, size_t count, size_t faces) {
                     std::vector<ObjCorner>& out = part_of(material).corners;
                     if (count == 3)
                         out.insert(out.end(), corners, corners + 3 * faces);
                     else
                         triangulate_face(geometry, corners, count, out);
                 });
    return parts;
}

// The part's vertices: one per distinct (position, uv, normal) index
// triple, in the order of first use (assets/corner_weld.hpp: each corner is
// compared with the first corner at its position).
WeldedCorners weld_part_corners(const std::vector<ObjCorner>& corners, size_t position_count,
                                ThreadPool* pool) {
    auto key = [&](uint32_t c) {
        return std::tuple(corners[c].position, corners[c].uv, corners[c].normal, c);
    };
    return weld_corners(
        corners.size(), position_count, [&](size_t c) { return corners[c].position; },
        [&](uint32_t a, uint32_t b) {
            return corners[a].uv == corners[b].uv && corners[a].normal == corners[b].normal;
        },
        [&](uint32_t a, uint32_t b) { return key(a) < key(b); }, pool);
}

// Ranges of vertices filled or normalised on one thread.
constexpr size_t kVertexRange = 16384;

// One part: its vertices, one per distinct (position, uv, normal) in the
// order of first use, normals computed where the file gives none, and
// checked.
MeshPart build_part(const ObjGeometry& geometry, uint32_t material,
                    std::vector<ObjCorner>&& corners, const std::string& path, ThreadPool* pool) {
    MeshPart part;
    part.material = material;
    WeldedCorners welded = weld_part_corners(corners, geometry.positions.size(), pool);
    const size_t vertices = welded.first_corner.size();
    part.positions.resize(vertices);
    part.normals.resize(vertices);
    part.uvs.resize(vertices);
    std::atomic<bool> missing_normals = false, any_uv = false;
    run_ranges(pool, vertices, kVertexRange, [&](size_t first, size_t last) {
        bool range_missing_normals = false, range_any_uv = false;
        for (size_t v = first; v < last; ++v) {
            const ObjCorner& k = corners[welded.first_corner[v]];
            part.positions[v] = geometry.positions[k.position];
            part.normals[v] = k.normal >= 0 ? geometry.normals[k.normal] : glm::vec3(0);
            // OBJ puts v = 0 at the bottom of the image; facet samples from the top.
            const glm::vec2 uv = k.uv >= 0 ? geometry.uvs[k.uv] : glm::vec2(0);
            part.uvs[v] = k.uv >= 0 ? glm::vec2(uv.x, 1.0f - uv.y) : uv;
            range_missing_normals = range_missing_normals || k.normal < 0;
            range_any_uv = range_any_uv || k.uv >= 0;
        }
        if (range_missing_normals) missing_normals = true;
        if (range_any_uv) any_uv = true;
    });
    part.indices = std::move(welded.vertex);
    // The corners are not needed any more: free them before the normals'
    // buffers grow (a fifth of the peak memory on a big file).
    corners = {};
    welded.first_corner = {};
    if (!any_uv) part.uvs.clear();
    if (missing_normals) compute_normals(part, kObjCreaseDegrees, nullptr, nullptr, pool);
    // Smoothing splits vertices: there may be more now.
    run_ranges(pool, part.normals.size(), kVertexRange, [&](size_t first, size_t last) {
        for (size_t v = first; v < last; ++v) {
            glm::vec3& n = part.normals[v];
            const float len = glm::length(n);
            n = len > 0 ? n / len : glm::vec3(0, 1, 0);
        }
    });
    validate_part(part, path);
    return part;
}

}  // namespace

Mesh load_obj(const std::string& path, const AssetContext& context) {
    return load_obj(
        MeshFile{path, read_input_file(path, "OBJ", context.paths.max_file_bytes), MeshFormat::obj},
        context);
}

Mesh load_obj(const MeshFile& file, const AssetContext& context) {
    const std::string& path = file.path;
    std::optional<ThreadPool> threads;
    ObjGeometry geometry = parse_file(file, context, threads);
    ThreadPool* const pool = threads ? &*threads : nullptr;
    Mesh mesh;
    mesh.source = path;
    mesh.loader = "facet";
    mesh.warnings = geometry.warnings;

    ObjMaterials materials(path, context);
    // One past the file's materials: faces without a material read so far.
    // Libraries come one by one, so the number is known only at the end:
    // a placeholder until then.
    constexpr uint32_t kNoMaterial = ~0u;
    const std::vector<MaterialChange> changes =
        read_material_statements(geometry, materials, mesh.warnings, kNoMaterial);
    mesh.materials = materials.build(mesh.warnings);

    std::map<uint32_t, PartCorners> parts = sort_faces(geometry, changes, kNoMaterial);
    geometry.faces.clear();
    geometry.faces.shrink_to_fit();
    if (parts.count(kNoMaterial)) {
        Material fallback;
        fallback.name = "default";
        mesh.materials.push_back(fallback);
    }
    const uint32_t default_material = static_cast<uint32_t>(mesh.materials.size() - 1);
    for (auto& [material, corners] : parts) {
        const uint32_t index = material == kNoMaterial ? default_material : material;
        mesh.parts.push_back(build_part(geometry, index, std::move(corners.corners), path, pool));
    }
    if (mesh.triangle_count() == 0)
        throw Error(ExitCode::invalid_input, path + ": the OBJ file has no faces");
    return mesh;
}

}  // namespace facet
