#include <api/output_rules.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <solver/record/ContactIntervals.hpp>
#include <solver/schema/output_schema.hpp>
#include <solver/util/sha256.hpp>

namespace beamimpact {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;

std::string read_text(const fs::path& f) {
  std::ifstream in(f, std::ios::binary);
  std::ostringstream os;
  os << in.rdbuf();
  return os.str();
}

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r");
  const auto e = s.find_last_not_of(" \t\r");
  return b == std::string::npos ? std::string() : s.substr(b, e - b + 1);
}

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> out;
  std::istringstream in(line);
  for (std::string cell; std::getline(in, cell, ',');) out.push_back(trim(cell));
  if (!line.empty() && line.back() == ',') out.emplace_back();
  return out;
}

/// The records of every rule, checked in order.
class Verdicts {
 public:
  bool operator()(const std::string& rule, const fs::path& file, bool ok, const std::string& message) {
    out.push_back({rule, file.string(), ok, ok ? "" : message});
    return ok;
  }
  std::vector<OutputVerdict> out;
};

/// The summary's required keys (docs/protocol.md) and their types; "" when all hold.
std::string summary_problem(const Json& s, std::size_t contacts) {
  if (!s.is_object()) return "expected a JSON object";
  for (const char* k : {"method", "scene_sha256"})
    if (!s.contains(k) || !s[k].is_string()) return fmt::format("expected \"{}\" as a string", k);
  for (const char* k : {"dt", "steps", "wall_seconds", "end_time"})
    if (!s.contains(k) || !s[k].is_number()) return fmt::format("expected \"{}\" as a number", k);
  if (!s.contains("contacts") || !s["contacts"].is_array() || s["contacts"].size() != contacts)
    return fmt::format("expected \"contacts\" as an array of {} object(s), one per scene contact", contacts);
  for (const auto& c : s["contacts"]) {
    if (!c.is_object() || !c.contains("impulse_normal") || !c["impulse_normal"].is_number() ||
        !c.contains("intervals") || !c["intervals"].is_array())
      return "expected each contact to give \"impulse_normal\" (N s) and \"intervals\" ([[start, end], ...] "
             "s)";
    for (const auto& iv : c["intervals"])
      if (!iv.is_array() || iv.size() != 2 || !iv[0].is_number() || !iv[1].is_number())
        return "expected each contact's \"intervals\" as [[start, end], ...] (s)";
    if (c.contains("interval_impulses") &&
        (!c["interval_impulses"].is_array() || c["interval_impulses"].size() != c["intervals"].size() ||
         !std::all_of(c["interval_impulses"].begin(), c["interval_impulses"].end(),
                      [](const Json& j) { return j.is_number(); })))
      return "expected \"interval_impulses\" as one number (N s) per interval of \"intervals\"";
  }
  return "";
}

/// Units in values: the run ends at the scene's end time in seconds (a run in milliseconds ends
/// 1000 times later) within one step of it.
std::string units_problem(const Json& s, const HistoryTable& h, const OutputExpectation& e, double h_max) {
  for (const auto& [key, unit] : summary_units().items())
    if (!s.contains("units") || !s["units"].is_object() || !s["units"].contains(key) ||
        s["units"][key] != unit)
      return "expected \"units\": " + summary_units().dump();
  const double dt = s["dt"].get<double>(), end = s["end_time"].get<double>(),
               t_last = h.columns.at("t").back();
  const double slack = 1.0001 * std::max(h_max, std::abs(dt)) + 1e-12 * e.end_time;
  if (!(dt > 0.0 && dt <= e.end_time * 1.0001))
    return fmt::format("expected \"dt\" in s (0 < dt <= the scene's end, {:.9g} s), got {:.9g}", e.end_time,
                       dt);
  if (!(std::abs(end - e.end_time) <= slack))
    return fmt::format(
        "expected \"end_time\" in s: the scene's time.end = {:.9g} s within one step ({:.3g} s), "
        "got {:.9g}",
        e.end_time, slack, end);
  if (!(std::abs(t_last - end) <= slack))
    return fmt::format(
        "expected history.csv's last t in s: end_time = {:.9g} s within one step ({:.3g} s), got "
        "{:.9g}",
        end, slack, t_last);
  return "";
}

