// STL, PLY, FBX, Collada and 3DS through Debian's libassimp, into the same
// Mesh as the OBJ and glTF loaders. assimp stays in this file: nothing
// outside assets/ sees its types.
//
// What is read: triangles (polygons are triangulated, points and lines left
// out), the node hierarchy baked into world positions, normals (computed as
// for OBJ when the file has none), the first UV set, the first vertex
// colour set, and each material's diffuse colour and diffuse texture file.
// Animations in these formats are not played.
#include <assimp/DefaultIOSystem.h>
#include <assimp/material.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <assimp/Importer.hpp>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <map>
#include <memory>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_inverse.hpp>
#include <glm/mat4x4.hpp>

#include "assets/isolated_call.hpp"
#include "assets/mesh.hpp"
#include "assets/mesh_format.hpp"
#include "assets/ply_check.hpp"
#include "core/error.hpp"
#include "core/input_file.hpp"
#include "core/memory.hpp"
#include "core/plain_text.hpp"

namespace facet {
namespace {

// Normals are computed for files without them, smooth across edges whose
// faces meet at less than this (as for OBJ).
constexpr float kCreaseDegrees = 60.0f;

std::string lower(std::string text) {
    for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return text;
}

[[noreturn]] void bad(const std::string& path, const std::string& what) {
    throw Error(ExitCode::invalid_input, path + ": " + what);
}

// assimp opens files through this: only the mesh file itself, so that a
// hostile file cannot make it read another (textures go through the asset
// path policy below, as for OBJ).
// The file system assimp sees: none. It reads the bytes facet read
// (ReadFileFromMemory); a file that names others (textures are resolved by
// facet, below) opens nothing through it.
class NoFileSystem : public Assimp::DefaultIOSystem {
  public:
    bool Exists(const char*) const override { return false; }
    Assimp::IOStream* Open(const char*, const char*) override { return nullptr; }
};

glm::mat4 to_glm(const aiMatrix4x4& m) {
    // assimp's matrices are row-major; glm's columns are assimp's rows.
    return glm::mat4(m.a1, m.b1, m.c1, m.d1, m.a2, m.b2, m.c2, m.d2, m.a3, m.b3, m.c3, m.d3, m.a4,
                     m.b4, m.c4, m.d4);
}

// A texture named by a file, as the asset path policy allows. Exporters
// write the authoring machine's paths and 3DS its DOS names in capitals:
// when the name is not found as written, a file of the same name in other
// letter case in the mesh's folder is taken.
std::string texture_file(const std::string& path, const std::string& where, std::string reference,
                         const AssetContext& context) {
    std::replace(reference.begin(), reference.end(), '\\', '/');
    try {
        return resolve_asset_reference(path, where, reference, context.paths);
    } catch (const Error&) {
        const std::filesystem::path folder = std::filesystem::path(path).parent_path();
        const std::string wanted = lower(std::filesystem::path(reference).filename().string());
        std::error_code error;
        for (const auto& entry : std::filesystem::directory_iterator(
                 folder.empty() ? std::filesystem::path(".") : folder, error))
            if (lower(entry.path().filename().string()) == wanted)
                return resolve_asset_reference(path, where, entry.path().filename().string(),
                                               context.paths);
        throw;
    }
}

// Why assimp could not read a file, in words: it reports a failed
// allocation as "std::bad_alloc", and sometimes nothing.
std::string assimp_error(const Assimp::Importer& importer) {
    const std::string error = importer.GetErrorString();
    if (error.empty()) return "cannot read it (assimp gives no reason)";
    if (error == "std::bad_alloc")
        return "cannot read it: it asks for more memory than there is (damaged, or far too large)";
    return "cannot read: " + with_long_words_cut(error);
}

// A texture that cannot be used: a warning naming it, without the file's
// name twice.
void texture_warning(const std::string& path, const Error& e, Warnings& warnings) {
    std::string message = e.what();
    if (message.compare(0, path.size() + 2, path + ": ") == 0) message.erase(0, path.size() + 2);
    warnings.push_back(file_warning(path, message + "; drawn without it"));
}

// The mesh assimp's child process sends back: its parts, the fields of its
// materials that read_materials sets, its warnings, and each material's
// texture file.
void write_mesh(const Mesh& mesh, const std::vector<std::string>& textures, ByteWriter& out) {
    out.u32(static_cast<uint32_t>(mesh.parts.size()));
    for (const MeshPart& p : mesh.parts) {
        out.array(p.positions), out.array(p.normals), out.array(p.uvs), out.array(p.uvs1);
        out.array(p.tangents), out.array(p.colors), out.array(p.indices);
        out.u32(p.material);
    }
    out.u32(static_cast<uint32_t>(mesh.materials.size()));
    for (size_t i = 0; i < mesh.materials.size(); ++i) {
        const Material& m = mesh.materials[i];
        out.text(m.name);
        for (int c = 0; c < 3; ++c) out.f32(m.color[c]);
        out.f32(m.shininess);
        out.u32(m.double_sided ? 1 : 0);
        out.text(textures[i]);
    }
    out.u32(static_cast<uint32_t>(mesh.warnings.size()));
    for (const Warning& w : mesh.warnings) {
        out.text(w.where.file), out.u32(static_cast<uint32_t>(w.where.line));
        out.u32(static_cast<uint32_t>(w.where.column)), out.text(w.where.origin);
        out.text(w.key), out.text(w.message);
    }
}

Mesh read_mesh(ByteReader& in, std::vector<std::string>& textures) {
    Mesh mesh;
    mesh.loader = "assimp";
    mesh.parts.resize(in.u32());
    for (MeshPart& p : mesh.parts) {
        p.positions = in.array<glm::vec3>(), p.normals = in.array<glm::vec3>();
        p.uvs = in.array<glm::vec2>(), p.uvs1 = in.array<glm::vec2>();
        p.tangents = in.array<glm::vec4>(), p.colors = in.array<glm::vec3>();
        p.indices = in.array<uint32_t>();
        p.material = in.u32();
    }
    mesh.materials.resize(in.u32());
    for (Material& m : mesh.materials) {
        m.name = in.text();
        for (int c = 0; c < 3; ++c) m.color[c] = in.f32();
        m.shininess = in.f32();
        m.double_sided = in.u32() != 0;
        textures.push_back(in.text());
    }
    mesh.warnings.resize(in.u32());
    for (Warning& w : mesh.warnings) {
        w.where.file = in.text(), w.where.line = static_cast<int>(in.u32());
        w.where.column = static_cast<int>(in.u32()), w.where.origin = in.text();
        w.key = in.text(), w.message = in.text();
    }
    return mesh;
}

// The file's materials, each with the texture file its diffuse map names
// ("" for none) in `textures`; the textures are decoded later, outside
// assimp's process (load_assimp).
std::vector<Material> read_materials(const aiScene& scene, const MeshFile& file,
                                     const AssetContext& context, Warnings& warnings,
                                     std::vector<std::string>& textures) {
    const std::string& path = file.path;
    const bool without_materials = file.format == MeshFormat::ply || file.format == MeshFormat::stl;
    std::vector<Material> materials;
    for (unsigned i = 0; i < scene.mNumMaterials; ++i) {
        const aiMaterial& m = *scene.mMaterials[i];
        Material mat;
        aiString name;
        if (m.Get(AI_MATKEY_NAME, name) == AI_SUCCESS) mat.name = name.C_Str();
        aiColor3D color;
        if (m.Get(AI_MATKEY_COLOR_DIFFUSE, color) == AI_SUCCESS)
            mat.color = glm::clamp(glm::vec3(color.r, color.g, color.b), 0.0f, 1.0f);
        float shininess = 0;
        if (m.Get(AI_MATKEY_SHININESS, shininess) == AI_SUCCESS && shininess > 0)
            mat.shininess = std::min(shininess, 2048.0f);
        // PLY and STL have no materials: the two-sidedness assimp gives
        // them is its own default, not the file's, so they cull as OBJ does.
        int two_sided = 0;
        if (!without_materials && m.Get(AI_MATKEY_TWOSIDED, two_sided) == AI_SUCCESS)
            mat.double_sided = two_sided != 0;
        aiString file_name;
        std::string texture;
        // "*N" names a texture inside the file; those are not read. A
        // texture that cannot be found is a warning: files from these
        // formats often name one on the machine that made them.
        if (m.GetTexture(aiTextureType_DIFFUSE, 0, &file_name) == AI_SUCCESS &&
            file_name.length > 0 && file_name.C_Str()[0] != '*') {
            const std::string where = "material '" + mat.name + "': diffuse texture";
            try {
                texture = texture_file(path, where, file_name.C_Str(), context);
            } catch (const Error& e) {
                texture_warning(path, e, warnings);
            }
        }
        materials.push_back(mat);
        textures.push_back(texture);
    }
    return materials;
}

MeshPart read_part(const aiMesh& source, const glm::mat4& world, const std::string& path) {
    MeshPart part;
    const glm::mat3 normal_matrix = glm::inverseTranspose(glm::mat3(world));
    const bool mirrored = glm::determinant(glm::mat3(world)) < 0;
    // STL writers often leave the facet normal zero: then the part's
    // normals all come from its faces.
    bool unusable_normals = false;
    for (unsigned v = 0; v < source.mNumVertices; ++v) {
        const aiVector3D& p = source.mVertices[v];
        part.positions.push_back(glm::vec3(world * glm::vec4(p.x, p.y, p.z, 1)));
        if (source.mNormals) {
            const aiVector3D& n = source.mNormals[v];
            const glm::vec3 turned = normal_matrix * glm::vec3(n.x, n.y, n.z);
            const float length = glm::length(turned);
            if (length > 0 && std::isfinite(length))
                part.normals.push_back(turned / length);
            else
                unusable_normals = true;
        }
        if (source.mTextureCoords[0]) {
            const aiVector3D& uv = source.mTextureCoords[0][v];
            part.uvs.push_back({uv.x, uv.y});
        }
        if (source.mColors[0]) {
            const aiColor4D& c = source.mColors[0][v];
            part.colors.push_back(glm::clamp(glm::vec3(c.r, c.g, c.b), 0.0f, 1.0f));
        }
    }
    for (unsigned f = 0; f < source.mNumFaces; ++f) {
        const aiFace& face = source.mFaces[f];
        if (face.mNumIndices != 3) continue;  // points and lines
        uint32_t a = face.mIndices[0], b = face.mIndices[1], c = face.mIndices[2];
        if (mirrored) std::swap(b, c);
        part.indices.insert(part.indices.end(), {a, b, c});
    }
    part.material = source.mMaterialIndex;
    if (unusable_normals) part.normals.clear();
    if (part.normals.empty() && !part.indices.empty()) compute_normals(part, kCreaseDegrees);
    for (const glm::vec3& p : part.positions)
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
            bad(path, "mesh '" + std::string(source.mName.C_Str()) +
                          "': a vertex position is not finite");
    return part;
}

// What assimp's reader made, checked before its processing steps rely on
// it: every vertex position a finite number, every face with indices, all
// of them below the mesh's vertex count. (Its triangulation asserts the
// last two, stopping the process on a hostile file.)
void check_raw_meshes(const aiScene& scene, const std::string& path) {
    for (unsigned m = 0; m < scene.mNumMeshes; ++m) {
        const aiMesh& mesh = *scene.mMeshes[m];
        const std::string what = "mesh '" + std::string(mesh.mName.C_Str()) + "': ";
        for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
            const aiVector3D& p = mesh.mVertices[v];
            if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
                bad(path, what + "vertex " + std::to_string(v) + "'s position is not finite");
        }
        for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
            const aiFace& face = mesh.mFaces[f];
            if (face.mNumIndices == 0 || !face.mIndices)
                bad(path, what + "face " + std::to_string(f) + " has no vertices");
            for (unsigned k = 0; k < face.mNumIndices; ++k)
                if (face.mIndices[k] >= mesh.mNumVertices)
                    bad(path, what + "face " + std::to_string(f) + " refers to vertex " +
                                  std::to_string(face.mIndices[k]) + " of " +
                                  std::to_string(mesh.mNumVertices));
        }
    }
}

