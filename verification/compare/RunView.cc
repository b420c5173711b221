#include <verification/compare/RunView.hpp>

#include <algorithm>
#include <cmath>

#include <solver/record/output_files.hpp>
#include <solver/schema/output_schema.hpp>
#include <solver/util/InputError.hpp>

namespace beamimpact::verification {
namespace {

/// j[key] when it is a number (a summary writes null for a value that is not finite).
std::optional<double> number_at(const nlohmann::json& j, const char* key) {
  if (!j.contains(key) || !j[key].is_number()) return std::nullopt;
  return j[key].get<double>();
}

/// v when it is finite (what summary.json would hold as a number).
std::optional<double> finite(double v) { return std::isfinite(v) ? std::optional<double>(v) : std::nullopt; }

bool is_pair_of_numbers(const nlohmann::json& v) {
  return v.is_array() && v.size() == 2 && v[0].is_number() && v[1].is_number();
}

/// summary.json contacts[k]'s impulse, intervals and interval impulses.
ContactFacts contact_facts(const nlohmann::json& c, const std::string& file, const std::string& key) {
  if (!c.is_object()) throw InputError(file, key, "expected a contact object");
  ContactFacts f;
  if (c.contains("impulse_normal")) {
    if (!c["impulse_normal"].is_number())
      throw InputError(file, key + "/impulse_normal", "expected a number (N s)");
    f.impulse_normal = c["impulse_normal"].get<double>();
  }
  if (c.contains("intervals")) {
    const nlohmann::json& iv = c["intervals"];
    if (!iv.is_array() || !std::all_of(iv.begin(), iv.end(), is_pair_of_numbers))
      throw InputError(file, key + "/intervals", "expected an array of [start, end] times (s)");
    f.intervals.emplace();
    for (const auto& p : iv) f.intervals->push_back({p[0].get<double>(), p[1].get<double>()});
  }
  if (c.contains("interval_impulses")) {  // used only when there is a number for every interval
    const nlohmann::json& J = c["interval_impulses"];
    if (J.is_array() && std::all_of(J.begin(), J.end(), [](const auto& x) { return x.is_number(); }))
      f.interval_impulses = J.get<std::vector<double>>();
  }
  f.friction = number_at(c, "friction");
  f.real_gap_min = number_at(c, "real_gap_min");
  return f;
}

}  // namespace

void RunView::read_summary(const nlohmann::json& s, const std::string& file, RunView& view) {
  if (!s.is_object()) throw InputError(file, "", "expected a JSON object");
  if (s.contains("scene_sha256")) {
    if (!s["scene_sha256"].is_string()) throw InputError(file, "scene_sha256", "expected a string");
    view.scene_sha256 = s["scene_sha256"].get<std::string>();
  }
  view.energy_initial = number_at(s, "energy_initial");
  view.momentum_drift_max = number_at(s, "momentum_drift_max");
  if (s.contains("contacts")) {
    if (!s["contacts"].is_array()) throw InputError(file, "contacts", "expected an array of contact objects");
    for (std::size_t k = 0; k < s["contacts"].size(); ++k)
      view.contacts_summary.push_back(contact_facts(s["contacts"][k], file, "contacts/" + std::to_string(k)));
  }
  if (s.contains("bodies")) {
    if (!s["bodies"].is_object()) throw InputError(file, "bodies", "expected an object of bodies by name");
    view.final_velocity.emplace();
    for (const auto& [name, b] : s["bodies"].items()) {
      if (!b.is_object() || (b.contains("final_velocity") && !is_pair_of_numbers(b["final_velocity"])))
        throw InputError(file, "bodies/" + name + "/final_velocity", "expected [vx, vy] (m/s)");
      auto& v = (*view.final_velocity)[name];
      if (b.contains("final_velocity"))
        v = {b["final_velocity"][0].get<double>(), b["final_velocity"][1].get<double>()};
    }
  }
}

RunView RunView::from_result(const Scene& scene, const SimulationResult& result, std::string label) {
  check_outputs_finite(scene, result);
  if (!scene.output.history)
    throw InputError(scene.file, "output.history",
                     "expected true: a comparison needs the run's history rows");
  const std::vector<std::string> names = history_columns(static_cast<int>(scene.contacts.size()));
  auto columns = std::make_shared<Columns>();
  for (const auto& n : names) (*columns)[n].reserve(result.history.size());
  for (const HistoryRow& row : result.history) {
    const std::vector<double> v = history_values(row);
    for (std::size_t i = 0; i < names.size(); ++i) (*columns)[names[i]].push_back(v[i]);
  }
  RunView view;
  view.label = std::move(label);
  view.columns = std::move(columns);
  for (const ContactSummary& c : result.contacts)
    view.contacts_summary.push_back(ContactFacts{c.impulse_normal, c.intervals, c.interval_impulses,
                                                 finite(c.friction), finite(c.real_gap_min)});
  view.final_velocity.emplace();
  for (const auto& [name, v] : result.final_velocity)
    (*view.final_velocity)[name] = std::array<double, 2>{v[0], v[1]};
  view.scene_sha256 = scene.sha256;
  view.energy_initial = finite(result.energy_initial);
  view.momentum_drift_max = finite(result.momentum_drift_max);
  return view;
}

const std::vector<double>& RunView::column(const std::string& name) const {
  const auto it = columns->find(name);
  if (it == columns->end())
    throw InputError(label + "/history.csv", name,
                     "expected this column (docs/scene-format.md), it is absent");
  return it->second;
}

int RunView::contact_count(const Columns& columns) {
  int n = columns.count("R") ? 1 : 0;
  while (columns.count(contact_column("R", n + 1))) ++n;
  return n;
}

double RunView::median_step(const std::vector<double>& t) {
  if (t.size() < 2) return 0.0;
  std::vector<double> d(t.size() - 1);
  for (std::size_t i = 1; i < t.size(); ++i) d[i - 1] = t[i] - t[i - 1];
  std::nth_element(d.begin(), d.begin() + static_cast<long>(d.size() / 2), d.end());
  return d[d.size() / 2];
}

}  // namespace beamimpact::verification
