#include <solver/record/output_files.hpp>

#include <cmath>
#include <fstream>
#include <stdexcept>

#include <fmt/format.h>

#include <beamimpact/version.hpp>
#include <solver/schema/output_schema.hpp>
#include <solver/util/write_file_atomic.hpp>

namespace beamimpact {
namespace {

void check_finite(double v, const char* what) {
  if (!std::isfinite(v)) throw std::runtime_error(fmt::format("non-finite {} in the result", what));
}

}  // namespace

std::vector<double> history_values(const HistoryRow& row) {
  std::vector<double> v{row.t};
  for (const ContactSample& c : row.contacts)
    v.insert(v.end(), {c.R, c.tau, c.gap, c.ua[0], c.ua[1], c.va[0], c.va[1], c.ub[0], c.ub[1], c.vb[0],
                       c.vb[1], static_cast<double>(static_cast<int>(c.state))});
  v.insert(v.end(),
           {row.kinetic, row.strain, row.dissipated, row.load_work, row.momentum[0], row.momentum[1]});
  return v;
}

nlohmann::json cost_json(const Scene& scene, const SimulationResult& r) {
  long elements = 0;  // the elastic bodies' elements (a rigid body's only place its nodes)
  for (const Body& b : scene.bodies)
    if (!b.rigid) elements += b.elements;
  const double ns = 1e9 * r.wall_seconds, steps = static_cast<double>(r.steps);
  nlohmann::json c = {{"dofs", r.dofs},
                      {"elements", elements},
                      {"steps", r.steps},
                      {"ns_per_dof_step", ns / (static_cast<double>(r.dofs) * steps)},
                      {"basis", "wall_seconds (set-up included) over DOFs x steps and elements x steps"}};
  if (elements > 0) c["ns_per_element_step"] = ns / (static_cast<double>(elements) * steps);
  return c;
}

nlohmann::json summary_json(const Scene& scene, const SimulationResult& r) {
  using nlohmann::json;
  json assumed = scene.assumed;
  for (const auto& [k, v] : r.assumed) assumed[k] = v;
  json bodies = json::object();
  for (const auto& [name, v] : r.final_velocity) bodies[name]["final_velocity"] = {v[0], v[1]};
  json contacts = json::array();
  for (const ContactSummary& c : r.contacts) {
    json j = {{"striker", c.striker},
              {"target", c.target},
              {"kind", to_string(c.kind)},
              {"friction", c.friction},
              {"intervals", c.intervals},
              {"impacts", c.intervals.size()},
              {"interval_impulses", c.interval_impulses},
              {"merge_rule", c.merge_rule},
              {"impulse_normal", c.impulse_normal},
              {"impulse_tangential", c.impulse_tangential},
              {"peak_R", c.peak_R},
              {"peak_R_excluding_closure", c.peak_R_excluding_closure},
              {"first_step_R", c.first_step_R},
              {"stick_steps", c.stick_steps},
              {"slip_steps", c.slip_steps},
              {"real_gap_min", c.real_gap_min},
              {"real_gap_min_time", c.real_gap_min_time}};
    j.update(c.extra);
    contacts.push_back(j);
  }
  json settings = {{"time",
                    {{"dt", scene.time.dt ? json(*scene.time.dt) : json("auto")},
                     {"fraction", scene.time.fraction},
                     {"end", scene.time.end},
                     {"output_every", scene.time.output_every},
                     {"allow_above_critical", scene.time.allow_above_critical},
                     {"allow_long_run", scene.time.allow_long_run}}},
                   {"model",
                    {{"mass", to_string(scene.model.mass)},
                     {"rotary_inertia", to_string(scene.model.rotary_inertia)},
                     {"kinematics", r.kinematics.empty() ? to_string(scene.model.kinematics) : r.kinematics},
                     {"rayleigh_mass", scene.model.rayleigh_mass},
                     {"rayleigh_stiffness", scene.model.rayleigh_stiffness}}},
                   {"output",
                    {{"history", scene.output.history},
                     {"fields", scene.output.fields},
                     {"field_format", to_string(scene.output.field_format)},
                     {"field_precision", to_string(scene.output.field_precision)}}}};
  settings.update(r.settings);
  json s = {{"scene", scene.name},
            {"scene_file", scene.file},
            {"scene_sha256", scene.sha256},
            {"description", scene.description},
            {"method", r.method},
            {"contact_sampling", r.contact_sampling},
            {"version", kVersion},
            {"dt", r.dt},
            {"steps", r.steps},
            {"end_time", r.end_time > 0.0 ? r.end_time : scene.time.end},  // the last row's time
            {"wall_seconds", r.wall_seconds},
            {"critical_dt", r.critical_dt},
            {"effects", r.effects},
            {"assumed", assumed},
            {"overrides", scene.overrides},
            {"settings", settings},
            {"energy_initial", r.energy_initial},
            {"energy_final", r.energy_final},
            {"momentum_drift_max", r.momentum_drift_max},
            {"bodies", bodies},
            {"contacts", contacts},
            {"units", summary_units()},
            {"complete", true}};
  if (r.dofs > 0 && r.steps > 0) s["cost"] = cost_json(scene, r);
  s.update(r.extra);
  return s;
}

void check_outputs_finite(const Scene& scene, const SimulationResult& r) {
  for (double v : {r.energy_initial, r.energy_final, r.momentum_drift_max, r.critical_dt})
    check_finite(v, "summary value");
  for (const ContactSummary& c : r.contacts)
    for (double v :
         {c.impulse_normal, c.impulse_tangential, c.peak_R, c.peak_R_excluding_closure, c.real_gap_min})
      check_finite(v, "contact summary value");
  const auto cols = history_columns(static_cast<int>(scene.contacts.size()));
  for (const HistoryRow& row : r.history) {
    const std::vector<double> values = history_values(row);
    for (std::size_t i = 0; i < values.size(); ++i)
      if (!std::isfinite(values[i]))
        throw std::runtime_error(fmt::format(
            "non-finite value of '{}' at t = {} s: the run diverged (a dt above the stability limit?)",
            cols[i], row.t));
  }
}

void write_outputs(const Scene& scene, const SimulationResult& r, const std::filesystem::path& dir) {
  std::filesystem::create_directories(dir);
  const auto summary = dir / "summary.json", history = dir / "history.csv";
  std::filesystem::remove(summary);  // a stale summary must not vouch for a new, failed run
  try {
    check_outputs_finite(scene, r);
    if (scene.output.history) {
      fmt::memory_buffer b;
      fmt::format_to(std::back_inserter(b), "{}\n",
                     fmt::join(history_columns(static_cast<int>(scene.contacts.size())), ","));
      for (const HistoryRow& row : r.history) {
        const std::vector<double> values = history_values(row);
        for (std::size_t i = 0; i < values.size(); ++i)
          fmt::format_to(std::back_inserter(b), "{}{}", i ? "," : "", values[i]);
        b.push_back('\n');
      }
      write_file_atomic(history, fmt::to_string(b));
    } else {
      std::filesystem::remove(history);  // [output] history = false: no rows were kept
    }
    write_file_atomic(summary, summary_json(scene, r).dump(2) + "\n");
  } catch (...) {
    std::filesystem::remove(history);
    throw;
  }
}

}  // namespace beamimpact
