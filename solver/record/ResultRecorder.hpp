#pragma once
/// @file ResultRecorder.hpp
/// @brief The one run recorder of every in-process method (paper, ida, exact): contact
/// statistics and intervals, energies, momentum drift, final velocities, effects and wall time.
/// Every key of summary.json that these quantities feed comes from here and from
/// write_outputs(); a method adds only what is its own (settings, solver counters, events).

#include <chrono>
#include <string>
#include <vector>

#include <solver/record/ContactStats.hpp>
#include <solver/record/SimulationResult.hpp>

namespace beamimpact {

/// @brief How a method samples its contacts, which the summary states (`contact_sampling`):
/// methods that step, step adaptively or know their events exactly are compared on that basis.
enum class ContactSampling {
  kFixedSteps,     ///< every time step of a fixed-step scheme (paper)
  kAdaptiveSteps,  ///< every accepted step of an adaptive integrator; switches located as events (ida)
  kExactEvents,    ///< output rows only; intervals, impulse and peaks from exact event times (exact)
};

/// @brief Accumulates one run into a SimulationResult.
///
/// Usage: construct at the start of the run (the wall clock starts), set_merge_rule(), then for
/// each step sample() every contact, track_momentum() where the method defines its drift, and
/// add_row() for every output row (summary.json's "loads" states the scene's [loads] and
/// the last row's load_work); finally finish() with each contact's kind, then overwrite
/// what the method knows better (exact event times) in the returned result.
class ResultRecorder {
 public:
  /// @param scene the scene run (contact names, number of contacts)
  /// @param method the registry name written into the summary ("paper", "ida", "exact")
  /// @param sampling how contacts are sampled (written into the summary)
  ResultRecorder(const Scene& scene, std::string method, ContactSampling sampling);

  /// @brief The result being filled: methods set dt, critical_dt, steps, assumed, extra here.
  SimulationResult& result() { return r_; }

  /// @brief Contact phases separated by less than merge_gap (s) are one interval; `rule` is the
  /// sentence written into the summary. Must be called before the first sample().
  void set_merge_rule(double merge_gap, const std::string& rule);

  /// @brief One contact sample at time t (s): forces R, tau (N) acting over a step dt (s).
  void sample(std::size_t contact, double t, double R, double tau, double dt, ContactState state) {
    stats_[contact].add(t, R, tau, dt, state);
  }

  /// @brief The real gap of a contact at time t (m): the gap from the deformed geometry
  /// (model/deformed_geometry.hpp, or an exact solution's own gap), never a method's contact
  /// rows. The summary reports the smallest one and when it occurred.
  void track_real_gap(std::size_t contact, double t, double gap) {
    if (gap < real_gap_[contact].first) real_gap_[contact] = {gap, t};
  }

  /// @brief Total linear momentum (N s) at time t (s); the drift is measured from the first value
  /// given, net of the loads' impulse since then: |p(t) - p(t0) - F (t - t0)| (set_load_force).
  void track_momentum(const Vec2& p, double t = 0.0);
  /// @brief The loads' net force on the bodies' momentum (N, constant in time: the scene's
  /// [loads]); its impulse is taken out of the momentum drift. Call before track_momentum.
  void set_load_force(const Vec2& F) { load_force_ = F; }

  /// @brief One output row: the first row's kinetic + strain energy is E0 (unless
  /// set_initial_energy() gave it), the last one's is the final energy. The row is kept for
  /// history.csv unless the scene says [output] history = false.
  void add_row(HistoryRow row);
  /// @brief E0 (J) from the initial conditions, for a method whose t = 0 row already carries a
  /// contact force in its velocity (the paper's V^0 when the contact closes in the first step).
  void set_initial_energy(double E0) {
    r_.energy_initial = E0;
    initial_energy_set_ = true;
  }

  /// @brief Centre-of-mass velocity (m/s) of a body at the end of the run.
  void set_final_velocity(const std::string& body, const Vec2& v) { r_.final_velocity[body] = v; }

  /// @brief Fills each contact's summary (names from the scene, kind as given, intervals,
  /// impulses, peaks, stick/slip counts) and the wall time, and hands the result over (the
  /// recorder is spent afterwards).
  /// @param kinds the kind of each scene contact, in scene order
  SimulationResult finish(const std::vector<ContactKind>& kinds);

  /// @brief The summary's description of a sampling kind.
  static const char* describe(ContactSampling s);

 private:
  const Scene& scene_;
  SimulationResult r_;
  std::vector<ContactStats> stats_;
  bool initial_energy_set_ = false;
  std::vector<std::pair<double, double>> real_gap_;  ///< per contact: smallest real gap (m) and its time (s)
  double load_work_final_ = 0.0;                     ///< J, the last row's load_work
  long rows_ = 0;                                    ///< output rows seen (kept or not: [output] history)
  bool momentum_started_ = false;
  Vec2 p0_{};
  double t0_ = 0.0;
  Vec2 load_force_{};  ///< N, the loads' net force on the momentum
  std::chrono::steady_clock::time_point wall0_;
};

}  // namespace beamimpact
