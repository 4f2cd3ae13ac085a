#include "render/world.hpp"

#include <map>

#include "assets/primitives.hpp"
#include "core/error.hpp"

namespace facet {
namespace {

Material resolve_material(const Material& base, const MaterialDesc& desc,
                          std::map<std::string, std::shared_ptr<const Texture>>& textures) {
    Material m = base;
    // Animated values start at their first key; frames update them.
    if (desc.color) m.color = desc.color->value;
    if (desc.ambient) m.ambient = desc.ambient->value;
    if (desc.diffuse) m.diffuse = desc.diffuse->value;
    if (desc.specular) m.specular = desc.specular->value;
    if (desc.shininess) m.shininess = desc.shininess->value;
    if (desc.double_sided) m.double_sided = *desc.double_sided;
    if (desc.uv_scale) m.uv_scale = *desc.uv_scale;
    if (desc.texture) {
        auto& slot = textures[*desc.texture];
        if (!slot) {
            try {
                slot = std::make_shared<Texture>(load_texture(*desc.texture));
            } catch (const Error& e) {
                fail_input(desc.texture_at, "", e.what());
            }
        }
        m.texture = slot;
    }
    if (desc.wrap && m.texture) {
        auto copy = std::make_shared<Texture>(*m.texture);
        copy->wrap = *desc.wrap == TextureWrap::clamp ? Wrap::clamp : Wrap::repeat;
        m.texture = copy;
    }
    return m;
}

}  // namespace

World build_world(const SceneDesc& scene) {
    World world;
    std::map<std::string, std::shared_ptr<const Mesh>> meshes;
    std::map<std::string, std::shared_ptr<const Texture>> textures;
    for (uint32_t o = 0; o < scene.objects.size(); ++o) {
        const ObjectDesc& obj = scene.objects[o];
        std::shared_ptr<const Mesh> mesh;
        if (!obj.mesh.empty()) {
            auto& slot = meshes[obj.mesh];
            if (!slot) {
                try {
                    slot = std::make_shared<Mesh>(load_mesh(obj.mesh));
                } catch (const Error& e) {
                    fail_input(obj.mesh_at, "objects." + std::to_string(o) + ".mesh", e.what());
                }
                for (const auto& w : slot->warnings) world.warnings.push_back(obj.mesh + ": " + w);
            }
            mesh = slot;
        } else {
            const PrimitiveDesc& p = *obj.primitive;
            PrimitiveSpec spec;
            spec.type = p.type;
            spec.size = p.size;
            spec.box_size = p.box_size;
            spec.radius = p.radius;
            spec.height = p.height;
            spec.segments = p.segments;
            spec.rings = p.rings;
            spec.sides = p.sides;
            spec.tube = p.tube;
            spec.subdivisions = p.subdivisions;
            spec.smooth = p.smooth;
            try {
                mesh = std::make_shared<Mesh>(make_primitive(spec));
            } catch (const Error& e) {
                fail_input(p.where, "objects." + std::to_string(o) + ".primitive", e.what());
            }
        }
        world.object_bounds.push_back(mesh->bounds());
        if (!obj.visible) continue;

        const uint32_t material_base = static_cast<uint32_t>(world.materials.size());
        for (const Material& m : mesh->materials) {
            world.materials.push_back(resolve_material(m, obj.material, textures));
            world.material_object.push_back(o);
        }

        for (const MeshPart& part : mesh->parts) {
            Draw d;
            d.object = o;
            d.first_vertex = static_cast<uint32_t>(world.positions.size());
            d.vertex_count = static_cast<uint32_t>(part.positions.size());
            d.first_triangle = static_cast<uint32_t>(world.triangle_draw.size());
            d.triangle_count = static_cast<uint32_t>(part.triangle_count());
            d.material = material_base + part.material;
            const uint32_t draw_index = static_cast<uint32_t>(world.draws.size());
            world.positions.insert(world.positions.end(), part.positions.begin(),
                                   part.positions.end());
            world.normals.insert(world.normals.end(), part.normals.begin(), part.normals.end());
            if (part.uvs.empty())
                world.uvs.resize(world.uvs.size() + part.positions.size(), glm::vec2(0));
            else
                world.uvs.insert(world.uvs.end(), part.uvs.begin(), part.uvs.end());
            world.vertex_draw.resize(world.positions.size(), draw_index);
            for (uint32_t i : part.indices) world.indices.push_back(d.first_vertex + i);
            world.triangle_draw.resize(world.triangle_draw.size() + d.triangle_count, draw_index);
            world.cull_back.resize(world.cull_back.size() + d.triangle_count,
                                   world.materials[d.material].double_sided ? 0 : 1);
            world.draws.push_back(d);
        }
    }
    if (world.positions.size() >= 0xffffffffu)
        throw Error(ExitCode::invalid_input, "the scene has more than 4 billion vertices");
    return world;
}

}  // namespace facet
