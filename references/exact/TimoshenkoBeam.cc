#include <references/exact/TimoshenkoBeam.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace beamimpact::exact {

std::array<TimoshenkoRoot, 2> timoshenko_roots(const SimpleBeam& beam, const BeamShear& shear, long n) {
  const double k = static_cast<double>(n) * std::numbers::pi / beam.length;
  const double rA = beam.rho * beam.area, rI = beam.rho * beam.inertia, EI = beam.E * beam.inertia;
  const double S = shear.kappa * shear.G * beam.area;  // kappa G A (N)
  // a W^2 - b W + c = 0 in W = omega^2: the larger root from the sum, the smaller from the product
  // c / a (no cancellation when the branches are far apart, as for a slender beam).
  const double a = rA * rI, b = (rA * EI + rI * S) * k * k + rA * S, c = S * EI * k * k * k * k;
  const double upper = 0.5 * (b + std::sqrt(std::max(0.0, b * b - 4.0 * a * c))) / a;
  const double lower = c / (a * upper);
  std::array<TimoshenkoRoot, 2> roots;
  for (int i = 0; i < 2; ++i) {
    const double w2 = i == 0 ? lower : upper;
    roots[i].omega = std::sqrt(w2);
    roots[i].ratio =
        k - rA * w2 / (S * k);  // from the first equation: (kappa G A k^2 - rho A omega^2) / (kappa G A k)
  }
  return roots;
}

}  // namespace beamimpact::exact
