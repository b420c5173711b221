#include <verification/compare/StoredRun.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include <solver/schema/output_schema.hpp>
#include <solver/util/InputError.hpp>

namespace beamimpact::verification {
namespace {

std::vector<std::string> split_csv(const std::string& line) {
  std::vector<std::string> out;
  std::string cell;
  std::istringstream in(line);
  while (std::getline(in, cell, ',')) {
    // Tolerate spaces and a trailing '\r' (files edited on other systems).
    const auto b = cell.find_first_not_of(" \t\r");
    const auto e = cell.find_last_not_of(" \t\r");
    out.push_back(b == std::string::npos ? std::string() : cell.substr(b, e - b + 1));
  }
  if (!line.empty() && line.back() == ',') out.emplace_back();
  return out;
}

void check_times(const std::vector<double>& t, const std::string& file) {
  if (t.empty()) throw InputError(file, "", "expected at least one data row after the header");
  for (std::size_t i = 1; i < t.size(); ++i) {
    if (!(t[i] > t[i - 1])) {
      throw InputError(file, "t",
                       "expected strictly increasing times, row " + std::to_string(i + 2) +
                           " has t = " + std::to_string(t[i]) + " after " + std::to_string(t[i - 1]));
    }
  }
}

/// Refuses a null anywhere (no writer produces one; it would read as 0 or throw later).
void check_no_null(const nlohmann::json& j, const std::string& file, const std::string& where) {
  if (j.is_null()) throw InputError(file, where.empty() ? "/" : where, "expected a value, found null");
  if (j.is_object())
    for (const auto& [k, v] : j.items()) check_no_null(v, file, where + "/" + k);
  if (j.is_array())
    for (std::size_t i = 0; i < j.size(); ++i) check_no_null(j[i], file, where + "/" + std::to_string(i));
}

/// The keys the comparison reads, checked for their types once here (so that a wrong type is
/// bad input naming the key, not a JSON library error later).
void check_summary(const nlohmann::json& s, const std::string& file) {
  if (!s.is_object()) throw InputError(file, "", "expected a JSON object");
  check_no_null(s, file, "");
  auto fail = [&](const std::string& key, const std::string& what) {
    throw InputError(file, key, "expected " + what);
  };
  auto pair_of_numbers = [](const nlohmann::json& v) {
    return v.is_array() && v.size() == 2 && v[0].is_number() && v[1].is_number();
  };
  if (s.contains("scene_sha256") && !s["scene_sha256"].is_string()) fail("scene_sha256", "a string");
  if (s.contains("contacts")) {
    if (!s["contacts"].is_array()) fail("contacts", "an array of contact objects");
    for (std::size_t k = 0; k < s["contacts"].size(); ++k) {
      const auto& c = s["contacts"][k];
      const std::string key = "contacts/" + std::to_string(k);
      if (!c.is_object()) fail(key, "a contact object");
      if (c.contains("impulse_normal") && !c["impulse_normal"].is_number())
        fail(key + "/impulse_normal", "a number (N s)");
      if (c.contains("intervals")) {
        if (!c["intervals"].is_array()) fail(key + "/intervals", "an array of [start, end] times (s)");
        for (const auto& iv : c["intervals"])
          if (!pair_of_numbers(iv)) fail(key + "/intervals", "an array of [start, end] times (s)");
      }
    }
  }
  if (s.contains("bodies")) {
    if (!s["bodies"].is_object()) fail("bodies", "an object of bodies by name");
    for (const auto& [name, b] : s["bodies"].items())
      if (!b.is_object() || (b.contains("final_velocity") && !pair_of_numbers(b["final_velocity"])))
        fail("bodies/" + name + "/final_velocity", "[vx, vy] (m/s)");
  }
}

}  // namespace

StoredRun StoredRun::read(const std::filesystem::path& dir) {
  const std::string csv = (dir / "history.csv").string();
  const std::string sum = (dir / "summary.json").string();
  StoredRun h;
  h.label_ = dir.string();

  // summary.json is written last by every method: without it the run is not complete.
  std::ifstream sin(sum);
  if (!sin) throw InputError(sum, "", "expected summary.json of a complete run (not found or unreadable)");
  try {
    h.summary_ = nlohmann::json::parse(sin);
  } catch (const nlohmann::json::exception& e) {
    throw InputError(sum, "", std::string("expected valid JSON: ") + e.what());
  }
  check_summary(h.summary_, sum);

  std::ifstream in(csv);
  if (!in) throw InputError(csv, "", "expected history.csv (not found or unreadable)");
  std::string line;
  if (!std::getline(in, line)) throw InputError(csv, "", "expected a header line, the file is empty");
  const std::vector<std::string> names = split_csv(line);
  std::vector<std::vector<double>*> cols;
  for (const auto& n : names) {
    if (n.empty()) throw InputError(csv, "", "expected a column name in every header cell");
    if (h.columns_.count(n)) throw InputError(csv, n, "column appears twice in the header");
    cols.push_back(&h.columns_[n]);
  }
  for (const char* required : {"t", "R"}) {
    if (!h.columns_.count(required)) {
      throw InputError(csv, required,
                       "expected this column in the header (docs/scene-format.md), found: " + line);
    }
  }
  long row = 1;
  while (std::getline(in, line)) {
    ++row;
    if (line.empty() || line == "\r") continue;
    const auto cells = split_csv(line);
    if (cells.size() != names.size()) {
      throw InputError(csv, "",
                       "row " + std::to_string(row) + " has " + std::to_string(cells.size()) +
                           " cells, expected " + std::to_string(names.size()));
    }
    for (std::size_t c = 0; c < cells.size(); ++c) {
      char* end = nullptr;
      const double v = std::strtod(cells[c].c_str(), &end);
      if (cells[c].empty() || end != cells[c].c_str() + cells[c].size() || !std::isfinite(v)) {
        throw InputError(
            csv, names[c],
            "row " + std::to_string(row) + ": expected a finite number, found '" + cells[c] + "'");
      }
      cols[c]->push_back(v);
    }
  }
  check_times(h.columns_.at("t"), csv);
  return h;
}

StoredRun StoredRun::from_columns(std::map<std::string, std::vector<double>> columns, nlohmann::json summary,
                                  std::string label) {
  StoredRun h;
  h.label_ = std::move(label);
  if (!columns.count("t")) throw InputError(h.label_, "t", "expected a time column");
  for (const auto& [name, v] : columns) {
    if (v.size() != columns.at("t").size()) {
      throw InputError(h.label_, name, "expected as many values as times");
    }
  }
  h.columns_ = std::move(columns);
  h.summary_ = std::move(summary);
  check_times(h.columns_.at("t"), h.label_);
  return h;
}

const std::vector<double>& StoredRun::column(const std::string& name) const {
  const auto it = columns_.find(name);
  if (it == columns_.end()) {
    throw InputError(label_ + "/history.csv", name,
                     "expected this column (docs/scene-format.md), it is absent");
  }
  return it->second;
}

int StoredRun::contacts() const { return RunView::contact_count(columns_); }

double StoredRun::output_step() const { return RunView::median_step(t()); }

RunView StoredRun::view() const {
  RunView v;
  v.label = label_;
  v.columns = std::shared_ptr<const Columns>(std::shared_ptr<const void>(), &columns_);  // borrowed
  RunView::read_summary(summary_, label_, v);
  return v;
}

}  // namespace beamimpact::verification
