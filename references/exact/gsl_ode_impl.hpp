#pragma once
/// @file gsl_ode_impl.hpp
/// @brief What the modal-sum solutions (rod on a beam, ball on a beam) share of GSL: an owning
/// ODE driver and the check that turns a GSL status into an error naming the solution and step.

#include <memory>
#include <stdexcept>
#include <string>

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

}  // namespace beamimpact::exact::detail
