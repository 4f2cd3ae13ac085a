#pragma once
// A scene's cloth object turned into what the simulation (cloth/cloth.hpp)
// takes: parameters in the object's local space at the scene's frame rate,
// and the keyed wind of each simulation frame.
#include <memory>

#include "cloth/cloth.hpp"
#include "scene/scene_desc.hpp"

namespace facet {

// The simulation parameters of a scene's cloth, in the object's local space
// (gravity turned by the inverse of the object's rotation at `first_frame`),
// with the keyable values (mass, stiffness, friction, damping) at simulation
// frame `frame`.
ClothParams cloth_params(const ObjectDesc& object, double fps, int first_frame, int frame = 0);

// Whether any of the cloth's mass, stiffness, friction or damping is keyed.
bool cloth_values_keyed(const ObjectDesc& object);

// The keyed wind of a cloth object at simulation frame `frame` (scene frame
// first_frame + frame), turned into the object's local space.
WindState cloth_wind(const ObjectDesc& object, int frame, int first_frame, double fps);

// The cloth model of a cloth object, built once per run with enough
// substeps for every frame's keyed values, after checking those values
// (stability, stretch under weight) and the wind of every frame of the
// scene against it. Throws facet::Error (invalid_input) naming the frame of
// a bad key.
std::shared_ptr<const ClothModel> build_scene_cloth(const ObjectDesc& object,
                                                    const OutputDesc& output);

// The simulation of a cloth object with its keyed wind and, when any are
// keyed, its keyed values; `object` must outlive it.
std::unique_ptr<ClothSimulation> scene_cloth_simulation(const ObjectDesc& object,
                                                        const OutputDesc& output,
                                                        std::shared_ptr<const ClothModel> model);

}  // namespace facet
