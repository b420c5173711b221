#pragma once
/// @file penalty_law.hpp
/// @brief The IDA reference's contact law: a linear spring-dashpot penalty in the normal
/// direction (force clipped at zero: contact releases when the force would turn tensile) and
/// a regularised Coulomb law in the tangential direction; plus the map between the dashpot's
/// damping ratio and the restitution of an isolated two-mass impact under that law.

#include <cmath>

namespace beamimpact::ida {

/// @brief Penalty parameters of one contact (SI).
struct PenaltyLaw {
  double kn = 0.0;     ///< N/m, normal stiffness
  double cn = 0.0;     ///< N s/m, normal dashpot
  double mu = 0.0;     ///< Coulomb coefficient
  double v_reg = 1.0;  ///< m/s, regularisation velocity of the friction law
  /// Hertz law: the spring is kn |g|^(3/2) (kn in N/m^1.5) instead of kn |g| (N/m).
  bool hertz = false;

  /// @brief Trial normal force kn*(-g) + cn*(-g') (N), or with the Hertz spring
  /// -kn sign(g) |g|^(3/2) - cn g'; contact holds while it is >= 0.
  double normal_force(double gap, double gap_rate) const {
    if (hertz) return -kn * gap * std::sqrt(std::abs(gap)) - cn * gap_rate;
    return -kn * gap - cn * gap_rate;
  }
  /// @brief The spring's stiffness d(force)/d(-g) at gap g (N/m): kn, or 3/2 kn |g|^(1/2).
  double spring_stiffness(double gap) const { return hertz ? 1.5 * kn * std::sqrt(std::abs(gap)) : kn; }
  /// @brief Energy in the spring at gap g (J): kn g^2 / 2, or 2/5 kn |g|^(5/2).
  double spring_energy(double gap) const {
    if (hertz) return 0.4 * kn * gap * gap * std::sqrt(std::abs(gap));
    return 0.5 * kn * gap * gap;
  }
  /// @brief Smooth sign of the slip velocity v/sqrt(v^2 + v_reg^2), in (-1, 1).
  double slip_sign(double vt) const;
  /// @brief Derivative of slip_sign with respect to vt (s/m).
  double slip_sign_derivative(double vt) const;
  /// @brief Tangential force on the striker (N) for normal force R >= 0 and slip velocity vt.
  double friction_force(double R, double vt) const { return -mu * R * slip_sign(vt); }
};

/// @brief Coefficient of restitution of two masses meeting through a spring-dashpot whose
/// force is clipped at zero (release when kn d + cn d' = 0), as a function of the damping
/// ratio zeta = cn / (2 sqrt(kn m_red)). Closed form: zeta < 1 from the damped oscillation,
/// zeta > 1 gives q^((1+q)/(1-q)) with q the ratio of the two real roots; zeta = 1 gives e^-2.
double restitution_for_damping_ratio(double zeta);

/// @brief Inverse of restitution_for_damping_ratio for e in (0, 1] (bisection to 1e-14).
double damping_ratio_for_restitution(double e);

}  // namespace beamimpact::ida
