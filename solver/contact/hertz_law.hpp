#pragma once
/// @file hertz_law.hpp
/// @brief The Hertz local contact law in the paper's displacement compatibility: the corrected
/// gap is no longer zero but the local indentation, g^{p+1} = -(R / k)^(2/3) (R = k delta^(3/2),
/// Johnson 1985, Eq. 4.23). With g^{p+1} = a + b R linear in R (a the predicted gap including
/// the other forces, b > 0 the compliance of the step), R solves a + b R + (R / k)^(2/3) = 0.

namespace beamimpact::paper {

/// @brief The root R >= 0 of a + b R + (R / k)^(2/3) = 0 (N); 0 when a >= 0.
/// Newton's iteration on the indentation x = (R / k)^(2/3), h(x) = a + b k x^(3/2) + x, from
/// min(-a, (-a / (b k))^(2/3)), both at or right of the root: h is increasing and convex, so the
/// iterates decrease monotonically onto the root and never leave the bracket [0, x0].
/// @param a m, the gap the step reaches without this force
/// @param b m/N, the gap's response to the force (> 0)
/// @param k N/m^1.5, the Hertz stiffness (> 0)
double hertz_force(double a, double b, double k);

/// @brief The energy stored in a Hertz spring carrying force R: 2/5 k delta^(5/2) = 2/5 R delta
/// with delta = (R / k)^(2/3) (J).
double hertz_energy(double R, double k);

}  // namespace beamimpact::paper
