// The mass-spring cloth (cloth.hpp). Forces follow seed 004 §1.3 (docs/references.md)
// (system 1.11) and the algorithm of section 2.1; the integration is
// semi-implicit Euler in fixed substeps with Provot's strain limit
// ("Deformation constraints in a mass-spring model to describe rigid cloth
// behavior", Graphics Interface 1995). Everything runs in double precision
// on one thread in a fixed order, so a state is a pure function of the
// parameters, the wind and the step count. The parameter checks and the
// stability bound are in cloth_limits.cpp.
#include "cloth/cloth.hpp"
#include "core/integer_hash.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>

#include "cloth/cloth_grid.hpp"
#include "core/error.hpp"

namespace facet {
namespace {

using namespace cloth_detail;

// The strain limit's Gauss-Seidel passes per substep stop once no spring
// was more than kStrainTolerance (relative) over its limit at the start of
// a pass, or after kMaxStrainPasses.
constexpr int kMaxStrainPasses = 16;
constexpr double kStrainTolerance = 0.005;
// The largest turn of the wind by gusts, in radians per unit of gust,
// sideways and up or down. A flag answers sideways turns by flapping.
constexpr double kSideTurn = 1.0, kLiftTurn = 0.5;
// The start state's out-of-plane twist, relative to the cloth's height.
constexpr double kStartTwist = 1e-4;

// --- Deterministic gust noise ------------------------------------------------
// Integer hashing only (no global RNG, no trigonometry): the same bits on
// every platform (core/integer_hash.hpp).

// Smooth value noise in [-1, 1] over t (in periods): random values at the
// integers, blended with Perlin's quintic fade (C2, so forces do not jerk).
double value_noise(uint32_t seed, uint32_t channel, double t) {
    const double cell = std::floor(t);
    const double f = t - cell;
    const auto k = static_cast<uint32_t>(static_cast<int64_t>(cell));  // wraps after 2^32 periods
    auto value = [&](uint32_t i) {
        return static_cast<double>(hash32(seed, channel, i) >> 8) * (2.0 / 16777216.0) - 1.0;
    };
    const double a = value(k), b = value(k + 1);
    const double s = f * f * f * (f * (f * 6 - 15) + 10);
    return a + (b - a) * s;
}

// Three octaves (periods 2.7, 0.9 and 0.31 s; weights summing to 1) so the
// gusts have both slow swells and quick flutter. Result in [-1, 1].
double gust_noise(uint32_t seed, uint32_t channel, double seconds) {
    return 0.5 * value_noise(seed, 3 * channel + 0, seconds / 2.7) +
           0.3 * value_noise(seed, 3 * channel + 1, seconds / 0.9) +
           0.2 * value_noise(seed, 3 * channel + 2, seconds / 0.31);
}

// --- Forces --------------------------------------------------------------------

glm::dvec3 unit_or(const glm::dvec3& v, const glm::dvec3& fallback) {
    const double l = glm::length(v);
    return l > 0 ? v / l : fallback;
}

glm::dvec3 wind_vector(const WindState& w) {
    return glm::normalize(glm::dvec3(w.direction)) * static_cast<double>(w.strength);
}

void column_winds(const ClothModel& model, const WindState& from, const WindState& to, int64_t step,
                  std::vector<glm::dvec3>& out) {
    const int n = model.substeps;
    // Frames start at multiples of n steps; substep s of a frame blends its
    // two key frames' winds by s / n.
    const int64_t s = ((step % n) + n) % n;
    const double alpha = static_cast<double>(s) / n;
    const glm::dvec3 base = wind_vector(from) * (1 - alpha) + wind_vector(to) * alpha;
    const double gust = static_cast<double>(from.gust) * (1 - alpha) + to.gust * alpha;
    const double speed = glm::length(base);
    out.assign(static_cast<size_t>(model.params.columns - 1), base);
    if (speed == 0 || gust == 0) return;
    const glm::dvec3 along = base / speed;
    const glm::dvec3 up = unit_or(-glm::dvec3(model.params.gravity), glm::dvec3(0, 1, 0));
    glm::dvec3 side = glm::cross(along, up);
    if (glm::length(side) < 1e-9) side = glm::cross(along, glm::dvec3(0, 0, 1));
    side = glm::normalize(side);
    const glm::dvec3 lift = glm::cross(side, along);
    const double seconds = static_cast<double>(step) * model.step_seconds;
    // Gusts travel downwind at the wind's speed: a face x metres from the
    // pole feels what the pole felt x / speed seconds earlier.
    const double travel = std::max(speed, 0.5);
    for (size_t c = 0; c < out.size(); ++c) {
        const double t = seconds - 0.5 * (model.column_x[c] + model.column_x[c + 1]) / travel;
        const double strength = speed * (1 + gust * gust_noise(from.seed, 0, t));
        const glm::dvec3 dir =
            glm::normalize(along + gust * kSideTurn * gust_noise(from.seed, 1, t) * side +
                           gust * kLiftTurn * gust_noise(from.seed, 2, t) * lift);
        out[c] = strength * dir;
    }
}

// Positions, velocities and forces as three arrays each, so the force loops
// below run on contiguous doubles and the compiler vectorises them (two
// square roots and divisions per instruction): they are most of the time.
struct Soa {
    std::vector<double> x, y, z;
    void resize(size_t n) {
        x.assign(n, 0);
        y.assign(n, 0);
        z.assign(n, 0);
    }
};

void to_soa(const std::vector<glm::dvec3>& in, Soa& out) {
    for (size_t i = 0; i < in.size(); ++i) {
        out.x[i] = in[i].x;
        out.y[i] = in[i].y;
        out.z[i] = in[i].z;
    }
}

// The springs of one kind: from vertex a = row * columns + column to
// a + offset, for rows [0, rows) and columns [first, last). All share one
// rest length and one pair of constants.
struct SpringFamily {
    int offset, rows, first, last;
    double rest, k, c;
};

std::vector<SpringFamily> spring_families(const ClothParams& p, double mass) {
    const Grid g = grid_of(p);
    const int C = g.columns, R = g.rows;
    const SpringConstants k = spring_constants(p, g);
    const double diagonal = std::sqrt(g.dx * g.dx + g.dy * g.dy);
    auto family = [&](int offset, int rows, int first, int last, double rest, double stiffness) {
        return SpringFamily{
            offset, rows, first, last, rest, stiffness, critical_damping(p, stiffness, mass)};
    };
    std::vector<SpringFamily> f = {
        family(1, R, 0, C - 1, g.dx, k.horizontal), family(C, R - 1, 0, C, g.dy, k.vertical),
        family(C + 1, R - 1, 0, C - 1, diagonal, k.shear),  // top left to bottom right
        family(C - 1, R - 1, 1, C, diagonal, k.shear),      // top right to bottom left
    };
    if (p.bend_stiffness > 0) {
        if (C >= 3) f.push_back(family(2, R, 0, C - 2, 2 * g.dx, k.bend_horizontal));
        if (R >= 3) f.push_back(family(2 * C, R - 2, 0, C, 2 * g.dy, k.bend_vertical));
    }
    return f;
}

struct Scratch {
    // This frame's constants: the model's, with the keyed values of the
    // frame (mass, stiffness, friction, damping) when there are any.
    ClothParams params;
    double particle_mass = 0;
    std::vector<SpringFamily> families;
    Soa position, velocity, force, part;  // `part`: one force per spring or cell of a row
    std::vector<glm::dvec3> predicted;
    Soa wind;  // per column of cells
};

// Hooke's law plus damping along the spring (seed 1.2, 2.1 step 2) for one
// family, a row at a time: each spring's force into `part`, then the sums,
// in separate loops so neither waits on the other through memory.
void add_family(const SpringFamily& fam, int columns, Scratch& s) {
    const double* __restrict x = s.position.x.data();
    const double* __restrict y = s.position.y.data();
    const double* __restrict z = s.position.z.data();
    const double* __restrict vx = s.velocity.x.data();
    const double* __restrict vy = s.velocity.y.data();
    const double* __restrict vz = s.velocity.z.data();
    double* __restrict px = s.part.x.data();
    double* __restrict py = s.part.y.data();
    double* __restrict pz = s.part.z.data();
    const int o = fam.offset, n = fam.last - fam.first;
    const double k = fam.k, c = fam.c, rest = fam.rest;
    for (int row = 0; row < fam.rows; ++row) {
        const int a0 = row * columns + fam.first;
        for (int j = 0; j < n; ++j) {
            const int a = a0 + j, b = a + o;
            const double dx = x[b] - x[a], dy = y[b] - y[a], dz = z[b] - z[a];
            // Adding 1e-300 changes no real length (it is far below one ulp)
            // but keeps a spring of zero length finite: d = 0, so force 0.
            // (A branch or std::max here stops the loop vectorising.)
            const double l = std::sqrt(dx * dx + dy * dy + dz * dz);
            const double inv = 1.0 / (l + 1e-300);
            const double ux = dx * inv, uy = dy * inv, uz = dz * inv;
            const double closing =
                (vx[b] - vx[a]) * ux + (vy[b] - vy[a]) * uy + (vz[b] - vz[a]) * uz;
            const double f = k * (l - rest) + c * closing;
            px[j] = f * ux;
            py[j] = f * uy;
            pz[j] = f * uz;
        }
        double* __restrict fx = s.force.x.data() + a0;
        double* __restrict fy = s.force.y.data() + a0;
        double* __restrict fz = s.force.z.data() + a0;
        for (int j = 0; j < n; ++j) {
            fx[j] += px[j];
            fy[j] += py[j];
            fz[j] += pz[j];
        }
        fx += o;
        fy += o;
        fz += o;
        for (int j = 0; j < n; ++j) {
            fx[j] -= px[j];
            fy[j] -= py[j];
            fz[j] -= pz[j];
        }
    }
}

// Wind on each face (seed 1.3-1.4): F = drag A n (n.w), with w the wind
// relative to the face, plus tangential_drag A (w - n (n.w)). The face is a
// grid cell (its two triangles together): X = (tr - bl) x (tl - br) / 2 is
// its vector area whatever the diagonal, A = |X|, n = X / |X|, and each
// corner takes a quarter of F.
void add_wind(const ClothModel& model, Scratch& s) {
    const ClothParams& p = model.params;
    const double normal_drag = p.wind_drag, tangential_drag = p.wind_tangential_drag;
    if (normal_drag == 0 && tangential_drag == 0) return;
    const Soa& q = s.position;
    const Soa& v = s.velocity;
    const int C = p.columns, n = C - 1;
    double* __restrict fx = s.part.x.data();
    double* __restrict fy = s.part.y.data();
    double* __restrict fz = s.part.z.data();
    for (int row = 0; row + 1 < p.rows; ++row) {
        const int r0 = row * C;
        for (int j = 0; j < n; ++j) {
            const int tl = r0 + j, tr = tl + 1, bl = tl + C, br = bl + 1;
            const double ax = q.x[tr] - q.x[bl], ay = q.y[tr] - q.y[bl], az = q.z[tr] - q.z[bl];
            const double bx = q.x[tl] - q.x[br], by = q.y[tl] - q.y[br], bz = q.z[tl] - q.z[br];
            const double xx = 0.5 * (ay * bz - az * by), xy = 0.5 * (az * bx - ax * bz),
                         xz = 0.5 * (ax * by - ay * bx);
            const double area = std::sqrt(xx * xx + xy * xy + xz * xz);
            const double wx = s.wind.x[j] - 0.25 * (v.x[tl] + v.x[tr] + v.x[bl] + v.x[br]);
            const double wy = s.wind.y[j] - 0.25 * (v.y[tl] + v.y[tr] + v.y[bl] + v.y[br]);
            const double wz = s.wind.z[j] - 0.25 * (v.z[tl] + v.z[tr] + v.z[bl] + v.z[br]);
            // A n (n.w) = X (X.w) / |X|; A w = |X| w.
            const double normal =
                (normal_drag - tangential_drag) * (xx * wx + xy * wy + xz * wz) / (area + 1e-300);
            const double along = tangential_drag * area;
            fx[j] = 0.25 * (normal * xx + along * wx);
            fy[j] = 0.25 * (normal * xy + along * wy);
            fz[j] = 0.25 * (normal * xz + along * wz);
        }
        for (int corner : {0, 1, C, C + 1})
            for (int j = 0; j < n; ++j) {
                s.force.x[r0 + corner + j] += fx[j];
                s.force.y[r0 + corner + j] += fy[j];
                s.force.z[r0 + corner + j] += fz[j];
            }
    }
}

// Seed 1.11: F = m g + springs + friction + wind, friction read as air
// friction on the vertex's motion, -friction m v (docs/cloth.md).
void accumulate_forces(const ClothModel& model, const ClothState& state, Scratch& s) {
    const ClothParams& p = s.params;
    const double m = s.particle_mass;
    const glm::dvec3 weight = m * glm::dvec3(p.gravity);
    const double friction = static_cast<double>(p.friction) * m;
    to_soa(state.positions, s.position);
    to_soa(state.velocities, s.velocity);
    const size_t n = state.positions.size();
    for (size_t i = 0; i < n; ++i) {
        s.force.x[i] = weight.x - friction * s.velocity.x[i];
        s.force.y[i] = weight.y - friction * s.velocity.y[i];
        s.force.z[i] = weight.z - friction * s.velocity.z[i];
    }
    for (const SpringFamily& f : s.families) add_family(f, p.columns, s);
    add_wind(model, s);
}

// Provot 1995: after the step, pull the ends of every structural and shear
// spring longer than (1 + max_stretch) x rest back to that length (only the
// free end moves when one end is pinned). Gauss-Seidel in spring order.
void limit_stretch(const ClothModel& model, std::vector<glm::dvec3>& x) {
    const double limit = 1.0 + static_cast<double>(model.params.max_stretch);
    // Long range attachments first (Kim, Chentanez and Mueller-Fischer,
    // "Long range attachments", SCA 2012): no vertex may be further from its
    // nearest pin than limit x their rest distance. One pass bounds the
    // stretch a pull from the pins would otherwise spread over many
    // Gauss-Seidel passes along the whole cloth.
    for (size_t i = 0; i < x.size(); ++i) {
        const uint32_t pin = model.attachment[i];
        if (pin == kNoAttachment) continue;
        const glm::dvec3 d = x[i] - x[pin];
        const double l2 = glm::dot(d, d);
        const double max_l = limit * model.attachment_rest[i];
        if (l2 > max_l * max_l) x[i] = x[pin] + d * (max_l / std::sqrt(l2));
    }
    const double tolerance2 = (1 + kStrainTolerance) * (1 + kStrainTolerance);
    for (int pass = 0; pass < kMaxStrainPasses; ++pass) {
        double worst2 = 0;  // the largest (length / limit)^2 this pass met
        for (const ClothSpring& sp : model.springs) {
            if (!sp.limit_stretch) break;  // structural and shear come first
            const glm::dvec3 d = x[sp.b] - x[sp.a];
            const double l2 = glm::dot(d, d);
            const double max_l = limit * sp.rest;
            if (!(l2 > max_l * max_l)) continue;  // most springs: no square root
            worst2 = std::max(worst2, l2 / (max_l * max_l));
            const double l = std::sqrt(l2);
            const glm::dvec3 excess = d * ((l - max_l) / l);
            const bool free_a = !model.pinned[sp.a], free_b = !model.pinned[sp.b];
            if (free_a && free_b) {
                x[sp.a] += 0.5 * excess;
                x[sp.b] -= 0.5 * excess;
            } else if (free_a) {
                x[sp.a] += excess;
            } else if (free_b) {
                x[sp.b] -= excess;
            }
        }
        if (worst2 <= tolerance2) break;
    }
}

void substep(const ClothModel& model, ClothState& state, Scratch& s) {
    const double h = model.step_seconds;
    const double inv_m = 1.0 / s.particle_mass;
    accumulate_forces(model, state, s);
    const size_t n = state.positions.size();
    // Semi-implicit Euler (seed 1.9-1.10 with the step h): v += h F/m, then
    // x += h v with the new velocity.
    for (size_t i = 0; i < n; ++i) {
        if (model.pinned[i]) continue;
        state.velocities[i] += (h * inv_m) * glm::dvec3(s.force.x[i], s.force.y[i], s.force.z[i]);
        state.positions[i] += h * state.velocities[i];
    }
    s.predicted = state.positions;
    limit_stretch(model, state.positions);
    // The constraint's move becomes velocity too (Provot, section 4), so the
    // next step does not undo it.
    for (size_t i = 0; i < n; ++i)
        if (!model.pinned[i]) state.velocities[i] += (state.positions[i] - s.predicted[i]) / h;
    ++state.step;
}

}  // namespace

// --- Model ---------------------------------------------------------------------

namespace {

// Vertex indices of the grid: row by row, each row column by column.
struct GridIndex {
    int columns;
    uint32_t operator()(int column, int row) const {
        return static_cast<uint32_t>(row * columns + column);
    }
};

// Pins the left edge, the top edge (each if asked) and the vertices named.
void pin_vertices(ClothModel& m, const ClothPins& pins, int C, int R) {
    const GridIndex at{C};
    const size_t n = static_cast<size_t>(C) * R;
    m.pinned.assign(n, 0);
    for (int r = 0; r < R; ++r)
        if (pins.left_edge) m.pinned[at(0, r)] = 1;
    for (int c = 0; c < C; ++c)
        if (pins.top_edge) m.pinned[at(c, 0)] = 1;
    for (int v : pins.vertices) m.pinned[static_cast<size_t>(v)] = 1;
}

// The flat rest grid in the XY plane, top left at the origin, and the rest
// part's vertices.
void lay_out_rest_grid(ClothModel& m, const ClothParams& params, int C, int R) {
    const GridIndex at{C};
    m.rest_positions.resize(static_cast<size_t>(C) * R);
    MeshPart& part = m.rest_part;
    for (int r = 0; r < R; ++r)
        for (int c = 0; c < C; ++c) {
            // Exact end values: the last column is at `width`, not (C-1) * dx.
            const double x = static_cast<double>(params.width) * c / (C - 1);
            const double y = -static_cast<double>(params.height) * r / (R - 1);
            m.rest_positions[at(c, r)] = {x, y, 0};
            part.positions.push_back(glm::vec3(glm::dvec3(x, y, 0)));
            part.normals.push_back({0, 0, 1});
            part.uvs.push_back({static_cast<float>(c) / (C - 1), static_cast<float>(r) / (R - 1)});
        }
    for (int c = 0; c < C; ++c) m.column_x.push_back(m.rest_positions[at(c, 0)].x);
}

// Each free vertex's nearest pin at rest, for the long range attachments
// (the rest shape is flat, so the straight line is the distance in the
// cloth). Ties go to the first pin in index order.
void attach_to_nearest_pins(ClothModel& m) {
    const size_t n = m.pinned.size();
    std::vector<uint32_t> pinned_list;
    for (uint32_t i = 0; i < n; ++i)
        if (m.pinned[i]) pinned_list.push_back(i);
    m.attachment.assign(n, kNoAttachment);
    m.attachment_rest.assign(n, 0);
    for (uint32_t i = 0; i < n; ++i) {
        if (m.pinned[i]) continue;
        double best = std::numeric_limits<double>::infinity();
        for (uint32_t pin : pinned_list) {
            const double d = glm::length(m.rest_positions[i] - m.rest_positions[pin]);
            if (d < best) {
                best = d;
                m.attachment[i] = pin;
            }
        }
        m.attachment_rest[i] = best;
    }
}

// The list of springs (the strain limit walks it; the forces use the same
// springs grouped by kind, spring_families).
void add_springs(ClothModel& m, const ClothParams& params, const Grid& g) {
    const int C = g.columns, R = g.rows;
    const GridIndex at{C};
    const SpringConstants k = spring_constants(params, g);
    const double diagonal = std::sqrt(g.dx * g.dx + g.dy * g.dy);
    auto spring = [&](uint32_t a, uint32_t b, double rest, double stiffness, bool limit) {
        m.springs.push_back(
            {a, b, rest, stiffness, critical_damping(params, stiffness, m.particle_mass), limit});
    };
    // Structural, row by row outward from the pole so one Gauss-Seidel pass
    // of the strain limit carries a pull from the pins across the cloth.
    for (int r = 0; r < R; ++r)
        for (int c = 0; c < C; ++c) {
            if (c + 1 < C) spring(at(c, r), at(c + 1, r), g.dx, k.horizontal, true);
            if (r + 1 < R) spring(at(c, r), at(c, r + 1), g.dy, k.vertical, true);
        }
    // Shear springs exist even at zero stiffness: they carry the strain limit.
    for (int r = 0; r + 1 < R; ++r)
        for (int c = 0; c + 1 < C; ++c) {
            spring(at(c, r), at(c + 1, r + 1), diagonal, k.shear, true);
            spring(at(c + 1, r), at(c, r + 1), diagonal, k.shear, true);
        }
    if (params.bend_stiffness > 0)
        for (int r = 0; r < R; ++r)
            for (int c = 0; c < C; ++c) {
                if (c + 2 < C) spring(at(c, r), at(c + 2, r), 2 * g.dx, k.bend_horizontal, false);
                if (r + 2 < R) spring(at(c, r), at(c, r + 2), 2 * g.dy, k.bend_vertical, false);
            }
}

// Two triangles per cell, cell by cell along each row (the wind looks up
// a face's column from its index). The diagonal alternates like a
// checkerboard so the mesh has no preferred shear direction.
void add_cell_triangles(ClothModel& m, int C, int R) {
    const GridIndex at{C};
    for (int r = 0; r + 1 < R; ++r)
        for (int c = 0; c + 1 < C; ++c) {
            const uint32_t tl = at(c, r), tr = at(c + 1, r), bl = at(c, r + 1),
                           br = at(c + 1, r + 1);
            if ((r + c) % 2 == 0)
                m.indices.insert(m.indices.end(), {bl, br, tr, bl, tr, tl});
            else
                m.indices.insert(m.indices.end(), {bl, br, tl, br, tr, tl});
        }
    m.rest_part.indices = m.indices;
}

}  // namespace

ClothModel build_cloth_model(const ClothParams& params, const ClothPins& pins) {
    try {
        check_cloth_params(params, pins);
    } catch (const Error& e) {
        throw Error(ExitCode::invalid_input, "cloth: " + e.detail());
    }
    ClothModel m;
    m.params = params;
    m.substeps = cloth_substeps(params);
    m.step_seconds = params.frame_seconds / m.substeps;
    m.particle_mass = particle_mass(params);
    const Grid g = grid_of(params);
    pin_vertices(m, pins, g.columns, g.rows);
    lay_out_rest_grid(m, params, g.columns, g.rows);
    attach_to_nearest_pins(m);
    add_springs(m, params, g);
    add_cell_triangles(m, g.columns, g.rows);
    m.preroll_frames =
        static_cast<int>(std::llround(params.preroll_seconds / params.frame_seconds));
    return m;
}

ClothState start_state(const ClothModel& model) {
    ClothState s;
    s.frame = -model.preroll_frames;
    s.step = static_cast<int64_t>(s.frame) * model.substeps;
    s.positions = model.rest_positions;
    s.velocities.assign(model.rest_positions.size(), glm::dvec3(0));
    // A flat cloth in a plane that holds gravity and the wind would stay in
    // it forever by symmetry, held up by its springs like a board. A twist
    // of a ten-thousandth of its height lets it buckle as real cloth does.
    const int C = model.params.columns, R = model.params.rows;
    const double twist = kStartTwist * static_cast<double>(model.params.height);
    for (int r = 0; r < R; ++r)
        for (int c = 0; c < C; ++c) {
            const size_t i = static_cast<size_t>(r * C + c);
            if (!model.pinned[i])
                s.positions[i].z =
                    twist * (static_cast<double>(c) / (C - 1)) * (static_cast<double>(r) / (R - 1));
        }
    return s;
}

glm::dvec3 wind_at_step(const ClothModel& model, const WindState& from, const WindState& to,
                        int64_t step, int column) {
    std::vector<glm::dvec3> winds;
    column_winds(model, from, to, step, winds);
    return winds.at(static_cast<size_t>(column));
}

ClothParams with_keyed_values(const ClothParams& model, const ClothParams& keyed) {
    ClothParams p = model;
    p.mass = keyed.mass;
    p.stiffness = keyed.stiffness;
    p.friction = keyed.friction;
    p.damping = keyed.damping;
    return p;
}

void advance_cloth_frame(const ClothModel& model, ClothState& state, const WindState& from,
                         const WindState& to, const ClothParams* keyed) {
    Scratch s;
    s.params = keyed ? with_keyed_values(model.params, *keyed) : model.params;
    try {
        if (keyed) {
            ClothParams at_model_steps = s.params;
            at_model_steps.substeps = model.substeps;
            check_cloth_params(at_model_steps);
        }
        for (const WindState* w : {&from, &to}) check_wind(*w, s.params);
    } catch (const Error& e) {
        throw Error(ExitCode::invalid_input, "cloth: " + e.detail());
    }
    s.particle_mass = keyed ? particle_mass(s.params) : model.particle_mass;
    s.families = spring_families(s.params, s.particle_mass);
    const size_t n = state.positions.size();
    for (Soa* a : {&s.position, &s.velocity, &s.force}) a->resize(n);
    s.part.resize(static_cast<size_t>(model.params.columns));
    s.wind.resize(static_cast<size_t>(model.params.columns - 1));
    std::vector<glm::dvec3> winds;
    for (int i = 0; i < model.substeps; ++i) {
        column_winds(model, from, to, state.step, winds);
        for (size_t c = 0; c < winds.size(); ++c) {
            s.wind.x[c] = winds[c].x;
            s.wind.y[c] = winds[c].y;
            s.wind.z[c] = winds[c].z;
        }
        substep(model, state, s);
    }
    ++state.frame;
}

double kinetic_energy(const ClothModel& model, const ClothState& state) {
    double sum = 0;
    for (const auto& v : state.velocities) sum += glm::dot(v, v);
    return 0.5 * model.particle_mass * sum;
}

ClothFrame cloth_frame(const ClothModel& model, const ClothState& state) {
    // Normals from central differences across the grid (one-sided at the
    // borders), not from the triangles: the alternating diagonals would give
    // vertices with four and with eight triangles differently weighted
    // normals, a checkerboard that Gouraud shading shows.
    const int C = model.params.columns, R = model.params.rows;
    const auto& x = state.positions;
    ClothFrame f;
    f.positions.reserve(x.size());
    f.normals.reserve(x.size());
    for (const auto& p : x) f.positions.push_back(glm::vec3(p));
    for (int r = 0; r < R; ++r)
        for (int c = 0; c < C; ++c) {
            const size_t right = static_cast<size_t>(r * C + std::min(c + 1, C - 1));
            const size_t left = static_cast<size_t>(r * C + std::max(c - 1, 0));
            const size_t up = static_cast<size_t>(std::max(r - 1, 0) * C + c);
            const size_t down = static_cast<size_t>(std::min(r + 1, R - 1) * C + c);
            const glm::dvec3 n = glm::cross(x[right] - x[left], x[up] - x[down]);
            f.normals.push_back(glm::vec3(unit_or(n, glm::dvec3(0, 0, 1))));
        }
    return f;
}

// --- Driver --------------------------------------------------------------------

ClothSimulation::ClothSimulation(std::shared_ptr<const ClothModel> model, WindAt wind_at,
                                 ParamsAt params_at)
    : model_(std::move(model)), wind_at_(std::move(wind_at)), params_at_(std::move(params_at)) {
    current_ = start_state(*model_);
    const WindState first = wind(0);
    const std::optional<ClothParams> first_params = keyed(0);
    while (current_.frame < 0)
        advance_cloth_frame(*model_, current_, first, first,
                            first_params ? &*first_params : nullptr);
    checkpoints_.push_back(current_);
}

std::optional<ClothParams> ClothSimulation::keyed(int frame) const {
    if (!params_at_) return std::nullopt;
    return params_at_(frame);
}

WindState ClothSimulation::wind(int frame) const {
    return wind_at_ ? wind_at_(frame) : WindState{};
}

const ClothState& ClothSimulation::simulate_to(int frame) {
    if (frame < 0)
        throw Error(ExitCode::invalid_input,
                    "cloth: frame " + std::to_string(frame) + " is before the simulation's start");
    // Resume from the latest checkpoint at or before `frame` when that is
    // nearer than where the simulation stands (or it stands past `frame`).
    const size_t index =
        std::min(static_cast<size_t>(frame / kCheckpointInterval), checkpoints_.size() - 1);
    if (current_.frame > frame || checkpoints_[index].frame > current_.frame)
        current_ = checkpoints_[index];
    while (current_.frame < frame) {
        const std::optional<ClothParams> params = keyed(current_.frame);
        advance_cloth_frame(*model_, current_, wind(current_.frame), wind(current_.frame + 1),
                            params ? &*params : nullptr);
        if (current_.frame % kCheckpointInterval == 0 &&
            static_cast<size_t>(current_.frame / kCheckpointInterval) == checkpoints_.size())
            checkpoints_.push_back(current_);
    }
    return current_;
}

}  // namespace facet
