#pragma once
/// @file ida_options.hpp
/// @brief The [ida] table of a scene: tolerances, penalty parameters, friction regularisation,
/// linear solver and output step. Every default used is recorded in `assumed` ("ida.key").

#include <map>
#include <optional>
#include <string>

#include <solver/scene/Scene.hpp>

namespace beamimpact::ida {

/// @brief Settings read from [ida] (SI units). Unset optionals are derived per contact.
struct IdaOptions {
  double rtol = 1e-8;                   ///< IDA relative tolerance
  double atol = 1e-11;                  ///< IDA absolute tolerance (m, m/s, rad, rad/s)
  std::optional<double> kn;             ///< N/m, penalty stiffness for every contact
  double kn_factor = 1000.0;            ///< kn = kn_factor x EA/le of the stiffer contact element
  std::optional<double> cn;             ///< N s/m, dashpot for every contact
  std::optional<double> damping_ratio;  ///< cn = 2 zeta sqrt(kn m_red)
  double restitution = 0.01;            ///< target restitution (used when cn and zeta are unset)
  double friction_velocity = 0.0;       ///< m/s, regularisation velocity of the Coulomb law
  std::string linear_solver = "auto";   ///< "auto" | "dense" | "klu"
  int dense_max = 16;                   ///< auto: dense up to this many unknowns (KLU was faster
                                        ///< from S1 (48 unknowns) up)
  std::optional<double> output_step;    ///< s, history row spacing (default: the scene's grid)
  double max_step = 0.0;                ///< s, 0 = IDA's choice
  double merge_gap = 0.0;               ///< s, contact phases closer than this are one interval
};

/// @brief Reads scene.method_tables["ida"]. dt: s, the scene's step (resolved when "auto"),
/// which sets the default chatter merge gap; v_scale: m/s, the largest initial speed.
/// Throws InputError naming the file and "ida.key" for a bad or unknown key.
IdaOptions read_ida_options(const Scene& scene, double dt, double v_scale,
                            std::map<std::string, std::string>* assumed);

}  // namespace beamimpact::ida
