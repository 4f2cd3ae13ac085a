#pragma once
// A mass-spring cloth on a rectangular grid: the flag of seed 004 (sections
// 1.3 and 2.1), as plain data and pure functions plus a small caching driver.
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
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "assets/mesh.hpp"

namespace facet {

// Physical parameters. The defaults are a cotton flag of 1.5 m x 1 m on a
// 6 m pole (seed 004: 2:3, the flag's height 1/6 of the pole's) in a light
// breeze; see the comment on each value.
struct ClothParams {
    // Vertices along the width (local +X) and the height (local -Y), each in
    // [2, kMaxClothGridSide]. 48 x 32 gives square cells of about 3 cm,
    // enough for folds a few centimetres across at 1080p.
    int columns = 48;
    int rows = 32;
    float width = 1.5f;   // m, finite and > 0
    float height = 1.0f;  // m, finite and > 0
    // Total mass in kg, spread evenly over the vertices as in the seed (1.3).
    // Flag cotton (bunting) weighs about 0.2 kg/m^2. Finite and > 0, and
    // light enough that its weight alone, over `stiffness` times the shorter
    // side, stays within max_stretch (heavier, the strain limit alone would
    // hold the cloth up, and it cannot).
    float mass = 0.3f;
    // Stretch stiffness of the sheet in N/m: the Hooke constant k of every
    // structural spring of a square cell (rectangular cells scale it by the
    // ratio of the cell's sides so the sheet stays isotropic). Woven cotton
    // is far stiffer, but the strain limit below keeps the cloth from
    // stretching more than max_stretch, and a softer k needs fewer substeps
    // (their number grows as sqrt(k)): at 100 N/m the flag's own weight and
    // a 5 m/s wind stretch it by a few per cent. > 0; the upper bound
    // depends on substeps, mass and grid (validate_cloth_params says it).
    float stiffness = 100;
    // Shear (cell diagonals) and bend (two vertices apart) springs as
    // fractions of `stiffness`, each in [0, 1]. Cotton shears easily, hence
    // the low shear. Real cotton bends more easily still, but bend springs
    // much weaker than this let the grid crumple at the scale of one cell
    // (beads along the edges): folds finer than the grid cannot be drawn.
    float shear_stiffness = 0.2f;
    float bend_stiffness = 0.5f;
    // Strain limit (Provot 1995): structural and shear springs are never
    // longer than (1 + max_stretch) x their rest length after a step. [0.01, 1].
    float max_stretch = 0.1f;
    // Air friction in 1/s: F = -friction * m * v on every vertex (the seed's
    // -mu*F read as opposing the motion, see docs/cloth.md). [0, kMaxFriction].
    float friction = 0.1f;
    // Spring damping as a fraction of critical damping of one spring and its
    // vertex: F = -c ((v_a - v_b).u) u, c = 2 damping sqrt(k m). [0, 1].
    // It only has to calm jitter at the scale of a cell (the air damps the
    // large motions), and more of it needs more substeps.
    float damping = 0.05f;
    // Wind force coefficient in kg/(m^2 s): a face (grid cell) of area A
    // moving at v feels F = wind_drag A n (n.(w - v)). 1.0 gives 5 Pa on a
    // face square to a 5 m/s wind; the default flag flies 20 to 30 degrees
    // below the wind. [0, kMaxWindDrag].
    float wind_drag = 1.0f;
    // Tangential wind coefficient in kg/(m^2 s), not in the seed: the face
    // also feels wind_tangential_drag A (w - n (n.w)), the skin friction and
    // the form drag of ripples finer than the grid. It is what holds a real
    // flag out in the wind: the normal force alone cannot hold up a flag
    // that lies along the wind, so it would sag in its own plane. 0 gives
    // the seed's force alone. [0, kMaxWindDrag].
    float wind_tangential_drag = 0.5f;
    glm::vec3 gravity = {0, -9.81f, 0};  // m/s^2, finite, length <= 1000
    // Integration steps per frame, or 0 to choose the fewest that are stable
    // (cloth_substeps). Explicit values must be stable too; at most kMaxClothSubsteps.
    int substeps = 0;
    double frame_seconds = 1.0 / 24;  // the scene's frame duration, (0, 1]
    // Simulated time before frame 0, with frame 0's wind, so the first
    // rendered frame shows a flag already flying. [0, 60] s.
    double preroll_seconds = 2.0;
};

constexpr int kMaxClothGridSide = 256;
constexpr int kMaxClothSubsteps = 1000;
constexpr float kMaxFriction = 100;
constexpr float kMaxWindDrag = 100;
constexpr float kMaxWindStrength = 100;  // m/s
constexpr uint32_t kNoAttachment = 0xffffffffU;

// Which vertices hang on the pole. The union of the three is pinned; at
// least one vertex must be.
struct ClothPins {
    bool left_edge = true;  // column 0, every row (a flag on its pole)
    bool top_edge = false;  // row 0, every column (a curtain, a banner)
    // Flat vertex indices row * columns + column.
    std::vector<int> vertices;
};

// The wind at one frame, in the cloth's local space. The caller keyframes it
// (the seed's key frames); between frames it is interpolated linearly over
// the substeps, and the frames between key frames are simulated.
struct WindState {
    glm::vec3 direction = {1, 0, 0};  // any non-zero length; normalised here
    float strength = 5;               // m/s, [0, kMaxWindStrength]
    // Gusts in [0, 1]: seeded noise scales the strength by up to +-gust and
    // turns the direction by up to about gust radians sideways and gust / 2
    // up and down, varying over 0.3 to 3 s and travelling downwind at the
    // wind's speed, so the flag keeps moving in a steady wind.
    float gust = 0.3f;
    uint32_t seed = 1;
};

// An empty string when the parameters are usable, otherwise one message that
// names the parameter, its value and its safe range (the first problem found).
std::string validate_cloth_params(const ClothParams& params, const ClothPins& pins = {});
std::string validate_wind(const WindState& wind);
// Also checks the wind against a cloth (valid params): the strongest gust,
// strength x (1 + gust), must not move a vertex more than a tenth of a cell
// in one substep (max_wind_speed), or the strain limit cannot keep up. With
// the defaults that is several hundred m/s, so only extreme wind_drag,
// light cloths or few substeps meet it.
std::string validate_wind(const WindState& wind, const ClothParams& params);
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

// Throws facet::Error (invalid_input) with validate_cloth_params' message.
ClothModel build_cloth_model(const ClothParams& params, const ClothPins& pins);
// The state the simulation starts from, preroll_frames before frame 0: the
// rest grid, still, with the free vertices twisted out of the plane by at
// most 1e-4 x height (so a cloth hanging in its own plane can buckle).
ClothState start_state(const ClothModel& model);
// Advances one frame (model.substeps steps), with the wind interpolated from
// `from` (this frame) to `to` (the next). Throws if a wind is invalid.
void advance_cloth_frame(const ClothModel& model, ClothState& state, const WindState& from,
                         const WindState& to);
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
    static constexpr int kCheckpointInterval = 32;

    // Throws facet::Error (invalid_input) for invalid params or wind.
    ClothSimulation(const ClothParams& params, const ClothPins& pins, WindAt wind_at);

    const ClothModel& model() const { return model_; }
    // Indices, UVs and the rest pose, the same at every frame.
    const MeshPart& rest_part() const { return model_.rest_part; }
    // The full state at `frame` (>= 0).
    const ClothState& simulate_to(int frame);
    ClothFrame state_at(int frame) { return cloth_frame(model_, simulate_to(frame)); }

  private:
    WindState wind(int frame) const;

    ClothModel model_;
    WindAt wind_at_;
    ClothState current_;
    std::vector<ClothState> checkpoints_;  // [i] is frame i * kCheckpointInterval
};

}  // namespace facet
