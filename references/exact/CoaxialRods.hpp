#pragma once
/// @file CoaxialRods.hpp
/// @brief Exact d'Alembert solution of two coaxial elastic rods in impact (references.md
/// section 1), in the frame where the target B is initially at rest: a free striker, and a
/// target whose far end is free or fixed (clamped against axial motion).

#include <array>
#include <vector>

#include <references/exact/Rod.hpp>

namespace beamimpact::exact {

/// @brief One piece of the solution: on [start, next start) the contact force and both end
/// velocities are constant, so displacements and the gap are linear.
struct RodsSegment {
  double start = 0.0;    ///< s
  double P = 0.0;        ///< N, compressive contact force
  double va = 0.0;       ///< m/s, striker contact-end velocity (towards B)
  double vb = 0.0;       ///< m/s, target contact-end velocity (away from A)
  double ua = 0.0;       ///< m, striker end displacement at `start`
  double ub = 0.0;       ///< m, target end displacement at `start`
  double gap = 0.0;      ///< m, gap at `start`
  bool closed = false;   ///< the gap is closed (force may still be zero)
  double ra = 0.0;       ///< N, force wave R_A leaving the contact end into the striker
  double rb = 0.0;       ///< N, force wave R_B leaving the contact end into the target
  double impulse = 0.0;  ///< N s, impulse of P over [0, start]
};

/// @brief The contact ends' state at one time.
struct RodsEndState {
  double P = 0.0, gap = 0.0;  ///< N, m
  double ua = 0.0, va = 0.0;  ///< m, m/s: striker end (positive towards B)
  double ub = 0.0, vb = 0.0;  ///< m, m/s: target end (positive away from A)
  bool closed = false;        ///< gap closed
};

/// @brief Energies and momentum of one rod, integrated exactly over its piecewise-constant
/// wave field (J, J, N s; velocities positive from A towards B).
struct RodField {
  double kinetic = 0.0, strain = 0.0, momentum = 0.0;
};

/// @brief The exact solution: the force P is piecewise constant between breakpoints
/// (contact start, re-contacts, and their shifts by multiples of T_A and T_B), so it is
/// evaluated once per piece, exactly, and every output is a closed-form function of time. So
/// are the force waves leaving the contact end (R_X(s) = P(s) + eps_X R_X(s - T_X)), stored per
/// piece: every look-up is a binary search, a piece costs O(log pieces) and an output row
/// O(pieces within one round trip x log pieces).
class CoaxialRods {
 public:
  /// @brief Striker a approaches target b (at rest) at v0 (m/s) across gap (m); solved to t_end (s).
  /// @param far how the target's far end reflects (free by default).
  CoaxialRods(const Rod& a, const Rod& b, double v0, double gap, double t_end, FarEnd far = FarEnd::kFree);

  /// @brief End state at time t (s), 0 <= t <= t_end; right-continuous at breakpoints.
  RodsEndState state(double t) const;
  /// @brief Impulse of P over [0, t] (N s), exact.
  double impulse(double t) const;
  /// @brief Exact kinetic and strain energy and momentum of the striker at time t.
  RodField striker_field(double t) const { return field(a_, t, true); }
  /// @brief Exact kinetic and strain energy and momentum of the target at time t.
  RodField target_field(double t) const { return field(b_, t, false); }
  /// @brief Intervals [start, end] (s) where P > 0; a zero-force phase with the gap still closed
  /// joins its neighbours (it is not a separation), and one at the end is not reported.
  std::vector<std::array<double, 2>> force_intervals() const;
  /// @brief The pieces of the solution (the first, before contact, starts at t = 0).
  const std::vector<RodsSegment>& segments() const { return segs_; }
  /// @brief Time of first touch (s), or a value above t_end when the rods never touch.
  double first_touch() const { return t0_; }
  /// @brief Largest force (N).
  double peak_force() const;

 private:
  /// The piece holding time s (the last with start <= s; the first piece for s < 0).
  const RodsSegment& piece_at(double s) const;
  /// R_X(s): the force wave leaving the contact end into the striker (or the target) at time s.
  double wave(double s, bool striker) const;
  RodField field(const Rod& rod, double t, bool striker) const;
  void solve();

  Rod a_, b_;
  double v0_, gap0_, t_end_, t0_;
  double eb_;  ///< reflection sign of the target's far end: +1 free, -1 fixed
  std::vector<RodsSegment> segs_;
};

}  // namespace beamimpact::exact
