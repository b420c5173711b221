#include <verification/matrix/ladder.hpp>

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include <solver/scene/scene_io.hpp>
#include <verification/matrix/evaluate.hpp>

namespace beamimpact::verification {

LadderPlan plan_ladder(const jobs::JobSpec& base, const Method& method, int rungs) {
  LadderPlan p;
  const std::optional<double> dt = load_scene(base.scene).time.dt;  // empty: "auto"
  const bool mesh = method.accepts.mesh_factor, step = method.accepts.dt && dt.has_value();
  if (!mesh && !step) {
    p.why = method.accepts.dt ? "no ladder: the scene's step is automatic and the method takes no mesh factor"
                              : "no ladder: the method accepts neither a time step nor a mesh factor";
    return p;
  }
  p.kind = mesh && step ? "mesh+dt" : mesh ? "mesh" : "dt";
  p.why = mesh && step
              ? fmt::format("elements x2 and dt / 2 a rung from dt = {:g} s (Courant number kept)", *dt)
          : mesh ? "elements x2 a rung, the step following from the scene"
                 : fmt::format(
                       "dt / 2 a rung from {:g} s at the scene's mesh: the limit is the method's "
                       "semi-discrete answer, its mesh error stays",
                       *dt);
  for (int k = 0; k < rungs; ++k) {
    jobs::JobSpec s = base;
    const int factor = 1 << k;
    if (k > 0 && mesh) s.mesh = std::to_string(factor);
    if (k > 0 && step) s.dt = *dt / factor;
    p.rungs.push_back(s);
  }
  return p;
}

LadderResult ladder_limit(const std::vector<double>& q, double agree) {
  LadderResult r;
  r.values = q;
  const std::size_t n = q.size();
  if (n < 3) {
    r.why_not = "fewer than three rungs";
    return r;
  }
  double spread = 0.0, scale = 0.0;
  for (double v : q) {
    spread = std::max(spread, std::abs(v - q.back()));
    scale = std::max(scale, std::abs(v));
  }
  if (spread <= std::max(kAgreement * scale, agree)) {  // as good at every resolution
    r.limit = q.back();
    r.uncertainty = spread;
    return r;
  }
  const auto lim = richardson_limit(q[n - 3], q[n - 2], q[n - 1], kLadderRatio);
  if (!lim) {
    r.order = observed_order(std::abs(q[n - 3] - q[n - 2]), std::abs(q[n - 2] - q[n - 1]), kLadderRatio);
    r.why_not = "the rungs' differences do not shrink monotonically (no asymptotic range)";
    return r;
  }
  r.order = lim->second;
  if (*r.order < kLeastOrder) {
    r.why_not = fmt::format("observed order {:.3g} below {:g}", *r.order, kLeastOrder);
    return r;
  }
  r.limit = lim->first;
  // The limit at the whole order nearest the observed one (1 at least): how far the limit moves
  // if the rungs' order is the scheme's formal order rather than the observed one.
  const double whole = std::max(1.0, std::round(*r.order));
  const double at_whole = q[n - 1] - (q[n - 2] - q[n - 1]) / (std::pow(kLadderRatio, whole) - 1.0);
  r.uncertainty = std::abs(lim->first - at_whole);
  if (n >= 4)
    if (const auto before = richardson_limit(q[n - 4], q[n - 3], q[n - 2], kLadderRatio))
      r.uncertainty = std::max(*r.uncertainty, std::abs(lim->first - before->first));
  return r;
}

}  // namespace beamimpact::verification