// The mesh as assimp reads it, without decoding its textures: their files
// go into `textures`, one per material ("" for none).
Mesh assimp_mesh(const MeshFile& file, const AssetContext& context,
                 std::vector<std::string>& textures) {
    const std::string& path = file.path;
    // A PLY file's structure is checked before assimp reads it
    // (assets/ply_check.hpp).
    if (file.format == MeshFormat::ply) check_ply(file.bytes, path);
    Assimp::Importer importer;
    // assimp reads the bytes facet read, and may open no other file.
    importer.SetIOHandler(new NoFileSystem);  // the importer owns it
    // Points and lines are split off and left out; polygons become
    // triangles; degenerate triangles go.
    importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE,
                                aiPrimitiveType_POINT | aiPrimitiveType_LINE);
    // Read as the file has it, checked, then processed: joining vertices
    // would merge a NaN position into another vertex without a word. The
    // reader is the one the bytes call for, whatever the file's name.
    const aiScene* scene =
        importer.ReadFileFromMemory(file.bytes.data(), file.bytes.size(), 0,
                                    std::string(mesh_format_extension(file.format)).c_str());
    if (!scene || !scene->mRootNode || (scene->mFlags & AI_SCENE_FLAGS_INCOMPLETE))
        bad(path, assimp_error(importer));
    check_raw_meshes(*scene, path);
    scene =
        importer.ApplyPostProcessing(aiProcess_Triangulate | aiProcess_SortByPType |
                                     aiProcess_FindDegenerates | aiProcess_JoinIdenticalVertices);
    if (!scene || !scene->mRootNode) bad(path, assimp_error(importer));
    Mesh mesh;
    mesh.source = path;
    mesh.loader = "assimp";
    mesh.materials = read_materials(*scene, file, context, mesh.warnings, textures);
    const uint32_t default_material = static_cast<uint32_t>(mesh.materials.size());
    Material fallback;
    fallback.name = "default";
    mesh.materials.push_back(fallback);
    textures.push_back("");

    // Every instance of a mesh is baked, so a small file can ask for far
    // more than its size: the vertices are counted before they are read.
    const uint64_t memory = memory_available();
    uint64_t planned = 0;
    struct Instance {
        const aiNode* node;
        glm::mat4 world;
    };
    std::vector<Instance> stack = {{scene->mRootNode, to_glm(scene->mRootNode->mTransformation)}};
    size_t visited = 0;
    while (!stack.empty()) {
        const Instance at = stack.back();
        stack.pop_back();
        if (++visited > 1000000) bad(path, "the node hierarchy has more than a million nodes");
        for (unsigned i = 0; i < at.node->mNumMeshes; ++i) {
            const unsigned index = at.node->mMeshes[i];
            if (index >= scene->mNumMeshes) bad(path, "a node refers to a missing mesh");
            const aiMesh& source = *scene->mMeshes[index];
            planned += planned_part_bytes(source.mNumVertices, uint64_t(3) * source.mNumFaces);
            check_memory("loading " + path, {{"mesh instances", planned}}, memory);
            MeshPart part = read_part(source, at.world, path);
            if (part.indices.empty()) continue;
            if (part.material >= default_material) part.material = default_material;
            validate_part(part, path);
            mesh.parts.push_back(std::move(part));
        }
        for (unsigned c = 0; c < at.node->mNumChildren; ++c)
            stack.push_back(
                {at.node->mChildren[c], at.world * to_glm(at.node->mChildren[c]->mTransformation)});
    }
    if (mesh.triangle_count() == 0) bad(path, "the file has no triangles to render");
    return mesh;
}

}  // namespace

