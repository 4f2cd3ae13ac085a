#pragma once
// The plain records that describe a cloth (cloth/cloth.hpp simulates it):
// its physical parameters, its pins and the wind at one frame. The scene
// description embeds them (scene/scene_desc.hpp, ClothDesc), so they hold
// nothing but values.
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

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

}  // namespace facet
