#pragma once
/// @file erfcx.hpp
/// @brief Scaled complementary error function erfcx(x) = exp(x^2) erfc(x), from GSL.

namespace beamimpact::exact {

/// @brief erfcx(x) = exp(x^2) erfc(x), accurate for large x where exp(x^2) overflows.
///
/// GSL has no erfcx, but its hazard function h(y) = phi(y) / Q(y) (the inverse Mills ratio,
/// computed by GSL with its own asymptotic series for large y) gives it exactly:
/// with y = sqrt(2) x, Q(y) = erfc(x)/2 and phi(y) = exp(-x^2)/sqrt(2 pi), so
/// erfcx(x) = sqrt(2/pi) / h(sqrt(2) x). For x < 0 there is no cancellation and
/// exp(x^2) erfc(x) is used directly.
double erfcx(double x);

}  // namespace beamimpact::exact
