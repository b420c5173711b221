#include <references/exact/erfcx.hpp>

#include <cmath>
#include <numbers>

#include <gsl/gsl_sf_erf.h>

namespace beamimpact::exact {

double erfcx(double x) {
  if (x < 0.0) return std::exp(x * x) * gsl_sf_erfc(x);
  return std::sqrt(2.0 / std::numbers::pi) / gsl_sf_hazard(std::numbers::sqrt2 * x);
}

}  // namespace beamimpact::exact
