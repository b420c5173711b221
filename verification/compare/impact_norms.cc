#include <verification/compare/impact_norms.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include <solver/schema/output_schema.hpp>

namespace beamimpact::verification {
namespace {

Norm missing(std::string name, std::string unit, std::string definition, std::string why) {
  return Norm{std::move(name), std::nullopt, std::move(unit), std::move(definition), {}, {}, std::move(why)};
}

/// A summary entry's own intervals (start only) and their impulses, when it lists one impulse
/// per interval; empty otherwise.
std::pair<std::vector<Interval>, std::vector<double>> own_impulses(const ContactFacts* s) {
  if (!s || !s->interval_impulses || !s->intervals || s->interval_impulses->size() != s->intervals->size())
    return {};
  std::pair<std::vector<Interval>, std::vector<double>> out;
  for (std::size_t i = 0; i < s->intervals->size(); ++i) {
    const double start = (*s->intervals)[i][0];
    out.first.push_back({start, start, 0, 0});
    out.second.push_back((*s->interval_impulses)[i]);
  }
  return out;
}

/// Total variation of R over consecutive rows inside each interval with R above threshold.
std::vector<double> variations(const RunView& h, const std::string& col, const std::vector<Interval>& iv,
                               double threshold) {
  const auto& t = h.t();
  const auto& R = h.column(col);
  std::vector<double> out;
  for (const Interval& i : iv) {
    double tv = 0.0;
    for (std::size_t r = 0; r + 1 < t.size(); ++r)
      if (t[r] >= i.start && t[r + 1] <= i.end && R[r] > threshold && R[r + 1] > threshold)
        tv += std::abs(R[r + 1] - R[r]);
    out.push_back(tv);
  }
  return out;
}

/// For each reference interval, the run's interval whose start is nearest (spurious extra
/// contacts of the run, counted by `impacts`, are then left out instead of shifting the pairs).
std::vector<std::size_t> nearest(const std::vector<Interval>& iva, const std::vector<Interval>& ivb) {
  std::vector<std::size_t> out;
  for (const Interval& b : ivb) {
    std::size_t best = 0;
    for (std::size_t i = 1; i < iva.size(); ++i)
      if (std::abs(iva[i].start - b.start) < std::abs(iva[best].start - b.start)) best = i;
    out.push_back(best);
  }
  return out;
}

/// max_i |x_pair(i) - y_i| / scale over the reference's entries y; scale = max_i |y_i| when 0.
Norm paired_relative(std::string name, const std::vector<double>& x, const std::vector<double>& y,
                     const std::vector<std::size_t>& pair, const std::string& def, double scale = 0.0) {
  const std::size_t n = x.empty() ? 0 : y.size();
  double num = 0.0, den = scale;
  for (std::size_t i = 0; i < n; ++i) {
    num = std::max(num, std::abs(x[pair[i]] - y[i]));
    if (scale == 0.0) den = std::max(den, std::abs(y[i]));
  }
  if (n == 0) return missing(std::move(name), "1", def, "no interval in the run or the reference");
  if (!(den > 0.0)) return missing(std::move(name), "1", def, "the reference's values are all zero");
  return Norm{std::move(name), num / den, "1", def, num, den, {}, true};  // a difference and its scale
}

}  // namespace

void add_impact_norms(Comparison& cmp, const RunView& a, const RunView& b, const ContactFacts* sa,
                      const ContactFacts* sb, const std::vector<Interval>& iva,
                      const std::vector<Interval>& ivb, int k, double threshold) {
  const std::string sfx = k <= 1 ? "" : "_" + std::to_string(k);
  const std::vector<std::size_t> pair = iva.empty() ? std::vector<std::size_t>{} : nearest(iva, ivb);
  for (const bool start : {true, false}) {
    const std::string name = (start ? "contact_starts" : "contact_ends") + sfx;
    const std::string def = std::string("max_i |t_a - t_b,i| (s), t_b,i = ") + (start ? "start" : "end") +
                            " of the reference's contact interval i, t_a = that of the run's interval "
                            "starting nearest to it";
    if (pair.empty() || ivb.empty()) {
      cmp.norms.push_back(missing(name, "s", def, "no interval in the run or the reference"));
    } else {
      double worst = 0.0;
      for (std::size_t i = 0; i < ivb.size(); ++i)
        worst = std::max(worst, start ? std::abs(iva[pair[i]].start - ivb[i].start)
                                      : std::abs(iva[pair[i]].end - ivb[i].end));
      cmp.norms.push_back({name, worst, "s", def, {}, {}, {}});
    }
  }
  {
    const std::string def =
        "max_i |J_a - J_b,i| / max_i |J_b,i|, J_b,i = normal impulse of the reference's "
        "contact interval i, J_a = that of the run's interval starting nearest to it "
        "(summary.json contacts[].interval_impulses: each method's own integral)";
    // Each method's own intervals (before the comparison's merging) carry its impulses.
    const auto [ia, ja] = own_impulses(sa);
    const auto [ib, jb] = own_impulses(sb);
    if (ja.empty() || jb.empty())
      cmp.norms.push_back(missing("impulse_per_impact" + sfx, "1", def,
                                  std::string(ja.empty() ? "the run" : "the reference") +
                                      " lists no interval_impulses (one per interval of its summary)"));
    else
      cmp.norms.push_back(paired_relative("impulse_per_impact" + sfx, ja, jb, nearest(ia, ib), def));
  }
  const std::string R = contact_column("R", k);
  const auto& Rb = b.column(R);
  const double peak = Rb.empty() ? 0.0 : *std::max_element(Rb.begin(), Rb.end());
  cmp.norms.push_back(paired_relative(
      "R_variation" + sfx, variations(a, R, iva, threshold), variations(b, R, ivb, threshold), pair,
      "max_i |TV_a - TV_b,i| / max R_b, TV = sum |R(r+1) - R(r)| over consecutive rows of a contact "
      "interval with R above the contact threshold (the oscillation of the force while closed); the run's "
      "interval is the one starting nearest to the reference's interval i",
      peak));
}

void add_energy_drift(Comparison& cmp, const RunView& a, const RunView& b) {
  const std::string def =
      "|dE_a - dE_b| / (n E_ref), dE = E(t1) - E(t0), E = kinetic + strain - load_work (J), n = the "
      "reference's impacts, E_ref = max_t (kinetic + strain) of the reference: energy drift per impact";
  double n = 0.0;
  for (const Norm& m : cmp.norms)
    if (m.name.rfind("impacts", 0) == 0 && m.b) n += *m.b;
  for (const RunView* h : {&a, &b})
    if (!h->has("kinetic") || !h->has("strain")) {
      cmp.norms.push_back(missing("energy_drift_per_impact", "1", def, h->label + " has no energy columns"));
      return;
    }
  if (n == 0.0) {
    cmp.norms.push_back(missing("energy_drift_per_impact", "1", def, "the reference has no impact"));
    return;
  }
  const auto energy = [&](const RunView& h, double t) {
    const std::vector<double> at = {t};
    double e = interpolate(h.t(), h.column("kinetic"), at)[0] + interpolate(h.t(), h.column("strain"), at)[0];
    if (h.has("load_work")) e -= interpolate(h.t(), h.column("load_work"), at)[0];
    return e;
  };
  const auto& Kb = b.column("kinetic");
  const auto& Sb = b.column("strain");
  double ref = 0.0;
  for (std::size_t i = 0; i < Kb.size(); ++i) ref = std::max(ref, Kb[i] + Sb[i]);
  if (!(ref > 0.0)) {
    cmp.norms.push_back(missing("energy_drift_per_impact", "1", def, "the reference has no energy"));
    return;
  }
  const double da = energy(a, cmp.t1) - energy(a, cmp.t0), db = energy(b, cmp.t1) - energy(b, cmp.t0);
  cmp.norms.push_back(
      {"energy_drift_per_impact", std::abs(da - db) / (n * ref), "1", def, da / n, db / n, {}});
}

bool known_impact_norm(const std::string& base) {
  return base == "contact_starts" || base == "contact_ends" || base == "impulse_per_impact" ||
         base == "R_variation";
}

}  // namespace beamimpact::verification
