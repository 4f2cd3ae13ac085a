#pragma once
// Which of a model's axes points up. glTF says +Y; OBJ, FBX, Collada and
// 3DS files are read Y-up, as facet's world is. STL and PLY have no
// convention, and CAD and 3D-printing tools write them Z-up: a model that
// stands on a flat base at its lowest Z is taken as Z-up
// (docs/turntables.md, "Which way is up").
#include <string>

#include "assets/mesh.hpp"
#include "assets/mesh_format.hpp"
#include "core/enum_names.hpp"

namespace facet {

enum class UpAxis { y, z };
inline constexpr EnumName<UpAxis> kUpAxes[] = {{UpAxis::y, "y"}, {UpAxis::z, "z"}};

struct UpChoice {
    UpAxis axis = UpAxis::y;
    bool detected = false;  // decided from the geometry (STL, PLY), not by convention
    std::string reason;     // for the log: "glTF files are Y-up", "its lowest Z is a flat base..."
};

// How much of a model's footprint a flat base must cover to count as one:
// the soles of a figure or the foot of a lamp do, a few points do not.
inline constexpr double kFlatBaseShare = 0.02;

// The share of the model's footprint across `axis` (its bounds' extents on
// the other two axes multiplied) that triangles facing straight down that
// axis cover at the model's lowest extent along it: 0 for a round bottom,
// about 1 for a box.
double flat_base_share(const Mesh& mesh, UpAxis axis);

// The up axis of a mesh read from a file of this format.
UpChoice choose_up_axis(const Mesh& mesh, MeshFormat format);

}  // namespace facet
