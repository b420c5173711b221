#include <verification/compare/Comparison.hpp>

#include <cmath>

#include <fmt/format.h>

namespace beamimpact::verification {

const Norm* Comparison::find(const std::string& name) const {
  for (const auto& n : norms)
    if (n.name == name) return &n;
  return nullptr;
}

nlohmann::json Comparison::to_json() const {
  nlohmann::json j;
  j["run"] = run;
  j["reference"] = reference;
  j["overlap_s"] = {t0, t1};
  j["grid_step_s"] = grid_step;
  j["window_s"] = window;
  j["merge_gap_s"] = merge_gap;
  j["force_threshold_N"] = force_threshold;
  j["notes"] = notes;
  auto& arr = j["norms"] = nlohmann::json::array();
  for (const auto& n : norms) {
    nlohmann::json e{{"name", n.name}, {"unit", n.unit}, {"definition", n.definition}};
    e["value"] = n.value ? nlohmann::json(*n.value) : nlohmann::json(nullptr);
    if (n.a) e[n.difference ? "difference" : "run_value"] = *n.a;
    if (n.b) e[n.difference ? "scale" : "reference_value"] = *n.b;
    if (!n.unavailable.empty()) e["unavailable"] = n.unavailable;
    arr.push_back(e);
  }
  return j;
}

std::string Comparison::to_text() const {
  std::string s = fmt::format("run:       {}\nreference: {}\n", run, reference);
  s += fmt::format(
      "compared on [{:.6g}, {:.6g}] s, common grid step {:.6g} s (linear interpolation, "
      "trapezoid integrals)\nforce window W = {:.6g} s, contact: R > {:.3g} N, samples closer "
      "than {:.6g} s merged into one interval\n\n",
      t0, t1, grid_step, window, force_threshold, merge_gap);
  // Scalar norms: the run's value, the reference's and their difference; norms over series or
  // pairs (difference set): the largest difference and the scale the error divides it by.
  s += "error: the norm's value (relative: the difference over the scale, see its definition)\n";
  s += fmt::format("{:<26} {:>11} {:>6} {:>12} {:>12} {:>12} {:>12}\n", "norm", "error", "unit", "run value",
                   "ref. value", "|run - ref|", "scale");
  const auto g = [](const std::optional<double>& v) { return v ? fmt::format("{:.6g}", *v) : std::string(); };
  for (const auto& n : norms) {
    const std::string v = n.value ? fmt::format("{:.4e}", *n.value) : "n/a";
    std::string run_value, ref_value, diff, scale;
    if (n.difference) {
      diff = g(n.a);
      scale = g(n.b);
    } else {
      run_value = g(n.a);
      ref_value = g(n.b);
      if (n.a && n.b) diff = g(std::abs(*n.a - *n.b));
    }
    s += fmt::format("{:<26} {:>11} {:>6} {:>12} {:>12} {:>12} {:>12}\n", n.name, v, n.unit, run_value,
                     ref_value, diff, scale);
  }
  s += "\ndefinitions (a = run, b = reference):\n";
  for (const auto& n : norms) {
    s += fmt::format("  {}: {}{}\n", n.name, n.definition,
                     n.unavailable.empty() ? "" : "  [unavailable: " + n.unavailable + "]");
  }
  for (const auto& n : notes) s += "note: " + n + "\n";
  return s;
}

}  // namespace beamimpact::verification
