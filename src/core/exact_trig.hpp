#pragma once
// Sine, cosine and arc tangent whose bits do not depend on the CPU or the C
// library: for tables that must come out the same on every machine (the
// BRDF's DFG table, an environment's spherical harmonics and prefiltered
// maps). The C library's cos may
// pick a different implementation on different CPUs (glibc has FMA
// variants chosen at run time), which could change the last bits.
#include <cmath>

namespace facet {

// cos(2 pi t) for any t, from the Taylor series of cos about 0 after moving
// t to [-1/2, 1/2]: only IEEE-exact adds, multiplies and divides (floor is
// exact too). 18 terms leave a truncation error below 1e-20 at pi.
inline double cos_turns(double t) {
    constexpr double kPiDouble = 3.14159265358979323846;
    const double x = 2.0 * kPiDouble * (t - std::floor(t) - 0.5);  // cos(2 pi t) = -cos(x)
    const double x2 = x * x;
    double term = 1.0, sum = 1.0;
    for (int k = 1; k < 18; ++k) {
        term *= -x2 / static_cast<double>((2 * k - 1) * (2 * k));
        sum += term;
    }
    return -sum;
}

// sin(2 pi t) = cos(2 pi (t - 1/4)).
inline double sin_turns(double t) {
    return cos_turns(t - 0.25);
}

// atan(t) in radians for 0 <= t <= 1. Above tan(pi/12) the angle is moved
// down by pi/6, atan(t) = pi/6 + atan((sqrt(3) t - 1) / (t + sqrt(3))), so
// that the Taylor series t - t^3/3 + t^5/5 - ... runs on |t| <= tan(pi/12)
// = 0.268, where 15 terms leave an error below 1e-19. Adds, multiplies and
// one divide, like cos_turns; the series' 1/(2k + 1) are constants the
// compiler rounds, so that a call (an environment map makes millions) does
// not wait on 14 divisions.
inline double atan_unit_interval(double t) {
    constexpr double kSqrt3 = 1.73205080756887729353;
    constexpr double kTanPiOver12 = 0.26794919243112270647;
    constexpr double kPiOver6 = 0.52359877559829887308;
    constexpr double kInverseOdd[15] = {1.0,        1.0 / 3.0,  1.0 / 5.0,  1.0 / 7.0,  1.0 / 9.0,
                                        1.0 / 11.0, 1.0 / 13.0, 1.0 / 15.0, 1.0 / 17.0, 1.0 / 19.0,
                                        1.0 / 21.0, 1.0 / 23.0, 1.0 / 25.0, 1.0 / 27.0, 1.0 / 29.0};
    double offset = 0.0;
    if (t > kTanPiOver12) {
        t = (kSqrt3 * t - 1.0) / (t + kSqrt3);
        offset = kPiOver6;
    }
    const double t2 = t * t;
    double power = t, sum = t;
    for (int k = 1; k < 15; ++k) {
        power *= -t2;
        sum += power * kInverseOdd[k];
    }
    return offset + sum;
}

// atan2(y, x) / (2 pi): the angle of (x, y) in turns, in [-1/2, 1/2], 0
// for (0, 0). The octant is reduced by swapping and mirroring, which is
// exact, so every quadrant has the same accuracy as atan_unit_interval.
inline double atan2_turns(double y, double x) {
    constexpr double kPiDouble = 3.14159265358979323846;
    const double ax = std::abs(x), ay = std::abs(y);
    if (ax == 0.0 && ay == 0.0) return 0.0;
    double angle =
        ax >= ay ? atan_unit_interval(ay / ax) : 0.5 * kPiDouble - atan_unit_interval(ax / ay);
    if (x < 0.0) angle = kPiDouble - angle;
    if (y < 0.0) angle = -angle;
    return angle / (2.0 * kPiDouble);
}

}  // namespace facet
