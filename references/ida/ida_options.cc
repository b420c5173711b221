#include <references/ida/ida_options.hpp>

#include <fmt/format.h>

#include <solver/record/ContactIntervals.hpp>
#include <solver/scene/TableReader.hpp>

namespace beamimpact::ida {

IdaOptions read_ida_options(const Scene& scene, double dt, double v_scale,
                            std::map<std::string, std::string>* assumed) {
  MethodOptions opts(scene, "ida", assumed);
  TableReader& r = opts.reader();
  IdaOptions o;
  auto positive = [&](const std::string& key, double v) {
    if (!(v > 0.0)) r.fail(key, "expected a positive number, got " + std::to_string(v));
    return v;
  };
  // Below 1e-14 (~100 x the double's unit roundoff 1.1e-16) IDA cannot meet the tolerance and
  // stops at t = 0 ("too much accuracy requested").
  o.rtol = r.number_or("rtol", o.rtol, "a relative tolerance in [1e-14, 0.1]");
  if (!(o.rtol >= 1e-14 && o.rtol <= 0.1))
    r.fail("rtol",
           "expected a relative tolerance in [1e-14, 0.1] (below 1e-14 double precision cannot meet it)");
  // Displacements of the paper's scenes are O(0.01-1) m and speeds O(1) m/s: an absolute
  // tolerance 1e-3 x rtol keeps the relative test in charge except near zero crossings.
  o.atol = r.number_or("atol", 1e-3 * o.rtol, "an absolute tolerance in [1e-18, 1]");
  // Below 1e-18 (m, m/s: far under the roundoff of any state of size 1e-2) the error weights of
  // the states at rest overflow IDA's tests and it stops at t = 0; above 1 nothing is resolved.
  if (!(o.atol >= 1e-18 && o.atol <= 1.0))
    r.fail("atol",
           "expected an absolute tolerance in [1e-18, 1] (m, m/s), got " + fmt::format("{:g}", o.atol));
  if (r.has("kn")) {
    if (r.has("kn_factor")) r.fail("kn", "give either kn or kn_factor, not both");
    o.kn = positive("kn", r.number("kn", "a positive penalty stiffness (N/m)"));
  } else {
    o.kn_factor =
        positive("kn_factor", r.number_or("kn_factor", o.kn_factor, "a positive multiple of EA/le"));
  }
  const int damping_keys = r.has("cn") + r.has("damping_ratio") + r.has("restitution");
  if (damping_keys > 1) r.fail("cn", "give at most one of cn, damping_ratio and restitution");
  if (r.has("cn")) {
    o.cn = r.number("cn", "a dashpot coefficient >= 0 (N s/m)");
    if (*o.cn < 0.0) r.fail("cn", "expected a number >= 0");
  } else if (r.has("damping_ratio")) {
    o.damping_ratio = r.number("damping_ratio", "a damping ratio >= 0");
    if (*o.damping_ratio < 0.0) r.fail("damping_ratio", "expected a number >= 0");
  } else {
    o.restitution = r.number_or("restitution", o.restitution, "a restitution in (0, 1]");
    if (!(o.restitution > 0.0 && o.restitution <= 1.0))
      r.fail("restitution",
             "expected a number in (0, 1] (0 needs an infinite dashpot; use a "
             "small value such as 0.001)");
  }
  const double v_reg = 1e-3 * (v_scale > 0.0 ? v_scale : 1.0);
  o.friction_velocity =
      positive("friction_velocity",
               r.number_or("friction_velocity", v_reg, "a positive regularisation velocity (m/s)"));
  o.linear_solver = r.choice_or("linear_solver", "auto", {"auto", "dense", "klu"});
  if (r.has("output_step"))
    o.output_step = positive("output_step", r.number("output_step", "a positive output step (s)"));
  o.max_step = r.number_or("max_step", 0.0, "a maximum step (s), 0 for none");
  if (o.max_step < 0.0) r.fail("max_step", "expected a number >= 0");
  // The paper's runs merge phases separated by fewer than 3 open steps: the same in seconds.
  o.merge_gap =
      r.number_or("merge_gap", default_merge_gap(dt), "a time (s) below which two contact phases are merged");
  if (o.merge_gap < 0.0) r.fail("merge_gap", "expected a number >= 0");
  r.finish();
  return o;
}

}  // namespace beamimpact::ida
