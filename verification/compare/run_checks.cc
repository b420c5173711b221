#include <verification/compare/run_checks.hpp>

#include <algorithm>
#include <cmath>

#include <solver/schema/output_schema.hpp>

namespace beamimpact::verification {
namespace {

Norm make(const std::string& name, const std::string& unit, const std::string& definition) {
  Norm n;
  n.name = name;
  n.unit = unit;
  n.definition = definition;
  return n;
}

/// Largest value of f(row) over the rows (0 when no row), for per-row health quantities.
template <typename F>
double max_over_rows(std::size_t rows, F f) {
  double m = 0.0;
  for (std::size_t i = 0; i < rows; ++i) m = std::max(m, f(i));
  return m;
}

/// E0 (J): summary.json's energy_initial (the initial conditions' energy), else the first row's
/// K + S (a method whose t = 0 row carries a step-0 contact force reports V^0 with it).
double initial_energy(const RunView& run, double first_row) { return run.energy_initial.value_or(first_row); }

/// Largest drop of a cumulative column below its running maximum.
double largest_drop(const std::vector<double>& d) {
  double high = d.empty() ? 0.0 : d.front(), drop = 0.0;
  for (double v : d) {
    high = std::max(high, v);
    drop = std::max(drop, high - v);
  }
  return drop;
}

void energy(const RunView& run, Comparison& c) {
  Norm band = make("energy_band", "1",
                   "max_t |K + S + D - W - E0| / E: kinetic + strain + dissipated - load work against the "
                   "initial energy, E = E0 + max_t |W| (W = 0 without loads or a load_work column)");
  Norm growth =
      make("energy_growth", "1", "max_t max(0, K + S + D - W - E0) / E: energy created (instability)");
  Norm drop = make("dissipated_decrease", "1",
                   "max_t (max_{t' <= t} D(t') - D(t)) / E: the dissipated energy never decreases (a "
                   "decrease is energy created and hides in K + S + D)");
  for (const char* col : {"kinetic", "strain", "dissipated"})
    if (!run.has(col))
      band.unavailable = growth.unavailable = drop.unavailable = std::string("no column ") + col;
  if (band.unavailable.empty()) {
    const auto& K = run.column("kinetic");
    const auto& S = run.column("strain");
    const auto& D = run.column("dissipated");
    const std::vector<double> zero(K.size(), 0.0);
    const auto& W = run.has("load_work") ? run.column("load_work") : zero;
    const double E0 = initial_energy(run, K[0] + S[0] - W[0]);
    const double E = E0 + max_over_rows(W.size(), [&](std::size_t i) { return std::abs(W[i]); });
    if (E > 0.0) {
      band.value = max_over_rows(K.size(),
                                 [&](std::size_t i) { return std::abs(K[i] + S[i] + D[i] - W[i] - E0) / E; });
      growth.value = max_over_rows(
          K.size(), [&](std::size_t i) { return std::max(0.0, K[i] + S[i] + D[i] - W[i] - E0) / E; });
      drop.value = largest_drop(D) / E;
    } else {
      band.unavailable = growth.unavailable = drop.unavailable = "initial energy and load work are zero";
    }
  }
  c.norms.push_back(band);
  c.norms.push_back(growth);
  c.norms.push_back(drop);
}

void contact_forces(const RunView& run, Comparison& c) {
  Norm tension =
      make("tension", "1", "max over contacts and rows of max(0, -R) / peak R: a contact never pulls");
  Norm cone = make("friction_cone", "1",
                   "max over contacts and rows of max(0, |tau| - mu R) / peak R: Coulomb's cone");
  const std::vector<ContactFacts>& contacts = run.contacts_summary;
  double t = 0.0, f = 0.0;
  for (int k = 1; k <= run.contacts(); ++k) {
    const auto& R = run.column(contact_column("R", k));
    const double peak = std::max(*std::max_element(R.begin(), R.end()), 1e-300);
    t = std::max(t, max_over_rows(R.size(), [&](std::size_t i) { return std::max(0.0, -R[i]); }) / peak);
    const std::string tau_col = contact_column("tau", k);
    const bool has_mu = static_cast<int>(contacts.size()) >= k && contacts[k - 1].friction.has_value();
    if (!run.has(tau_col) || !has_mu) {
      cone.unavailable = "no tau column or no contacts[].friction in summary.json";
      continue;
    }
    const double mu = *contacts[k - 1].friction;
    const auto& tau = run.column(tau_col);
    f = std::max(f, max_over_rows(R.size(), [&](std::size_t i) {
                      return std::max(0.0, std::abs(tau[i]) - mu * std::max(R[i], 0.0));
                    }) / peak);
  }
  tension.value = t;
  if (cone.unavailable.empty()) cone.value = f;
  c.norms.push_back(tension);
  c.norms.push_back(cone);
}

void geometry_and_momentum(const RunView& run, Comparison& c) {
  Norm pen = make("penetration", "m",
                  "max over contacts of max(0, -real_gap_min): real penetration, from the deformed geometry");
  double p = 0.0;
  for (const ContactFacts& k : run.contacts_summary) {
    if (!k.real_gap_min) {
      pen.unavailable = "no contacts[].real_gap_min in summary.json";
      break;
    }
    p = std::max(p, -*k.real_gap_min);
  }
  if (pen.unavailable.empty()) pen.value = p;
  c.norms.push_back(pen);

  Norm mom =
      make("momentum_drift", "1", "momentum_drift_max / |p(0)|: total momentum change (no support acting)");
  if (!run.has("px") || !run.has("py") || !run.momentum_drift_max) {
    mom.unavailable = "no px/py columns or momentum_drift_max";
  } else {
    const double p0 = std::hypot(run.column("px")[0], run.column("py")[0]);
    if (p0 > 0.0)
      mom.value = *run.momentum_drift_max / p0;
    else
      mom.unavailable = "zero initial momentum";
  }
  c.norms.push_back(mom);
}

}  // namespace

const std::vector<std::string>& check_names() {
  static const std::vector<std::string> n = {"energy_band",   "energy_growth", "dissipated_decrease",
                                             "tension",       "friction_cone", "penetration",
                                             "momentum_drift"};
  return n;
}

bool known_check(const std::string& name) {
  return std::find(check_names().begin(), check_names().end(), name) != check_names().end();
}

Comparison check_run(const RunView& run) {
  Comparison c;
  c.run = run.label;
  c.reference = "(none: health checks of one run)";
  c.t0 = run.t().front();
  c.t1 = run.t().back();
  energy(run, c);
  contact_forces(run, c);
  geometry_and_momentum(run, c);
  return c;
}

}  // namespace beamimpact::verification
