#pragma once
/// @file DelayMemory.hpp
/// @brief The rod's reflection memory R(s) (references.md section 2), stored as samples on
/// smooth pieces (R may jump or kink only where a piece starts) and read back by local
/// Lagrange interpolation, so that the delayed term R(t - T) is available at any time.

#include <array>
#include <cstddef>
#include <vector>

namespace beamimpact::exact {

/// @brief Piecewise-smooth history of one scalar function of time.
class DelayMemory {
 public:
  /// @brief Starts a new smooth piece at time t (s); later samples belong to it.
  void start_piece(double t);
  /// @brief Appends a sample (t increasing; t within the current piece).
  void add(double t, double value);
  /// @brief Number of pieces.
  std::size_t pieces() const { return starts_.size(); }
  /// @brief Start time (s) of piece i.
  double piece_start(std::size_t i) const { return starts_[i]; }
  /// @brief The last piece starting at or before s; -1 when s is before the first piece.
  long piece_at(double s) const;
  /// @brief Value at s interpolated on piece i only (degree <= 11, nearest samples).
  double value(std::size_t i, double s) const;
  /// @brief Value at s: 0 before the first piece, else interpolated on piece_at(s).
  double value(double s) const;
  /// @brief Total number of samples stored.
  std::size_t samples() const;

 private:
  std::vector<double> starts_;
  std::vector<std::vector<double>> t_, v_;
  /// Interpolation weights of one stencil: piece, first sample, size. A cache of a pure function
  /// of the stored times, which never change once added. Not thread-safe: one memory serves
  /// one integration.
  struct Stencil {
    std::size_t piece = static_cast<std::size_t>(-1), lo = 0, m = 0;
    double w[12] = {};
  };
  mutable std::array<Stencil, 8> cache_{};
  mutable std::size_t next_slot_ = 0;
  /// The last lower_bound answer and its piece (where the next search starts).
  mutable std::size_t hint_piece_ = static_cast<std::size_t>(-1), hint_ = 0;
  /// std::lower_bound(ts, s) searched from the hint.
  std::size_t lower_bound_near(const std::vector<double>& ts, double s, std::size_t piece) const;
};

}  // namespace beamimpact::exact
