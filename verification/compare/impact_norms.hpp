#pragma once
/// @file impact_norms.hpp
/// @brief Norms over each impact of a sequence (bouncing, re-contacts), where a total hides
/// what the benchmarks of many impacts tell apart: each contact's start time and impulse, the
/// oscillation of the force within each contact, and the energy drift per impact.

#include <vector>

#include <verification/compare/Comparison.hpp>
#include <verification/compare/RunView.hpp>
#include <verification/compare/series.hpp>

namespace beamimpact::verification {

/// @brief Adds, for contact k (suffix "_k" from k = 2):
/// each paired with the run's interval whose start is nearest to the reference's interval i
/// (spurious extra contacts of the run are counted by `impacts`, not paired):
///   contact_starts (s): max_i |start_a - start_b,i|;
///   impulse_per_impact (1): max_i |J_a - J_b,i| / max_i |J_b,i|, J from summary.json
///     contacts[].interval_impulses (each method's own integral over the interval);
///   R_variation (1): max_i |TV_a - TV_b,i| / max R_b (the reference's peak force), TV = sum of |R_{r+1} -
///   R_r| over
///     consecutive rows in the interval with R > threshold: the force's oscillation while closed.
/// @param cmp the comparison the norms are appended to
/// @param a the run; @param b the reference
/// @param sa the summary's facts of a's contact k (may be null); @param sb likewise of b
/// @param iva intervals of a; @param ivb intervals of b (as the compare merged them)
/// @param k contact number (1-based); @param threshold N, R above it counts as contact
void add_impact_norms(Comparison& cmp, const RunView& a, const RunView& b, const ContactFacts* sa,
                      const ContactFacts* sb, const std::vector<Interval>& iva,
                      const std::vector<Interval>& ivb, int k, double threshold);

/// @brief Adds energy_drift_per_impact (1): |dE_a - dE_b| / (n E_ref) with dE = E(t1) - E(t0),
/// E = kinetic + strain - load_work (the mechanical energy with the loads' potential), n the
/// reference's number of impacts over all contacts and E_ref = max_t (kinetic + strain) of b.
/// @param cmp the comparison (its t0, t1 and the "impacts" norms already added)
/// @param a the run; @param b the reference
void add_energy_drift(Comparison& cmp, const RunView& a, const RunView& b);

/// @brief True for a norm name this file produces ("contact_starts", "R_variation_2", ...).
bool known_impact_norm(const std::string& base);

}  // namespace beamimpact::verification
