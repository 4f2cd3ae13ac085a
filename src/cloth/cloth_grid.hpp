#pragma once
// Internal to the cloth (cloth.cpp, cloth_limits.cpp): the grid's cell sizes
// and the spring constants and masses both the simulation and its stability
// bound use.
#include <cmath>

#include "cloth/cloth.hpp"

namespace facet::cloth_detail {

struct Grid {
    int columns, rows;
    double dx, dy;  // cell sides, m
};

inline Grid grid_of(const ClothParams& p) {
    return {p.columns, p.rows, static_cast<double>(p.width) / (p.columns - 1),
            static_cast<double>(p.height) / (p.rows - 1)};
}

// Hooke constants per spring kind, chosen so `stiffness` is the sheet's
// stretch modulus whatever the cells' aspect: a row of springs of length dx
// spaced dy apart carries k * strain * dx / dy newtons per metre.
struct SpringConstants {
    double horizontal, vertical, shear, bend_horizontal, bend_vertical;
};

inline SpringConstants spring_constants(const ClothParams& p, const Grid& g) {
    const double s = p.stiffness;
    const double diagonal2 = g.dx * g.dx + g.dy * g.dy;
    return {s * g.dy / g.dx, s * g.dx / g.dy, p.shear_stiffness * s * 2 * g.dx * g.dy / diagonal2,
            p.bend_stiffness * s * g.dy / g.dx, p.bend_stiffness * s * g.dx / g.dy};
}

inline double critical_damping(const ClothParams& p, double k, double mass) {
    return 2.0 * p.damping * std::sqrt(k * mass);
}

inline double particle_mass(const ClothParams& p) {
    return static_cast<double>(p.mass) / (static_cast<double>(p.columns) * p.rows);
}

}  // namespace facet::cloth_detail
