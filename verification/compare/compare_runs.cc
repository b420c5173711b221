#include <verification/compare/compare_runs.hpp>

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include <solver/record/ContactIntervals.hpp>
#include <solver/schema/output_schema.hpp>
#include <solver/util/InputError.hpp>
#include <verification/compare/impact_norms.hpp>
#include <verification/compare/series.hpp>

namespace beamimpact::verification {
namespace {

/// Everything both histories are resampled onto.
struct Grid {
  std::vector<double> t;
};

Norm unavailable(std::string name, std::string unit, std::string definition, std::string why) {
  Norm n{std::move(name), std::nullopt, std::move(unit), std::move(definition), {}, {}, std::move(why)};
  return n;
}

/// Columns of one quantity (e.g. {"ua_x", "ua_y"}) of contact k; empty optional when absent.
std::optional<std::string> missing_column(const RunView& h, const std::vector<std::string>& cols) {
  for (const auto& c : cols)
    if (!h.has(c)) return c;
  return std::nullopt;
}

Series resample(const RunView& h, const std::vector<std::string>& cols, const Grid& g) {
  Series s;
  for (const auto& c : cols) s.push_back(interpolate(h.t(), h.column(c), g.t));
  return s;
}

/// Relative L2 and L-infinity errors of series a against reference b on the grid.
void add_series_norms(Comparison& cmp, const std::string& name, const Series& a, const Series& b,
                      const Grid& g, const std::string& what, bool want_l2 = true) {
  const Series d = difference(a, b);
  const double nb2 = l2_norm(g.t, b), nbi = linf_norm(b);
  const double nd2 = l2_norm(g.t, d), ndi = linf_norm(d);
  if (want_l2) {
    const std::string def = "sqrt(int |a-b|^2 dt) / sqrt(int |b|^2 dt) of " + what;
    if (nb2 > 0.0)
      cmp.norms.push_back({name + ".rel_l2", nd2 / nb2, "1", def, {}, {}, {}});
    else
      cmp.norms.push_back(
          unavailable(name + ".rel_l2", "1", def,
                      fmt::format("reference is identically zero (absolute L2 = {:.3e})", nd2)));
  }
  const std::string def = "max_t |a-b| / max_t |b| of " + what;
  if (nbi > 0.0)
    cmp.norms.push_back({name + ".rel_linf", ndi / nbi, "1", def, {}, {}, {}});
  else
    cmp.norms.push_back(
        unavailable(name + ".rel_linf", "1", def,
                    fmt::format("reference is identically zero (absolute max = {:.3e})", ndi)));
}

void add_vector_norms(Comparison& cmp, const RunView& a, const RunView& b, const Grid& g,
                      const std::string& base, int k, const std::string& what) {
  const std::vector<std::string> cols = {contact_column(base + "_x", k), contact_column(base + "_y", k)};
  const std::string name = contact_column(base, k);
  for (const RunView* h : {&a, &b}) {
    if (auto m = missing_column(*h, cols)) {
      const std::string why = h->label + "/history.csv has no column '" + *m + "'";
      cmp.norms.push_back(unavailable(name + ".rel_l2", "1", "relative L2 error of " + what, why));
      cmp.norms.push_back(unavailable(name + ".rel_linf", "1", "relative L-infinity error of " + what, why));
      cmp.notes.push_back(why);
      return;
    }
  }
  add_series_norms(cmp, name, resample(a, cols, g), resample(b, cols, g), g,
                   what + " (Euclidean norm of x, y)");
}

/// The summary's facts of contact k (1-based), or nullptr.
const ContactFacts* summary_contact(const RunView& h, int k) {
  if (h.contacts_summary.size() < static_cast<std::size_t>(k)) return nullptr;
  return &h.contacts_summary[static_cast<std::size_t>(k - 1)];
}

/// The contact facts of a run read from its history alone: its intervals (rows with R above
/// threshold, merged) and the trapezoid impulse of each (from the open row before to the open row
/// after, or the `impulse` column's rise over them), impulse_normal the whole running impulse I.
ContactFacts contact_from_history(const RunView& h, const std::vector<double>& R,
                                  const std::vector<double>& I, double threshold, double merge_gap) {
  ContactFacts c;
  c.impulse_normal = I.back();
  c.intervals.emplace();
  c.interval_impulses.emplace();
  for (const Interval& iv : contact_intervals(h.t(), R, threshold, merge_gap)) {
    const std::size_t lo = iv.first > 0 ? iv.first - 1 : 0, hi = std::min(iv.last + 1, I.size() - 1);
    c.intervals->push_back({iv.start, iv.end});
    c.interval_impulses->push_back(I[hi] - I[lo]);
  }
  return c;
}

/// Contact intervals from the summary (the method's own, event-accurate) or else from the rows;
/// either way, intervals closer than merge_gap seconds are one (the same rule for both runs, so
/// that counts do not depend on each method's merge rule in steps).
std::vector<Interval> intervals_of(const RunView& h, const ContactFacts* sc, const std::vector<double>& R,
                                   double threshold, double merge_gap) {
  if (sc && sc->intervals) {
    ContactIntervals merged(merge_gap);  // each of the method's intervals is a phase
    for (const auto& [start, end] : *sc->intervals) {
      merged.begin(start);
      merged.extend(end);
    }
    std::vector<Interval> out;
    for (const auto& [start, end] : merged.intervals()) out.push_back({start, end, 0, 0});
    return out;
  }
  return contact_intervals(h.t(), R, threshold, merge_gap);
}

/// Largest R over samples that are not closures: a closure is a sample in contact whose
/// predecessor is not (the same rule as solver/record/ContactStats: re-closures inside merged chatter count).
double peak_excluding_closure(const std::vector<double>& R, double threshold) {
  double p = 0.0;
  for (std::size_t r = 1; r < R.size(); ++r)
    if (R[r - 1] > threshold) p = std::max(p, R[r]);
  return p;
}

Norm relative_scalar(std::string name, double a, double b, std::string definition, std::string unit = "1") {
  Norm n{std::move(name), std::nullopt, std::move(unit), std::move(definition), a, b, {}};
  if (b != 0.0)
    n.value = std::abs(a - b) / std::abs(b);
  else
    n.unavailable = "reference value is zero";
  return n;
}

void add_contact_norms(Comparison& cmp, const RunView& a, const RunView& b, const Grid& g, int k,
                       const CompareOptions& options) {
  const std::string R = contact_column("R", k);
  const std::string sfx = k <= 1 ? "" : "_" + std::to_string(k);
  const auto& Ra = a.column(R);
  const auto& Rb = b.column(R);

  // Force itself: pointwise norms are harsh on impulsive forces (one-step shifts of a jump count
  // fully), hence also the running impulse and the window average below.
  add_series_norms(cmp, R, {interpolate(a.t(), Ra, g.t)}, {interpolate(b.t(), Rb, g.t)}, g,
                   "the contact force " + R + "(t)");
  // An optional cumulative column `impulse` (N s) is the method's own running impulse: adaptive
  // methods integrate between the rows what the rows cannot show (closure spikes).
  const std::string J = contact_column("impulse", k);
  const auto Ia = a.has(J) ? a.column(J) : running_integral(a.t(), Ra);
  const auto Ib = b.has(J) ? b.column(J) : running_integral(b.t(), Rb);
  add_series_norms(cmp, "I" + sfx, {interpolate(a.t(), Ia, g.t)}, {interpolate(b.t(), Ib, g.t)}, g,
                   "the running impulse I(t) = int_0^t " + R + " dt (column " + J +
                       " when a run has it, else the trapezoid rule on its rows)",
                   /*want_l2=*/false);
  add_series_norms(
      cmp, "Rw" + sfx, {window_average(a.t(), Ia, cmp.window, g.t)},
      {window_average(b.t(), Ib, cmp.window, g.t)}, g,
      fmt::format("the window-averaged force (I(t+W/2) - I(t-W/2))/W, W = {:.6g} s", cmp.window));

  // Scalars. Impulse and contact intervals come from summary.json when the method wrote them
  // (its own integral and event times: exact for adaptive and analytic methods, whose sampled
  // rows miss closure spikes), else from the rows; a side read from its history (options) from
  // the rows whatever its summary says.
  const double maxRb = *std::max_element(Rb.begin(), Rb.end());
  const double thr = options.threshold * maxRb;
  cmp.force_threshold = std::max(cmp.force_threshold, thr);
  const ContactFacts ha = contact_from_history(a, Ra, Ia, thr, cmp.merge_gap);
  const ContactFacts hb = contact_from_history(b, Rb, Ib, thr, cmp.merge_gap);
  const ContactFacts* sa = options.run_from_history ? &ha : summary_contact(a, k);
  const ContactFacts* sb = options.reference_from_history ? &hb : summary_contact(b, k);
  const double Ja = sa && sa->impulse_normal ? *sa->impulse_normal : Ia.back();
  const double Jb = sb && sb->impulse_normal ? *sb->impulse_normal : Ib.back();
  cmp.norms.push_back(relative_scalar("impulse" + sfx, Ja, Jb,
                                      "|J_a - J_b| / |J_b|, J = total normal impulse (N s): summary.json "
                                      "contacts[].impulse_normal, else (or for a side read from its history) "
                                      "int R dt over the rows"));
  const auto iva = intervals_of(a, sa, Ra, thr, cmp.merge_gap);
  const auto ivb = intervals_of(b, sb, Rb, thr, cmp.merge_gap);
  const std::string rule = fmt::format(
      "(intervals: summary.json contacts[].intervals, else rows with R > {:.3g} N; intervals closer than "
      "{:.6g} s merged)",
      thr, cmp.merge_gap);
  cmp.norms.push_back({"impacts" + sfx,
                       std::abs(static_cast<double>(iva.size()) - static_cast<double>(ivb.size())),
                       "count",
                       "|n_a - n_b|, n = number of contact intervals " + rule,
                       static_cast<double>(iva.size()),
                       static_cast<double>(ivb.size()),
                       {}});
  for (const bool start : {true, false}) {
    const std::string name = (start ? "contact_start" : "contact_end") + sfx;
    const std::string def = std::string("|t_a - t_b| (s), t = ") + (start ? "start" : "end") +
                            " of the first contact interval " + rule;
    if (iva.empty() || ivb.empty()) {
      cmp.norms.push_back(
          unavailable(name, "s", def, iva.empty() ? "no contact in the run" : "no contact in the reference"));
      continue;
    }
    const double ta = start ? iva[0].start : iva[0].end, tb = start ? ivb[0].start : ivb[0].end;
    cmp.norms.push_back({name, std::abs(ta - tb), "s", def, ta, tb, {}});
  }
  cmp.norms.push_back(relative_scalar(
      "peak_R" + sfx, peak_excluding_closure(Ra, thr), peak_excluding_closure(Rb, thr),
      "|P_a - P_b| / P_b, P = max R over the rows, every closure row (in contact after an open one) left out "
      "(N); "
      "from the rows, not summary.json, so that penalty methods' sub-step closure spikes do not count"));

  add_impact_norms(cmp, a, b, sa, sb, iva, ivb, k, thr);

  add_vector_norms(cmp, a, b, g, "ua", k, "the striker contact node displacement ua (m)");
  add_vector_norms(cmp, a, b, g, "ub", k, "the struck point displacement ub (m)");
  add_vector_norms(cmp, a, b, g, "va", k, "the striker contact node velocity va (m/s)");
  add_vector_norms(cmp, a, b, g, "vb", k, "the struck point velocity vb (m/s)");
}

void add_final_velocity(Comparison& cmp, const RunView& a, const RunView& b) {
  const std::string def =
      "max over bodies |v_a - v_b| / max over bodies |v_b|, v = centre-of-mass velocity at the end "
      "(summary.json bodies.*.final_velocity, m/s)";
  if (!b.final_velocity || !a.final_velocity) {
    cmp.norms.push_back(unavailable("final_velocity", "1", def, "summary.json has no 'bodies'"));
    return;
  }
  double num = 0.0, den = 0.0;
  for (const auto& [name, vb] : *b.final_velocity) {
    const auto va = a.final_velocity->find(name);
    if (va == a.final_velocity->end()) {
      cmp.norms.push_back(unavailable("final_velocity", "1", def, "run has no body '" + name + "'"));
      return;
    }
    if (!vb || !va->second) {
      cmp.norms.push_back(unavailable("final_velocity", "1", def,
                                      "bad summary.json: body '" + name + "' has no final_velocity"));
      return;
    }
    num = std::max(num, std::hypot((*va->second)[0] - (*vb)[0], (*va->second)[1] - (*vb)[1]));
    den = std::max(den, std::hypot((*vb)[0], (*vb)[1]));
  }
  Norm n{"final_velocity", std::nullopt, "1", def, num, den, {}, true};  // a difference and its scale
  if (den > 0.0)
    n.value = num / den;
  else
    n.unavailable = "reference bodies all at rest at the end";
  cmp.norms.push_back(n);
}

void add_energy(Comparison& cmp, const RunView& a, const RunView& b) {
  const std::string def =
      "|E_a(t1) - E_b(t1)| / E_b(first row), E = kinetic + strain (J), t1 = end of the overlap";
  for (const RunView* h : {&a, &b}) {
    if (auto m = missing_column(*h, {"kinetic", "strain"})) {
      cmp.norms.push_back(
          unavailable("energy_final", "1", def, h->label + "/history.csv has no column '" + *m + "'"));
      return;
    }
  }
  auto energy_at = [](const RunView& h, double t) {
    const auto k = interpolate(h.t(), h.column("kinetic"), {t});
    const auto s = interpolate(h.t(), h.column("strain"), {t});
    return k[0] + s[0];
  };
  const double e0 = b.column("kinetic").front() + b.column("strain").front();
  Norm n{"energy_final", std::nullopt, "1", def, energy_at(a, cmp.t1), energy_at(b, cmp.t1), {}};
  if (e0 > 0.0)
    n.value = std::abs(*n.a - *n.b) / e0;
  else
    n.unavailable = "reference starts with zero energy";
  cmp.norms.push_back(n);
}

}  // namespace

bool known_norm(const std::string& name) {
  static const std::vector<std::string> per_contact_series = {"R", "Rw", "ua", "ub", "va", "vb"};
  static const std::vector<std::string> per_contact_scalar = {"impulse", "impacts", "contact_start",
                                                              "contact_end", "peak_R"};
  if (name == "final_velocity" || name == "energy_final" || name == "energy_drift_per_impact") return true;
  std::string base = name, kind;
  if (const auto dot = name.find('.'); dot != std::string::npos) {
    base = name.substr(0, dot);
    kind = name.substr(dot + 1);
  }
  if (const auto us = base.rfind('_'); us != std::string::npos && us + 1 < base.size() &&
                                       base.find_first_not_of("0123456789", us + 1) == std::string::npos) {
    if (std::stoi(base.substr(us + 1)) < 2) return false;
    base = base.substr(0, us);  // "R_2" -> "R"
  }
  if (kind.empty())
    return std::find(per_contact_scalar.begin(), per_contact_scalar.end(), base) !=
               per_contact_scalar.end() ||
           known_impact_norm(base);
  if (base == "I") return kind == "rel_linf";
  const bool series =
      std::find(per_contact_series.begin(), per_contact_series.end(), base) != per_contact_series.end();
  return series && (kind == "rel_l2" || kind == "rel_linf");
}

Comparison compare_runs(const RunView& a, const RunView& b, const CompareOptions& options) {
  Comparison cmp;
  cmp.run = a.label;
  cmp.reference = b.label;
  cmp.t0 = std::max(a.t().front(), b.t().front());
  cmp.t1 = std::min(a.t().back(), b.t().back());
  if (!(cmp.t1 > cmp.t0)) {
    throw InputError(a.label, "t",
                     fmt::format("expected a time span overlapping the reference's [{}, {}] s, "
                                 "found [{}, {}] s",
                                 b.t().front(), b.t().back(), a.t().front(), a.t().back()));
  }
  const double ha = a.output_step(), hb = b.output_step();
  for (const RunView* h : {&a, &b})
    if (!(h->output_step() > 0.0))
      throw InputError(h->label, "t", "expected at least two rows in history.csv");
  const double fine = std::min(ha, hb), coarse = std::max(ha, hb);
  cmp.grid_step = options.grid_step != 0.0 ? options.grid_step : fine;
  cmp.window = options.window != 0.0 ? options.window : 10.0 * coarse;
  cmp.merge_gap = options.merge_gap != 0.0 ? options.merge_gap : default_merge_gap(coarse);
  const double span_b = b.t().back() - b.t().front();
  if (cmp.t1 - cmp.t0 < 0.99 * span_b) {
    cmp.notes.push_back(
        fmt::format("the runs overlap on [{:.6g}, {:.6g}] s only, the reference spans [{:.6g}, {:.6g}] s",
                    cmp.t0, cmp.t1, b.t().front(), b.t().back()));
  }
  // Bad options are bad input (CLI: compare --grid/--window/--merge/--threshold), not a silent default.
  for (const auto& [key, v] : {std::pair{"--grid", options.grid_step}, std::pair{"--window", options.window},
                               std::pair{"--merge", options.merge_gap}})
    if (v != 0.0 && !(v > 0.0 && std::isfinite(v)))
      throw InputError(a.label, key, fmt::format("expected a positive finite time (s), got {}", v));
  if (!(options.threshold >= 0.0 && options.threshold < 1.0))
    throw InputError(
        a.label, "--threshold",
        fmt::format("expected a fraction of the reference's largest R in [0, 1), got {}", options.threshold));
  constexpr double kMostGridPoints = 1e8;  // 0.8 GB per resampled series: beyond any output
  if ((cmp.t1 - cmp.t0) / cmp.grid_step > kMostGridPoints)
    throw InputError(a.label, "--grid",
                     fmt::format("expected a step giving at most {:g} grid points on [{:g}, {:g}] s, "
                                 "got {:g} s",
                                 kMostGridPoints, cmp.t0, cmp.t1, cmp.grid_step));
  const std::string &sha_a = a.scene_sha256, &sha_b = b.scene_sha256;
  if (!sha_a.empty() && !sha_b.empty() && sha_a != sha_b)
    cmp.notes.push_back("warning: the runs are of different scene files (scene_sha256 differs: " +
                        sha_a.substr(0, 12) + " vs " + sha_b.substr(0, 12) + ")");
  const Grid g{uniform_grid(cmp.t0, cmp.t1, cmp.grid_step)};

  const int na = a.contacts(), nb = b.contacts();
  if (na != nb)
    cmp.notes.push_back(fmt::format("the run has {} contact(s), the reference {}: compared the first {}", na,
                                    nb, std::min(na, nb)));
  for (int k = 1; k <= std::min(na, nb); ++k) add_contact_norms(cmp, a, b, g, k, options);
  if (options.run_from_history || options.reference_from_history)
    cmp.notes.push_back(fmt::format(
        "impulse, contact intervals and interval impulses of the {} from history.csv (its summary.json not "
        "trusted for them); final velocities from summary.json (the history has no centre-of-mass velocity)",
        options.run_from_history && options.reference_from_history ? "run and the reference"
        : options.run_from_history                                 ? "run"
                                                                   : "reference"));
  add_final_velocity(cmp, a, b);
  add_energy(cmp, a, b);
  add_energy_drift(cmp, a, b);
  return cmp;
}

}  // namespace beamimpact::verification
