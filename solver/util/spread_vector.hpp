#pragma once
/// @file spread_vector.hpp
/// @brief A vector with no special structure, the same on every machine: for start vectors and
/// checks that must not hit a zero or a symmetry of the operator.

#include <Eigen/Core>

namespace beamimpact {

/// @brief n entries in [0.5, 1.5) from a linear congruential sequence (seed 12345): every
/// entry non-zero, so every mode of an operator carries some weight.
/// @param n the size
inline Eigen::VectorXd spread_vector(int n) {
  Eigen::VectorXd q(n);
  unsigned s = 12345u;
  for (int i = 0; i < n; ++i) {
    s = s * 1103515245u + 12345u;
    q(i) = 0.5 + static_cast<double>((s >> 8) & 0xffff) / 65536.0;
  }
  return q;
}

}  // namespace beamimpact
