#pragma once
// Everything a run needs that does not change from frame to frame: meshes
// and textures loaded once, materials resolved per object, and the
// concatenated vertex and index arrays the vertex stage transforms.
#include <array>
#include <memory>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "anim/frame_state.hpp"
#include "assets/mesh.hpp"
#include "cloth/cloth.hpp"
#include "scene/scene_desc.hpp"
#include "shade/environment_map.hpp"

namespace facet {

struct Draw {
    uint32_t object;  // index into SceneDesc::objects
    uint32_t first_vertex, vertex_count;
    uint32_t first_triangle, triangle_count;
    uint32_t material;  // index into World::materials
    bool has_uvs;       // the mesh part had texture coordinates
    bool has_colors;    // the mesh part had vertex colours (World::colors)
    // World::tangents holds this draw's tangent frames: its material has a
    // normal map and its part has the coordinates the map reads. A draw
    // whose material has a normal map but not this has lost it (a warning
    // said so) and is shaded with its interpolated normal.
    bool has_tangents;
};

// An object playing animations stored in its glTF file: its mesh parts
// are posed every frame (assets/gltf_pose.hpp) instead of using the rest pose.
struct AnimatedMesh {
    uint32_t object;
    std::shared_ptr<const Mesh> mesh;
    std::vector<int> animations;  // played together
    double duration;              // seconds: the longest of them
    bool loop;
    uint32_t first_draw;  // the mesh's parts are draws first_draw, first_draw + 1, ...
};

// The time in an animated mesh's animations at `seconds` of its clock:
// wrapped into the longest animation when it loops.
double animation_clock(const AnimatedMesh& mesh, double seconds);

// An object that is a simulated cloth (cloth/cloth.hpp): its one draw is
// re-posed every frame from the simulation of its model, built once.
struct ClothObject {
    uint32_t object;
    uint32_t draw;
    std::shared_ptr<const ClothModel> model;
};

struct World {
    std::vector<Material> materials;
    std::vector<uint32_t> material_object;  // per material: the scene object it belongs to
    std::vector<Draw> draws;
    std::vector<AnimatedMesh> animated_meshes;
    std::vector<ClothObject> cloths;
    // Some vertices move by themselves (glTF animation, cloth): the frame
    // renderer poses a copy of the vertex arrays every frame.
    bool deforms() const { return !animated_meshes.empty() || !cloths.empty(); }
    std::vector<Bounds> object_bounds;  // model space, per scene object
    // Per scene camera: the glTF camera of one `from:` a file (else no rig).
    std::vector<FileCamera> file_cameras;
    // The lights of objects with `lights:`, lit after the scene's own.
    std::vector<ObjectLight> object_lights;
    // Per scene object: `cast_shadows` (drawn into shadow maps), and
    // `receive_shadows` as 1 or 0, the value shading puts in its lanes.
    std::vector<uint8_t> casts_shadows;
    std::vector<float> receives_shadows;
    Warnings warnings;  // from mesh loading, for the user
    // The scene's environment, prefiltered once for every frame; null when
    // nothing draws it (no `pbr` style and no environment background).
    std::shared_ptr<const pbr::PrefilteredEnvironment> environment;

    // Model-space vertex data of all draws, concatenated.
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;
    std::vector<glm::vec2> uvs;
    // Texture coordinate set 1, one per vertex when any draw has it (zero
    // for the draws that do not), else empty.
    std::vector<glm::vec2> uvs1;
    // Vertex colours, one per vertex when any draw has them (white for the
    // draws that do not), else empty.
    std::vector<glm::vec3> colors;
    // Tangent frames (assets/tangent_frames.hpp: xyz unit along +u, w = +1
    // or -1, bitangent w (n x t) up the texture), one per vertex when some
    // draw has them (Draw::has_tangents; zero for the others), else empty,
    // so that scenes without normal maps carry and transform none.
    std::vector<glm::vec4> tangents;
    std::vector<uint32_t> vertex_draw;

    std::vector<uint32_t> indices;        // global vertex indices, three per triangle
    std::vector<uint32_t> triangle_draw;  // per triangle
    std::vector<uint8_t> cull_back;       // per triangle
    // Per triangle edge, three per triangle (edge i opposite vertex i): the
    // triangle across it, kNoNeighbor at a mesh boundary or where more than
    // two faces meet, and the cosine of the angle between the two faces'
    // normals at rest (-2 without a neighbour). The wireframe's edges are
    // picked from these each frame (render/feature_edge_stage.hpp). Filled
    // only when some style draws wireframes, else empty.
    static constexpr uint32_t kNoNeighbor = 0xffffffffu;
    std::vector<uint32_t> edge_neighbor;
    std::vector<float> edge_cosine;

    // Per vertex, model space: the direction hatching strokes follow, its
    // length the confidence in it (render/principal_directions.hpp). Filled
    // only when some style hatches, else empty.
    std::vector<glm::vec3> hatch_directions;

    size_t triangle_count() const { return triangle_draw.size(); }
    // The coordinates `slot` reads at a triangle's three corners: its set,
    // mapped by its transform (which is affine, so mapping the corners
    // maps every point between them).
    std::array<glm::vec2, 3> corner_uvs(uint32_t triangle, const TextureSlot& slot) const;
    // The texture coordinates a slot reads: its set, set 0 when the world has no set 1.
    const std::vector<glm::vec2>& uv_set(const TextureSlot& slot) const;
};

// Loads every mesh and texture the scene names, each model's parts in
// their materials under the scene's `variant:` (which must be one a model
// declares: check_variant). Errors name the scene file location of the
// object that refers to the bad file. `load_threads` may read one big mesh
// file (AssetContext::threads; 0: one per core), so that `render --threads
// N` governs loading too. A mesh in `loaded` is taken as it is instead of
// its file being read.
World build_world(const SceneDesc& scene, unsigned load_threads = 0,
                  const LoadedMeshes* loaded = nullptr);

// The variants the scene's models declare (KHR_materials_variants), each
// name once, in the order of the objects and of each file's list. The
// mesh files not in `loaded` are read into it, for build_world to take.
std::vector<std::string> scene_variants(const SceneDesc& scene, unsigned load_threads,
                                        LoadedMeshes& loaded);

}  // namespace facet