/// One contact interval of the rows: its first and last row in contact (R > 0).
struct RowInterval {
  double start, end;
  std::size_t first, last;
};

/// The rows' intervals of R > 0, phases closer than `gap` merged (ContactIntervals' rule).
std::vector<RowInterval> row_intervals(const std::vector<double>& t, const std::vector<double>& R,
                                       double gap) {
  ContactIntervals merged(gap);
  std::vector<RowInterval> out;
  for (std::size_t r = 0; r < t.size(); ++r) {
    if (!(R[r] > 0.0)) continue;
    if (r == 0 || !(R[r - 1] > 0.0)) {
      if (merged.begin(t[r])) out.push_back({t[r], t[r], r, r});
    } else {
      merged.extend(t[r]);
    }
    out.back().end = t[r];
    out.back().last = r;
  }
  return out;
}

/// One contact's rows as the consistency rule reads them.
struct Rows {
  const std::vector<double>& t;  ///< s
  const std::vector<double>& R;  ///< N
  double h;                      ///< s, the largest row spacing
  bool every_step;               ///< a row every step (h <= the summary's dt): R known at every step
  double jitter;  ///< s, the largest change between consecutive row spacings (the last left out)
};

/// The rows' resolution of an integral of R over rows lo..hi (N s). A row every step: the spread
/// of the conventions on these very rows, |L - T| = |Rt - T| = |L - Rt| / 2 with L = sum R_k h_k over
/// the step after each row, Rt over the step before and T the trapezoid rule, plus half a step of
/// the end rows' R (a sum over every row), plus the rows' time jitter times R's variation (times
/// written rounded), plus the rounding of the sum ((n + 8) ulps of sum |R| h).
/// Rows sparser than the steps (R between rows unseen): h max(max R, half R's variation).
double resolution(const Rows& rows, std::size_t lo, std::size_t hi) {
  const auto& t = rows.t;
  const auto& R = rows.R;
  double left = 0.0, right = 0.0, sum_abs = 0.0, peak = std::abs(R[lo]), tv = 0.0;
  for (std::size_t r = lo + 1; r <= hi; ++r) {
    const double hk = t[r] - t[r - 1];
    left += R[r - 1] * hk;
    right += R[r] * hk;
    sum_abs += std::abs(R[r]) * hk;
    peak = std::max(peak, std::abs(R[r]));
    tv += std::abs(R[r] - R[r - 1]);
  }
  const double rounding = static_cast<double>(hi - lo + 8) * std::numeric_limits<double>::epsilon() *
                          (sum_abs + std::abs(R[lo]) * rows.h);
  if (!rows.every_step) return rows.h * std::max(peak, 0.5 * tv) + rounding;
  // A row time written off by d moves the trapezoid sum by at most d times R's variation.
  return 0.5 * std::abs(left - right) + 0.5 * rows.h * (std::abs(R[lo]) + std::abs(R[hi])) +
         rows.jitter * tv + rounding;
}

/// Trapezoid integral of R over rows lo..hi.
double trapezoid(const std::vector<double>& t, const std::vector<double>& R, std::size_t lo, std::size_t hi) {
  double J = 0.0;
  for (std::size_t r = lo + 1; r <= hi && r < t.size(); ++r) J += 0.5 * (R[r] + R[r - 1]) * (t[r] - t[r - 1]);
  return J;
}

/// The summary's intervals merged by `gap` with their impulses summed (empty impulses when the
/// contact lists none); "" or why they cannot be read.
std::string summary_intervals(const Json& c, double gap, std::vector<std::array<double, 2>>& iv,
                              std::vector<double>& J) {
  ContactIntervals merged(gap);
  const bool has_J = c.contains("interval_impulses");
  double last_end = -std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < c["intervals"].size(); ++i) {
    const double a = c["intervals"][i][0].get<double>(), b = c["intervals"][i][1].get<double>();
    if (a < last_end || b < a)
      return fmt::format("interval {} [{:.9g}, {:.9g}] s is not in time order", i, a, b);
    last_end = b;
    const bool opened = merged.begin(a);
    merged.extend(b);
    if (has_J) {
      if (opened) J.push_back(0.0);
      J.back() += c["interval_impulses"][i].get<double>();
    }
  }
  iv = merged.intervals();
  return "";
}

