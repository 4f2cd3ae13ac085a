#pragma once
// Sine and cosine whose bits do not depend on the CPU or the C library: for
// tables that must come out the same on every machine (the BRDF's DFG
// table, an environment's spherical harmonics). The C library's cos may
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

// atan2(y, x) in radians for y >= 0 (an angle in [0, pi]), from IEEE-exact
// operations and sqrt, which is exactly rounded too. The ratio of the
// smaller to the larger magnitude is halved in angle twice, by
// atan(r) = 2 atan(r / (1 + sqrt(1 + r^2))), to at most tan(pi/16) < 0.2,
// where 14 terms of the Taylor series leave an error below 1e-20.
inline double exact_atan2(double y, double x) {
    constexpr double kPiDouble = 3.14159265358979323846;
    const double ax = std::fabs(x);
    if (!(y > 0) && !(ax > 0)) return 0;
    const bool steep = y > ax;
    double r = steep ? ax / y : y / ax;
    for (int halving = 0; halving < 2; ++halving) r = r / (1.0 + std::sqrt(1.0 + r * r));
    const double r2 = r * r;
    double power = r, sum = 0;
    for (int k = 0; k < 14; ++k) {
        sum += (k % 2 ? -power : power) / static_cast<double>(2 * k + 1);
        power *= r2;
    }
    double angle = 4.0 * sum;
    if (steep) angle = kPiDouble / 2 - angle;
    return x < 0 ? kPiDouble - angle : angle;
}

}  // namespace facet
