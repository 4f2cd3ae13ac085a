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

}  // namespace facet