/// The summary's (merged) intervals against the rows' of one contact: every row interval lies in
/// a summary interval; every summary interval longer than a row spacing holds row intervals, the
/// first starting within one row spacing of its start, the last ending within one row spacing
/// plus the merge gap of its end; its impulse (when listed) is the rows' integral over it. With
/// rows sparser than the steps, a contact shorter than a row spacing may fall between rows (its
/// impulse is in the total, checked before). "" when all hold.
std::string interval_problem(const std::string& label, const std::string& col,
                             const std::vector<std::array<double, 2>>& iv, const std::vector<double>& J,
                             const Rows& data, const std::vector<RowInterval>& rows, double gap) {
  const auto& t = data.t;
  const auto& R = data.R;
  const double h = data.h, slack = 1.0001 * h;
  std::vector<bool> used(rows.size(), false);
  for (std::size_t i = 0; i < iv.size(); ++i) {
    std::size_t first = rows.size(), last = 0;
    for (std::size_t r = 0; r < rows.size(); ++r)
      if (rows[r].end >= iv[i][0] - slack && rows[r].start <= iv[i][1] + slack + gap) {
        first = std::min(first, r);
        last = r;
        used[r] = true;
      }
    if (first == rows.size()) {
      if (!data.every_step && iv[i][1] - iv[i][0] < h)
        continue;  // shorter than a row spacing: it may fall between rows
      return fmt::format(
          "{}.intervals[{}] = [{:.9g}, {:.9g}] s in summary.json: no contact ({} > 0) in "
          "history.csv there; expected rows in contact within one row spacing ({:.3g} s)",
          label, i, iv[i][0], iv[i][1], col, h);
    }
    if (std::abs(iv[i][0] - rows[first].start) > slack || std::abs(iv[i][1] - rows[last].end) > slack + gap)
      return fmt::format(
          "{}.intervals[{}] = [{:.9g}, {:.9g}] s in summary.json, [{:.9g}, {:.9g}] s in "
          "history.csv ({} > 0); expected the start within one row spacing ({:.3g} s), the end "
          "within one row spacing plus the merge gap of {} row spacings ({:.3g} s)",
          label, i, iv[i][0], iv[i][1], rows[first].start, rows[last].end, col, h,
          merge_gap_of(kMergeSteps, 1.0), gap);
    if (J.empty()) continue;
    const std::size_t lo = rows[first].first > 0 ? rows[first].first - 1 : 0;
    const std::size_t hi = std::min(rows[last].last + 1, t.size() - 1);
    const double Ji = trapezoid(t, R, lo, hi), tol = resolution(data, lo, hi);
    if (std::abs(J[i] - Ji) > tol)
      return fmt::format(
          "{}.interval_impulses[{}] = {:.9g} N s in summary.json, {:.9g} N s in history.csv (the "
          "trapezoid integral of {} over it); expected the same within the rows' resolution "
          "{:.3g} N s",
          label, i, J[i], Ji, col, tol);
  }
  for (std::size_t r = 0; r < rows.size(); ++r)
    if (!used[r])
      return fmt::format(
          "history.csv shows {} in contact ({} > 0) over [{:.9g}, {:.9g}] s; summary.json {}.intervals "
          "lists no interval there",
          label, col, rows[r].start, rows[r].end, label);
  return "";
}

