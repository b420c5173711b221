#pragma once
/// @file RigidRodImpact.hpp
/// @brief Closed form of a rigid rod striking an immovable rigid surface obliquely with Coulomb
/// friction (references.md section 3): rod mass m, length l, inertia m l^2 / 12 about its
/// centre, inclined at theta to the surface, falling at V along the surface normal without spin,
/// restitution e. With s = sin theta, c = cos theta:
///   stick is possible iff mu >= 3 s c / (1 + 3 s^2);
///   stick: p_n = (1 + e) m V (1 + 3 s^2) / 4, p_t = p_n 3 s c / (1 + 3 s^2);
///   slip:  p_n = (1 + e) m V / (1 + 3 c^2 - 3 s c mu), p_t = mu p_n.
/// p_t acts on the rod at its contact end, toward its centre's side along the surface (the
/// direction that stops the end's slide).

namespace beamimpact::exact {

/// @brief The impulses and the rod's motion after the impact.
struct RigidRodImpact {
  double mu_star = 0.0;         ///< the stick threshold 3 s c / (1 + 3 s^2)
  bool stick = false;           ///< mu >= mu_star
  double p_n = 0.0;             ///< N s, normal impulse (on the rod, away from the surface)
  double p_t = 0.0;             ///< N s, tangential impulse (on the rod, toward its centre's side)
  double v_n = 0.0, v_t = 0.0;  ///< m/s, centre velocity after: normal (away), tangential (centre's side)
  double omega = 0.0;           ///< rad/s, spin after, positive turning the rod up off the surface
};

/// @brief The closed form for mass m (kg), length l (m), angle theta (rad, 0 < theta < pi/2),
/// approach speed V (m/s, > 0), friction mu, restitution e.
RigidRodImpact rigid_rod_impact(double m, double l, double theta, double V, double mu, double e = 0.0);

}  // namespace beamimpact::exact
