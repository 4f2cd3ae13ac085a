#pragma once
// A mass-spring cloth on a rectangular grid: the flag of seed 004 (docs/references.md,
// §1.3 and §2.1), as plain data and pure functions plus a small caching driver.
// docs/cloth.md describes the model, the forces, the integration and the
// parameters' safe ranges.
//
// Space: the cloth's local space. At rest the cloth is flat in the XY plane,
// its top-left corner (column 0, row 0) at the origin, columns along +X and
// rows along -Y, front face towards +Z. Gravity and wind are given in this
// space too; the caller rotates world vectors into it. Pinned vertices stay at
// their rest positions, so the object's transform is the pole they hang on.
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "assets/mesh.hpp"
#include "cloth/cloth_params.hpp"

namespace facet {

// Checks that the parameters are usable; otherwise throws facet::Error
// (invalid_input) with one message that names the parameter, its value and
// its safe range (the first problem found).
void check_cloth_params(const ClothParams& params, const ClothPins& pins = {});
void check_wind(const WindState& wind);
// Also checks the wind against a cloth (valid params): the strongest gust,
// strength x (1 + gust), must not move a vertex more than a tenth of a cell
// in one substep (max_wind_speed), or the strain limit cannot keep up. With
// the defaults that is several hundred m/s, so only extreme wind_drag,
// light cloths or few substeps meet it.
void check_wind(const WindState& wind, const ClothParams& params);
double max_wind_speed(const ClothParams& params);

// Substeps per frame the simulation uses: params.substeps if set, otherwise
// the fewest that satisfy the stability bound (docs/cloth.md). Valid params only.
int cloth_substeps(const ClothParams& params);

// Stability number of the explicit step, (h^2 lambda + 2 h gamma) / 4 with
// h = frame_seconds / substeps: lambda bounds the squared angular frequency of
// the stiffest mode of the grid's springs and gamma its damping rate. The
// step is stable below 1; facet requires <= kClothStabilityLimit.
double cloth_stability_number(const ClothParams& params, int substeps);
constexpr double kClothStabilityLimit = 0.8;

// One spring of the grid. The strain limit walks the list; the forces use
// the same springs grouped by kind (cloth.cpp, spring_families).
struct ClothSpring {
    uint32_t a, b;
    double rest;         // rest length, m
    double k;            // Hooke constant, N/m
    double c;            // damping coefficient, N s/m
    bool limit_stretch;  // structural and shear springs (Provot's constraint)
};

// Everything about a cloth that does not change while it moves.
struct ClothModel {
    ClothParams params;
    int substeps = 0;
    double step_seconds = 0;                 // h = frame_seconds / substeps
    double particle_mass = 0;                // kg, the same for every vertex (seed 1.3)
    std::vector<uint8_t> pinned;             // per vertex, 1 when pinned
    std::vector<glm::dvec3> rest_positions;  // per vertex
    std::vector<double> column_x;            // rest x of each column
    std::vector<ClothSpring> springs;        // structural, then shear, then bend
    // Per vertex, its nearest pin at rest and their rest distance (long
    // range attachments); kNoAttachment for pinned vertices.
    std::vector<uint32_t> attachment;
    std::vector<double> attachment_rest;
    // Three per triangle, two triangles per cell cell by cell along each
    // row, diagonals alternating like a checkerboard; front face +Z.
    std::vector<uint32_t> indices;
    MeshPart rest_part;      // rest positions, +Z normals, UVs, indices
    int preroll_frames = 0;  // whole frames simulated before frame 0
};

// The moving part. `step` counts substeps from frame 0 (negative in preroll);
// the gust noise is a function of step * h, so restoring a state restores
// the future exactly.
struct ClothState {
    int frame = 0;
    int64_t step = 0;
    std::vector<glm::dvec3> positions;
    std::vector<glm::dvec3> velocities;
};

// What the renderer needs at one frame, in local space.
struct ClothFrame {
    std::vector<glm::vec3> positions;
    // Unit length, towards +Z at rest: from central differences across the
    // grid, so they do not depend on the triangles' alternating diagonals.
    std::vector<glm::vec3> normals;
};

// Throws facet::Error (invalid_input) with check_cloth_params' message.
ClothModel build_cloth_model(const ClothParams& params, const ClothPins& pins);
// The state the simulation starts from, preroll_frames before frame 0: the
// rest grid, still, with the free vertices twisted out of the plane by at
// most 1e-4 x height (so a cloth hanging in its own plane can buckle).
ClothState start_state(const ClothModel& model);
// Advances one frame (model.substeps steps), with the wind interpolated from
// `from` (this frame) to `to` (the next). `keyed`, when given, holds this
// frame's keyed values: its mass, stiffness, friction and damping replace
// the model's for the frame (its other fields are not read). Throws if a
// wind or a keyed value is invalid, or unstable at model.substeps.
void advance_cloth_frame(const ClothModel& model, ClothState& state, const WindState& from,
                         const WindState& to, const ClothParams* keyed = nullptr);
// `model` with the keyed values (mass, stiffness, friction, damping) of `keyed`.
ClothParams with_keyed_values(const ClothParams& model, const ClothParams& keyed);
ClothFrame cloth_frame(const ClothModel& model, const ClothState& state);
double kinetic_energy(const ClothModel& model, const ClothState& state);
// The wind vector the cells in `column` (0 .. columns - 2) feel at `step`,
// gusts included (for tests and docs).
glm::dvec3 wind_at_step(const ClothModel& model, const WindState& from, const WindState& to,
                        int64_t step, int column);

// Runs a cloth from frame 0 in fixed steps and answers any frame, the same
// bits whichever frames are asked for and in which order: it keeps a
// checkpoint every kCheckpointInterval frames and replays from the nearest
// one. Frames asked for in increasing order cost one frame of simulation
// each. Not thread-safe (it caches); the simulation is single-threaded, so
// its results do not depend on the renderer's thread count.
class ClothSimulation {
  public:
    // `wind_at(frame)` must be a pure function of the frame (frame >= 0);
    // without one the wind is WindState{}.
    using WindAt = std::function<WindState(int frame)>;
    // `params_at(frame)`, when given, the keyed values at a frame (see
    // advance_cloth_frame); a pure function of the frame too.
    using ParamsAt = std::function<ClothParams(int frame)>;
    static constexpr int kCheckpointInterval = 32;

    // The model is built once (build_cloth_model) and shared with whoever
    // else needs it. Throws facet::Error (invalid_input) for an invalid wind.
    ClothSimulation(std::shared_ptr<const ClothModel> model, WindAt wind_at,
                    ParamsAt params_at = {});

    const ClothModel& model() const { return *model_; }
    // Indices, UVs and the rest pose, the same at every frame.
    const MeshPart& rest_part() const { return model_->rest_part; }
    // The full state at `frame` (>= 0).
    const ClothState& simulate_to(int frame);
    ClothFrame state_at(int frame) { return cloth_frame(*model_, simulate_to(frame)); }

  private:
    WindState wind(int frame) const;
    std::optional<ClothParams> keyed(int frame) const;

    std::shared_ptr<const ClothModel> model_;
    WindAt wind_at_;
    ParamsAt params_at_;
    ClothState current_;
    std::vector<ClothState> checkpoints_;  // [i] is frame i * kCheckpointInterval
};

}  // namespace facet
