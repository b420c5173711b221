#include <solver/schema/output_schema.hpp>

namespace beamimpact {

const char* to_string(ContactState s) {
  switch (s) {
    case ContactState::kOpen: return "open";
    case ContactState::kStick: return "stick";
    case ContactState::kSlip: return "slip";
    default: return "closed";
  }
}

const char* to_string(ContactKind k) {
  switch (k) {
    case ContactKind::kEndToEnd: return "end_to_end";
    case ContactKind::kNodeToNode: return "node_to_node";
    default: return "node_to_surface";
  }
}

const std::vector<std::string>& contact_columns() {
  static const std::vector<std::string> c = {"R",    "tau",  "gap",  "ua_x", "ua_y", "va_x",
                                             "va_y", "ub_x", "ub_y", "vb_x", "vb_y", "state"};
  return c;
}

const std::vector<std::string>& model_columns() {
  static const std::vector<std::string> c = {"kinetic", "strain", "dissipated", "load_work", "px", "py"};
  return c;
}

std::string contact_column(std::string_view base, int k) {
  std::string name(base);
  if (k > 1) name += "_" + std::to_string(k);
  return name;
}

std::vector<std::string> history_columns(int n_contacts) {
  std::vector<std::string> cols = {"t"};
  for (int k = 1; k <= n_contacts; ++k)
    for (const std::string& c : contact_columns()) cols.push_back(contact_column(c, k));
  for (const std::string& c : model_columns()) cols.push_back(c);
  return cols;
}

const nlohmann::json& summary_units() {
  static const nlohmann::json u = {{"t", "s"},      {"R", "N"},          {"tau", "N"},
                                   {"gap", "m"},    {"u", "m"},          {"v", "m/s"},
                                   {"energy", "J"}, {"momentum", "N s"}, {"impulse", "N s"}};
  return u;
}

const std::vector<std::string>& summary_keys() {
  static const std::vector<std::string> k = {"scene",
                                             "scene_file",
                                             "scene_sha256",
                                             "description",
                                             "method",
                                             "version",
                                             "contact_sampling",
                                             "dt",
                                             "steps",
                                             "end_time",
                                             "wall_seconds",
                                             "critical_dt",
                                             "effects",
                                             "assumed",
                                             "overrides",
                                             "energy_initial",
                                             "energy_final",
                                             "momentum_drift_max",
                                             "bodies",
                                             "contacts",
                                             "units",
                                             "complete"};
  return k;
}

const std::vector<std::string>& contact_summary_keys() {
  static const std::vector<std::string> k = {"striker",
                                             "target",
                                             "kind",
                                             "friction",
                                             "intervals",
                                             "impacts",
                                             "merge_rule",
                                             "impulse_normal",
                                             "impulse_tangential",
                                             "peak_R",
                                             "peak_R_excluding_closure",
                                             "first_step_R",
                                             "stick_steps",
                                             "slip_steps",
                                             "real_gap_min",
                                             "real_gap_min_time"};
  return k;
}

const std::vector<std::string>& critical_step_keys() {
  namespace k = critical_step_key;
  static const std::vector<std::string> keys = {k::kMethod,         k::kBound,      k::kOmegaMax,
                                                k::kElementBoundDt, k::kOmegaLower, k::kMargin,
                                                k::kDtOverCritical};
  return keys;
}

nlohmann::json schema_json() {
  using nlohmann::json;
  json states = json::object();
  for (ContactState s :
       {ContactState::kOpen, ContactState::kStick, ContactState::kSlip, ContactState::kClosed})
    states[std::to_string(static_cast<int>(s))] = to_string(s);
  json kinds = json::array();
  for (ContactKind k : {ContactKind::kEndToEnd, ContactKind::kNodeToNode, ContactKind::kNodeToSurface})
    kinds.push_back(to_string(k));
  return {
      {"time_column", "t"},
      {"contact_columns", contact_columns()},
      {"model_columns", model_columns()},
      {"contact_suffix_rule", "contact 1: no suffix; contact k >= 2: '_k' appended (R_2, vb_y_3)"},
      {"state_values", states},
      {"contact_kinds", kinds},
      {"summary_keys", summary_keys()},
      {"contact_summary_keys", contact_summary_keys()},
      {"critical_step_keys", critical_step_keys()},
      {"units",
       {{"t", "s"},
        {"R", "N"},
        {"tau", "N"},
        {"gap", "m"},
        {"ua", "m"},
        {"ub", "m"},
        {"va", "m/s"},
        {"vb", "m/s"},
        {"kinetic", "J"},
        {"strain", "J"},
        {"dissipated", "J"},
        {"load_work", "J"},
        {"px", "N s"},
        {"py", "N s"}}},
      {"optional_columns", {{"impulse", "N s, cumulative normal impulse per contact (adaptive methods)"}}}};
}

}  // namespace beamimpact
