#pragma once
// The materials of an OBJ file: its MTL libraries (read by tinyobjloader's
// MTL reader), found through the asset path policy, and turned into
// facet's materials with their textures (assets/obj_loader.cpp).
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "assets/mesh.hpp"
#include "assets/obj_parse.hpp"

namespace facet {

class ObjMaterials {
  public:
    ObjMaterials(const std::string& obj_path, const AssetContext& context);
    ~ObjMaterials();
    ObjMaterials(const ObjMaterials&) = delete;
    ObjMaterials& operator=(const ObjMaterials&) = delete;

    // mtllib: reads the first library of the statement's list that can be
    // read and is not read yet, as other OBJ readers do. A missing library
    // is a warning; one the asset path policy refuses is an error.
    void read_libraries(const ObjStatement& mtllib, Warnings& warnings);

    // usemtl: the index of the material of that name (words joined by
    // single spaces), or nullopt with a warning, once per name.
    std::optional<uint32_t> find(const ObjStatement& usemtl, Warnings& warnings);

    size_t size() const;

    // The materials read, in order, as facet's, textures loaded; with a
    // warning per material for what it gives that facet does not draw.
    std::vector<Material> build(Warnings& warnings) const;

  private:
    struct Libraries;
    std::unique_ptr<Libraries> libraries_;
};

}  // namespace facet
