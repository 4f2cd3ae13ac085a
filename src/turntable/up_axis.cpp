#include "turntable/up_axis.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <glm/geometric.hpp>

namespace facet {
namespace {

// A face counts as facing down when its normal is within this cosine of
// straight down (about 8 degrees): exported bases are flat, but
// tessellated ones can lean a little.
constexpr double kFacingDown = 0.99;
// ...and lies at the lowest extent within this share of the model's size.
constexpr double kBaseTolerance = 0.002;

int axis_index(UpAxis axis) {
    return axis == UpAxis::y ? 1 : 2;
}

std::string percent(double share) {
    char text[32];
    std::snprintf(text, sizeof text, "%.0f%%", 100 * share);
    return text;
}

std::string format_convention(MeshFormat format) {
    switch (format) {
        case MeshFormat::gltf:
        case MeshFormat::glb:
            return "glTF files are Y-up";
        case MeshFormat::obj:
            return "OBJ files are read Y-up, as most tools write them";
        default:
            return mesh_format_name(format) + " files are read Y-up, as facet's world is";
    }
}

}  // namespace

double flat_base_share(const Mesh& mesh, UpAxis axis) {
    const Bounds bounds = mesh.bounds();
    if (bounds.empty()) return 0;
    const int up = axis_index(axis);
    const glm::dvec3 extent = glm::dvec3(bounds.max) - glm::dvec3(bounds.min);
    const double footprint = extent[0] * extent[up == 1 ? 2 : 1];
    const double size = std::max({extent.x, extent.y, extent.z});
    if (!(footprint > 0)) return 0;
    const double lowest = bounds.min[up], tolerance = kBaseTolerance * size;
    double area = 0;
    for (const MeshPart& part : mesh.parts)
        for (size_t t = 0; t < part.triangle_count(); ++t) {
            const glm::dvec3 a = part.positions[part.indices[3 * t]];
            const glm::dvec3 b = part.positions[part.indices[3 * t + 1]];
            const glm::dvec3 c = part.positions[part.indices[3 * t + 2]];
            if (std::max({a[up], b[up], c[up]}) > lowest + tolerance) continue;
            const glm::dvec3 cross = glm::cross(b - a, c - a);
            const double length = glm::length(cross);
            // Either winding: an inside-out file's base is still its base.
            if (length > 0 && std::fabs(cross[up]) / length >= kFacingDown) area += length / 2;
        }
    return area / footprint;
}

UpChoice choose_up_axis(const Mesh& mesh, MeshFormat format) {
    if (format != MeshFormat::stl && format != MeshFormat::ply)
        return {UpAxis::y, false, format_convention(format)};
    const double base_z = flat_base_share(mesh, UpAxis::z);
    const double base_y = flat_base_share(mesh, UpAxis::y);
    const Bounds b = mesh.bounds();
    const double height_z = b.max.z - b.min.z, height_y = b.max.y - b.min.y;
    const std::string format_name = mesh_format_name(format);
    if (base_z < kFlatBaseShare && base_y < kFlatBaseShare)
        return {UpAxis::y, true,
                format_name +
                    " has no up axis and the model has no flat base at its lowest Y or "
                    "Z: taken as Y-up, facet's own"};
    if (base_y < kFlatBaseShare)
        return {UpAxis::z, true,
                "its lowest Z is a flat base (" + percent(base_z) +
                    " of its footprint) and its lowest Y is not: taken as Z-up"};
    if (base_z < kFlatBaseShare)
        return {UpAxis::y, true,
                "its lowest Y is a flat base (" + percent(base_y) +
                    " of its footprint) and its lowest Z is not: taken as Y-up"};
    // Flat both ways (a box, a plinth): it stands along its longer side.
    if (height_z > height_y)
        return {UpAxis::z, true,
                "it has flat bases at its lowest Y and Z and is taller along Z: taken as Z-up"};
    return {UpAxis::y, true,
            "it has flat bases at its lowest Y and Z and is not taller along Z: taken as Y-up"};
}

}  // namespace facet
