#pragma once
/// @file gsl_ode_impl.hpp
/// @brief What the modal-sum solutions (rod on a beam, ball on a beam) share of GSL: an owning
/// ODE driver and the check that turns a GSL status into an error naming the solution and step.

#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>

namespace beamimpact::exact::detail {

/// @brief Frees a GSL ODE driver.
struct DriverDeleter {
  void operator()(gsl_odeiv2_driver* d) const { gsl_odeiv2_driver_free(d); }
};

/// @brief An owning GSL ODE driver.
using Driver = std::unique_ptr<gsl_odeiv2_driver, DriverDeleter>;

/// @brief Throws std::runtime_error "SOLUTION: WHAT: GSL's message" unless `status` is GSL_SUCCESS.
/// @param status a GSL return code
/// @param solution the solution's name ("rod-on-beam", "ball-on-beam")
/// @param what the step that returned it ("integration", "root finding", ...)
inline void check_gsl(int status, const char* solution, const char* what) {
  if (status != GSL_SUCCESS)
    throw std::runtime_error(std::string(solution) + ": " + what + ": " + gsl_strerror(status));
}

/// @brief Integrates a copy of (ta, ya) to tb with `aux` (reset first), for root finding on a
/// state the main driver has passed; counts the steps into `steps`.
/// @param aux the auxiliary driver
/// @param ta start time (s) @param ya state at ta @param tb end time (s; tb <= ta: ya unchanged)
/// @param tmp storage for the result (returned) @param steps running step count
/// @param solution the solution's name for an error message
inline const std::vector<double>& integrate_copy(gsl_odeiv2_driver* aux, double ta,
                                                 const std::vector<double>& ya, double tb,
                                                 std::vector<double>& tmp, long& steps,
                                                 const char* solution) {
  tmp = ya;
  gsl_odeiv2_driver_reset(aux);
  double t = ta;
  if (tb > ta) check_gsl(gsl_odeiv2_driver_apply(aux, &t, tb, tmp.data()), solution, "integration");
  steps += static_cast<long>(aux->e->count);
  return tmp;
}

}  // namespace beamimpact::exact::detail