Mesh load_assimp(const std::string& path, const AssetContext& context) {
    return load_assimp(read_mesh_file(path, context), context);
}

Mesh load_assimp(const MeshFile& file, const AssetContext& context) {
    // assimp's readers are not safe against hostile files (fuzzed, they
    // crash, loop and allocate gigabytes): they run in a child process,
    // which sends back the mesh without its textures (isolated_call.hpp).
    std::vector<std::string> textures;
    const std::vector<uint8_t> answer = run_isolated(file.path, [&] {
        ByteWriter out;
        std::vector<std::string> paths;
        write_mesh(assimp_mesh(file, context, paths), paths, out);
        return out.take();
    });
    ByteReader reader(answer);
    Mesh mesh = read_mesh(reader, textures);
    mesh.source = file.path;
    // The textures, decoded here under the run's texture budget.
    std::map<std::string, std::shared_ptr<const Texture>> decoded;
    for (size_t i = 0; i < textures.size(); ++i) {
        if (textures[i].empty()) continue;
        Material& mat = mesh.materials[i];
        try {
            auto& slot = decoded[textures[i]];
            if (!slot)
                slot = std::make_shared<Texture>(load_texture(textures[i], context.textures));
            mat.base_color_map.texture = slot;
            if (mat.color == glm::vec3(0)) mat.color = glm::vec3(1);
        } catch (const Error& e) {
            texture_warning(file.path, e, mesh.warnings);
        }
    }
    return mesh;
}

}  // namespace facet