/// summary.json against history.csv for contact k (1-based): impulse, intervals, interval impulses.
void check_contact(Verdicts& check, const fs::path& dir, const Json& c, const HistoryTable& h, int k,
                   double h_max, double dt) {
  const std::string col = contact_column("R", k), label = fmt::format("contacts[{}]", k - 1);
  const fs::path sum = dir / "summary.json";
  const auto& t = h.columns.at("t");
  const auto& R = h.columns.at(col);
  const std::string Jcol = contact_column("impulse", k);
  const double J_rows = h.columns.count(Jcol) ? h.columns.at(Jcol).back() : trapezoid(t, R, 0, t.size() - 1);
  const double J_sum = c["impulse_normal"].get<double>();
  double jitter = 0.0;
  for (std::size_t r = 2; r + 1 < t.size(); ++r)
    jitter = std::max(jitter, std::abs((t[r] - t[r - 1]) - (t[r - 1] - t[r - 2])));
  const Rows rows{t, R, h_max, h_max <= 1.0001 * dt, jitter};
  const double tol = resolution(rows, 0, t.size() - 1);
  if (!check(
          "consistency", sum, std::abs(J_sum - J_rows) <= tol,
          fmt::format("{}.impulse_normal = {:.9g} N s in summary.json, {:.9g} N s in history.csv ({}); "
                      "expected the same within the rows' resolution {:.3g} N s ({})",
                      label, J_sum, J_rows,
                      h.columns.count(Jcol) ? "its last " + Jcol : "the trapezoid integral of " + col, tol,
                      rows.every_step ? "a row every step: the spread of the time conventions on these rows"
                                      : "rows sparser than the steps: the largest row spacing x max(max " +
                                            col + ", half its variation)")))
    return;
  std::vector<std::array<double, 2>> iv;
  std::vector<double> J;
  // The rows merge phases closer than the default merge gap of a row spacing (ContactIntervals.hpp). A row
  // can show a phase one spacing longer at each end than the steps did (a row's R stands for the step after
  // its time: docs/protocol.md), so two phases the method's own rule kept apart can merge in the
  // rows: the summary's intervals are merged with two row spacings more before they are compared.
  const double gap = default_merge_gap(h_max);
  if (const std::string why = summary_intervals(c, gap + 2.0 * h_max, iv, J); !why.empty()) {
    check("consistency", sum, false, label + ".intervals: " + why);
    return;
  }
  const std::string why = interval_problem(label, col, iv, J, rows, row_intervals(t, R, gap), gap);
  check("consistency", sum, why.empty(), why);
}

/// The rules that need both files read: complete, finite, times, keys, units, sha256, consistency.
void check_read(Verdicts& check, const fs::path& dir, const Json& s, const HistoryTable& h,
                const OutputExpectation& e) {
  const fs::path sum = dir / "summary.json", csv = dir / "history.csv";
  check("complete", sum, s.is_object() && s.contains("complete") && s["complete"] == true,
        "expected \"complete\": true (a run that did not finish exits 3 and leaves no summary.json)");
  const bool finite = check("finite", csv, h.problem.empty(), h.problem);
  const bool has_t = h.columns.count("t") && !h.columns.at("t").empty();
  std::string times = has_t ? "" : "expected a column t with at least one row";
  double h_max = 0.0;
  if (has_t) {
    const auto& t = h.columns.at("t");
    for (std::size_t r = 1; r < t.size() && times.empty(); ++r) {
      if (!(t[r] > t[r - 1]))
        times = fmt::format("expected strictly increasing times: row {} has t = {:.17g} s after {:.17g} s",
                            r + 2, t[r], t[r - 1]);
      h_max = std::max(h_max, t[r] - t[r - 1]);
    }
  }
  const bool increasing = check("times", csv, times.empty(), times);
  const std::string keys = summary_problem(s, e.contacts);
  if (!check("summary keys", sum, keys.empty(), keys) || !finite || !increasing) return;
  check("units", sum, units_problem(s, h, e, h_max).empty(), units_problem(s, h, e, h_max));
  const std::string sha = sha256_hex(read_text(e.scene_file));
  check("scene sha256", sum, s["scene_sha256"] == sha,
        "expected \"scene_sha256\": \"" + sha + "\" (the sha256 of the scene file " + e.scene_file.string() +
            "), got \"" + s["scene_sha256"].get<std::string>() + "\"");
  std::size_t before = check.out.size();
  for (int k = 1; k <= static_cast<int>(e.contacts); ++k) {
    if (!h.columns.count(contact_column("R", k))) {
      check("consistency", csv, false,
            "expected a column " + contact_column("R", k) + " (one R per contact)");
      continue;
    }
    check_contact(check, dir, s["contacts"][static_cast<std::size_t>(k - 1)], h, k, h_max,
                  s["dt"].get<double>());
  }
  if (check.out.size() == before) check("consistency", sum, true, "");
}

}  // namespace

