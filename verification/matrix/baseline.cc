#include <verification/matrix/baseline.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>

#include <fmt/format.h>

#include <solver/util/InputError.hpp>

namespace beamimpact::verification {
namespace {

/// What a gate's value is: an observed order (higher is better), else an error or a Richardson
/// distance (lower is better).
bool higher_is_better(const nlohmann::json& gate) { return gate.contains("min_order"); }

std::string gate_key(const std::string& item, const nlohmann::json& gate) {
  const char* kind = gate.contains("min_order")    ? " (order)"
                     : gate.contains("richardson") ? " (richardson)"
                                                   : "";
  return item + " / " + gate.at("metric").get<std::string>() + kind;
}

struct Value {
  std::optional<double> value;
  bool higher_better = false;
};

/// Every gate of a norms.json-shaped "items" list by key. Items of one name (ladders that differ
/// in their reference) are told apart by their order: "NAME [2]" for the second.
std::map<std::string, Value> gate_values(const nlohmann::json& items, const std::string& file) {
  if (!items.is_array())
    throw InputError(file, "items", "expected a list of items (a baseline or a norms.json)");
  std::map<std::string, Value> out;
  std::map<std::string, int> seen;
  for (const auto& item : items) {
    std::string name = item.at("name").get<std::string>();
    if (const int n = ++seen[name]; n > 1) name += " [" + std::to_string(n) + "]";
    for (const auto& g : item.value("gates", nlohmann::json::array())) {
      Value v;
      if (g.contains("value") && g.at("value").is_number()) v.value = g.at("value").get<double>();
      v.higher_better = higher_is_better(g);
      out[gate_key(name, g)] = v;
    }
  }
  return out;
}

nlohmann::json gate_json(const GateResult& g) {
  nlohmann::json e{{"metric", g.gate.metric}, {"limit", g.limit()}};
  e["value"] = g.value ? nlohmann::json(*g.value) : nlohmann::json(nullptr);
  if (g.gate.tol) e["tol"] = *g.gate.tol;
  if (g.gate.min_order) e["min_order"] = *g.gate.min_order;
  if (g.gate.richardson) e["richardson"] = *g.gate.richardson;
  return e;
}

std::string number(const std::optional<double>& v) { return v ? fmt::format("{:.6g}", *v) : "none"; }

}  // namespace

nlohmann::json baseline_json(const std::string& version, const std::string& tier,
                             const std::vector<ItemResult>& items) {
  nlohmann::json j{{"baseline", "beamimpact verify --update-baseline"}, {"version", version}, {"tier", tier}};
  auto& arr = j["items"] = nlohmann::json::array();
  for (const ItemResult& i : items) {
    nlohmann::json gates = nlohmann::json::array();
    for (const GateResult& g : i.gates) gates.push_back(gate_json(g));
    arr.push_back({{"name", i.name}, {"gates", gates}});
  }
  return j;
}

BaselineComparison compare_baseline(const nlohmann::json& baseline, const std::string& file,
                                    const std::vector<ItemResult>& items, const BaselineNoise& noise) {
  if (!baseline.is_object() || !baseline.contains("items"))
    throw InputError(file, "items", "expected a baseline (verify --update-baseline) or a norms.json");
  const std::map<std::string, Value> before = gate_values(baseline.at("items"), file);
  const std::map<std::string, Value> now = gate_values(baseline_json("", "", items).at("items"), file);
  BaselineComparison c;
  c.noise = noise;
  for (const auto& [key, was] : before) {
    const auto it = now.find(key);
    if (it == now.end()) {
      c.not_run.push_back(key);
      continue;
    }
    const BaselineDelta d{key, was.value, it->second.value};
    if (!was.value) {  // a value where there was none is better; none then and none now, unchanged
      if (d.now)
        c.better.push_back(d);
      else
        ++c.unchanged;
      continue;
    }
    if (!d.now) {
      c.worse.push_back(d);
      continue;
    }
    const double allowed = std::max(noise.relative * std::abs(*was.value), noise.absolute);
    const double growth = was.higher_better ? *was.value - *d.now : *d.now - *was.value;
    if (growth > allowed)
      c.worse.push_back(d);
    else if (growth < -allowed)
      c.better.push_back(d);
    else
      ++c.unchanged;
  }
  for (const auto& [key, v] : now)
    if (!before.count(key)) c.added.push_back(key);
  return c;
}

std::string BaselineComparison::to_text() const {
  std::string s = fmt::format(
      "baseline: {} worse, {} better, {} within the noise (max({:g} x |value|, {:g})), {} new, {} not run\n",
      worse.size(), better.size(), unchanged, noise.relative, noise.absolute, added.size(), not_run.size());
  for (const auto& d : worse)
    s += fmt::format("  WORSE  {}: {} -> {}\n", d.gate, number(d.before), number(d.now));
  for (const auto& d : better)
    s += fmt::format("  better {}: {} -> {}\n", d.gate, number(d.before), number(d.now));
  return s;
}

nlohmann::json read_baseline(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw InputError(file.string(), "", "cannot read the baseline (write one with --update-baseline)");
  try {
    return nlohmann::json::parse(in);
  } catch (const nlohmann::json::parse_error& e) {
    throw InputError(file.string(), "", std::string("expected a JSON baseline: ") + e.what());
  }
}

}  // namespace beamimpact::verification
