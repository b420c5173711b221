#pragma once
/// @file RodOnWall.hpp
/// @brief Exact solution of a free elastic rod moving end-on towards an immovable rigid wall,
/// under a constant body acceleration g along the approach (gravity; 0 for none): the rod
/// striking a wall (d'Alembert) and the bouncing bar of Doyen, Ern and Piperno (2011).
///
/// Derivation. Let x run along the rod from its contact end (x = 0) to its free end (x = L),
/// pointing away from the wall, and describe the rod in the frame that moves with its
/// contact-free rigid motion (initial approach speed v0 plus g t): in that frame there is no
/// body force, the rod is at rest and stress-free until it touches, and the wall approaches it
/// at w(t) = v0 + g t. The wave equation u_tt = c^2 u_xx (c = sqrt(E / rho)) has the d'Alembert
/// solution u = P(t - x/c) + Q(t + x/c); with p = P', q = Q' the velocity is v = p(t - x/c) +
/// q(t + x/c) and the strain e = (q(t + x/c) - p(t - x/c)) / c. The free end (e(L) = 0) reflects
/// every wave leaving the contact end back to it after T2 = 2 L / c: q(t) = p(t - T2). At the
/// contact end the compressive force is R = Z (p - q), Z = rho A c:
///   open:   R = 0, so p(t) = q(t) = p(t - T2);
///   closed: the end moves with the wall, p + q = w, so p(t) = w(t) - p(t - T2) and
///           R = Z (w(t) - 2 p(t - T2)).
/// The gap closes at the rate w - (p + q). Since p = 0 before the first touch and w is linear in
/// t, p is piecewise linear: each piece is found exactly from the piece T2 earlier, the release
/// (R reaching zero on a linear piece, or jumping below zero where p(t - T2) jumps) and the touch
/// (a root of the piecewise quadratic gap) are closed-form, and every output is exact to
/// roundoff. Back in the ground frame the rod's velocity along the approach is w - v, and the
/// strain is the same. Without gravity: contact for exactly T2 at R = Z v0, the rod leaves
/// stress-free at -v0. With the bouncing bar's data the motion is periodic (see the test).

#include <array>
#include <vector>

#include <references/exact/CoaxialRods.hpp>
#include <references/exact/Rod.hpp>

namespace beamimpact::exact {

/// @brief The data of the problem (SI units).
struct RodOnWallSetup {
  Rod rod;             ///< the free elastic rod
  double v0 = 0.0;     ///< m/s, initial speed towards the wall
  double g = 0.0;      ///< m/s^2, body acceleration towards the wall (gravity along the axis)
  double gap = 0.0;    ///< m, initial gap between the contact end and the wall (> 0)
  double t_end = 0.0;  ///< s, solved up to this time
};

/// @brief The contact end at one time; displacement and velocity along the approach direction.
struct RodOnWallState {
  double R = 0.0;       ///< N, compressive contact force
  double gap = 0.0;     ///< m
  double u = 0.0;       ///< m, contact-end displacement towards the wall
  double v = 0.0;       ///< m/s, contact-end velocity towards the wall
  bool closed = false;  ///< touching the wall
};

/// @brief The exact solution up to t_end.
class RodOnWall {
 public:
  /// @brief Solves the problem; throws std::invalid_argument for a non-positive gap or t_end.
  explicit RodOnWall(const RodOnWallSetup& setup);

  /// @brief The contact end at time t (s), right-continuous at events.
  RodOnWallState state(double t) const;
  /// @brief Kinetic and strain energy and momentum (towards the wall) of the rod at time t, in
  /// the ground frame, integrated exactly over its piecewise-linear wave field.
  RodField field(double t) const;
  /// @brief Impulse of R over [0, t] (N s).
  double impulse(double t) const;
  /// @brief Work of gravity over [0, t], m g times the mean displacement towards the wall (J).
  double load_work(double t) const;
  /// @brief Contact intervals [touch, release] (s); one still closed at t_end ends there.
  const std::vector<std::array<double, 2>>& intervals() const { return intervals_; }
  /// @brief Largest R (N) up to t_end.
  double peak_force() const { return peak_; }
  /// @brief Number of linear pieces of the wave p (a cost measure).
  std::size_t pieces() const { return pieces_.size(); }

 private:
  /// On [start, next start): p = p0 + ps s, q = q0 + qs s (s = t - start); gap, impulse I and its
  /// integral J at `start`.
  struct Piece {
    double start, p0, ps, q0, qs;
    bool closed;
    double gap, I, J;
  };
  void solve();
  /// The piece holding time s (the last with start <= s); nullptr before the first.
  const Piece* piece_at(double s) const;
  /// p on the line of the piece holding `where`, evaluated at s (0 before the first piece).
  double p_line(double s, double where) const;
  /// The earliest start of q's next piece after t: a piece start of p shifted by T2.
  double next_q_break(double t) const;
  /// One step of the solver from t: returns the end of the piece pushed (or t on a switch).
  double advance(double t, bool& closed, double& gap, double& I, double& J);

  RodOnWallSetup s_;
  double T2_, Z_, eps_t_, tol_gap_, tol_v_;
  std::vector<Piece> pieces_;
  std::vector<std::array<double, 2>> intervals_;
  double peak_ = 0.0;
};

}  // namespace beamimpact::exact