const std::vector<std::pair<std::string, std::string>>& output_rules() {
  static const std::vector<std::pair<std::string, std::string>> r = {
      {"outputs", "exit 0 leaves history.csv and summary.json in {out}"},
      {"complete", "summary.json says \"complete\": true"},
      {"finite", "every value of history.csv is a finite number (and summary.json is JSON: no NaN)"},
      {"times", "history.csv's t strictly increases"},
      {"summary keys",
       "summary.json: method, scene_sha256, dt, steps, wall_seconds, end_time, complete, "
       "contacts (impulse_normal, intervals, interval_impulses one per interval when given)"},
      {"units",
       "summary.json units are the suite's, and the values are in them: end_time and history.csv's "
       "last t are the scene's end in s within one step"},
      {"scene sha256", "summary.json scene_sha256 is the sha256 of the scene file's bytes"},
      {"consistency",
       "summary.json agrees with history.csv within the rows' resolution: impulse and interval impulses "
       "(a row every step: the time conventions' spread on the rows; sparser rows: the largest spacing x "
       "max(max R, half its variation)), intervals (start within one row spacing, end within one more plus "
       "3.5 of merge gap)"},
  };
  return r;
}

HistoryTable read_history_table(const fs::path& csv) {
  std::ifstream in(csv);
  if (!in) throw std::runtime_error(csv.string() + ": not found or unreadable");
  HistoryTable h;
  std::string line;
  if (!std::getline(in, line)) throw std::runtime_error(csv.string() + ": empty; expected a header line");
  h.names = split(line);
  for (const std::string& n : h.names) h.columns[n];
  for (long row = 2; std::getline(in, line); ++row) {
    if (trim(line).empty()) continue;
    const std::vector<std::string> cells = split(line);
    if (cells.size() != h.names.size())
      throw std::runtime_error(fmt::format("{}: row {} has {} cells, expected {}", csv.string(), row,
                                           cells.size(), h.names.size()));
    for (std::size_t c = 0; c < cells.size(); ++c) {
      char* end = nullptr;
      double v = std::strtod(cells[c].c_str(), &end);
      const bool number = !cells[c].empty() && end == cells[c].c_str() + cells[c].size();
      if ((!number || !std::isfinite(v)) && h.problem.empty())
        h.problem =
            fmt::format("row {}, column {}: expected a finite number, found '{}'", row, h.names[c], cells[c]);
      if (!number) v = std::numeric_limits<double>::quiet_NaN();
      h.columns[h.names[c]].push_back(v);
    }
  }
  return h;
}

std::vector<OutputVerdict> check_outputs(const fs::path& dir, const OutputExpectation& expected) {
  Verdicts check;
  const fs::path sum = dir / "summary.json", csv = dir / "history.csv";
  std::error_code ec;
  if (!check("outputs", dir, fs::is_regular_file(sum, ec) && fs::is_regular_file(csv, ec),
             fmt::format("expected history.csv and summary.json after exit 0; found {}{}",
                         fs::is_regular_file(csv, ec) ? "history.csv" : "no history.csv",
                         fs::is_regular_file(sum, ec) ? ", summary.json" : ", no summary.json")))
    return check.out;
  Json s;
  const std::string text = read_text(sum);
  try {
    s = Json::parse(text);
  } catch (const std::exception& e) {
    const bool nan = text.find("NaN") != std::string::npos || text.find("Infinity") != std::string::npos;
    check(nan ? "finite" : "summary keys", sum, false,
          std::string(nan ? "expected finite numbers (NaN and Infinity are not JSON): "
                          : "expected valid JSON: ") +
              e.what());
    return check.out;
  }
  HistoryTable h;
  try {
    h = read_history_table(csv);
  } catch (const std::exception& e) {
    check("finite", csv, false, std::string("expected a table of numbers: ") + e.what());
    return check.out;
  }
  check_read(check, dir, s, h, expected);
  return check.out;
}

std::string first_broken_rule(const std::vector<OutputVerdict>& verdicts) {
  for (const OutputVerdict& v : verdicts)
    if (!v.passed) return "rule '" + v.rule + "': " + v.file + ": " + v.message;
  return "";
}

}  // namespace beamimpact
