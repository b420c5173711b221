#pragma once
/// @file hertz_law.hpp
/// @brief The Hertz local contact law R = k delta^(3/2) (delta = -g the indentation, Johnson 1985,
/// Eq. 4.23) in the paper's displacement compatibility, integrated so that it cannot create
/// energy: the force applied at step p is the secant (discrete gradient) of the spring's
/// potential V(g) = 2/5 k delta^(5/2) between the gaps at U^{p-1} and U^{p+1},
/// R^p = (V(g^{p+1}) - V(g^{p-1})) / (g^{p-1} - g^{p+1}). Its work over central differences'
/// step, R^p (g^{p+1} - g^{p-1}) / 2, is then exactly -(V(g^{p+1}) - V(g^{p-1})) / 2: summed over
/// the steps it telescopes into the change of the stored energy (V(g^p) + V(g^{p+1})) / 2, at any
/// step and any stiffness. With g^{p+1} = a + b R linear in R (a the predicted gap including the
/// other forces, b > 0 the compliance of the step), R solves R = D(a + b R) with D the secant.

namespace beamimpact::paper {

/// @brief The energy stored in a Hertz spring at gap g: 2/5 k delta^(5/2), delta = max(-g, 0) (J).
/// @param g m, the gap (negative: indentation)
/// @param k N/m^1.5, the Hertz stiffness
double hertz_potential(double g, double k);

/// @brief The secant force D(x) = (V(x) - V(gp)) / (gp - x) (N, >= 0): the constant force whose
/// work over the gap's move from gp to x is the spring's energy change; k delta^(3/2) at x = gp.
/// Evaluated without cancellation when both gaps indent.
/// @param x m, the gap at the step's end
/// @param gp m, the gap at its start
/// @param k N/m^1.5, the Hertz stiffness
double hertz_secant_force(double x, double gp, double k);

/// @brief The root R >= 0 of R = hertz_secant_force(a + b R, gp, k) (N); 0 when a >= 0 and
/// gp >= 0. D is non-increasing in x (V is convex), so h(y) = y - b D(a + y) increases and the
/// correction y = b R lies in [0, b D(a)]: the modified regula falsi (Illinois) in that bracket.
/// @param a m, the gap the step reaches without this force
/// @param b m/N, the gap's response to the force (> 0)
/// @param gp m, the gap two steps before (at U^{p-1})
/// @param k N/m^1.5, the Hertz stiffness (> 0)
double hertz_step_force(double a, double b, double gp, double k);

}  // namespace beamimpact::paper
