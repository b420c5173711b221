/// @file step_kernel.cc
/// @brief The hand-written lumped-mass central-difference kernel (see step_kernel.hpp).
#include "step_kernel.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace beamimpact::bench {

namespace {
constexpr double E = 2.1e11, rho = 7850.0, b = 0.01, length = 1.0;
}

StepKernel::StepKernel(std::size_t elements, bool frame) : frame_(frame), nodes_(elements + 1) {
  if (elements == 0) throw std::invalid_argument("StepKernel: elements must be >= 1");
  const std::size_t per = frame ? 3 : 1;
  const double L = length / static_cast<double>(elements), A = b * b, I = b * b * b * b / 12.0;
  const double m = rho * A * L;
  u_.assign(nodes_ * per, 0.0);
  f_.assign(nodes_ * per, 0.0);
  // Lumped mass: m/2 per translation and end, HRZ-like rotary inertia m L^2 / 78.
  std::vector<double> mass(nodes_ * per, 0.0);
  for (std::size_t e = 0; e < elements; ++e)
    for (std::size_t a = 0; a < 2; ++a)
      for (std::size_t d = 0; d < per; ++d) mass[(e + a) * per + d] += d == 2 ? m * L * L / 78.0 : m / 2.0;
  // Element bound on the critical step: rod 2 / omega = L / c; frame governed by bending.
  const double c = std::sqrt(E / rho);
  double dt = L / c;
  // Bending with HRZ rotary inertia: omega_max is about 22 c r / L^2 (r the radius of gyration).
  if (frame) dt = std::min(dt, 2.0 / 22.0 * L * L / (c * std::sqrt(I / A)));
  dt *= 0.5;
  minv_dt2_.resize(mass.size());
  for (std::size_t i = 0; i < mass.size(); ++i) minv_dt2_[i] = dt * dt / mass[i];
  if (frame) {
    const double ea = E * A / L, ei = E * I, L2 = L * L, L3 = L2 * L;
    const double k[6][6] = {{ea, 0, 0, -ea, 0, 0},
                            {0, 12 * ei / L3, 6 * ei / L2, 0, -12 * ei / L3, 6 * ei / L2},
                            {0, 6 * ei / L2, 4 * ei / L, 0, -6 * ei / L2, 2 * ei / L},
                            {-ea, 0, 0, ea, 0, 0},
                            {0, -12 * ei / L3, -6 * ei / L2, 0, 12 * ei / L3, -6 * ei / L2},
                            {0, 6 * ei / L2, 2 * ei / L, 0, -6 * ei / L2, 4 * ei / L}};
    for (int r = 0; r < 6; ++r)
      for (int q = 0; q < 6; ++q) k_[6 * r + q] = k[r][q];
  } else {
    const double ea = E * A / L;
    k_[0] = ea, k_[1] = -ea, k_[2] = -ea, k_[3] = ea;
  }
  // A smooth initial displacement so the step does real arithmetic (no denormals, no zeros).
  for (std::size_t i = 0; i < u_.size(); ++i) u_[i] = 1e-6 * std::sin(0.001 * static_cast<double>(i));
  u_prev_ = u_;
}

void StepKernel::step() {
  const std::size_t per = frame_ ? 3 : 1, w = 2 * per, n = u_.size();
  std::fill(f_.begin(), f_.end(), 0.0);
  // Internal force, element by element (the elements are identical and unrotated).
  for (std::size_t e = 0; e + 1 < nodes_; ++e) {
    const double* ue = u_.data() + e * per;
    double* fe = f_.data() + e * per;
    for (std::size_t r = 0; r < w; ++r) {
      double s = 0.0;
      for (std::size_t q = 0; q < w; ++q) s += k_[w * r + q] * ue[q];
      fe[r] += s;
    }
  }
  // Central difference, one fused sweep: u_next = 2u - u_prev - dt^2 M^-1 f.
  for (std::size_t i = 0; i < n; ++i) {
    const double next = 2.0 * u_[i] - u_prev_[i] - minv_dt2_[i] * f_[i];
    u_prev_[i] = u_[i];
    u_[i] = next;
  }
}

}  // namespace beamimpact::bench
