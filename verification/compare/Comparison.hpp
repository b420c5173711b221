#pragma once
/// @file Comparison.hpp
/// @brief The result of comparing a run with a reference run: named error norms, each with its
/// definition and unit, plus the settings used (grid, window, merge rule).

#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace beamimpact::verification {

/// @brief One error measure between a run (a) and its reference (b).
struct Norm {
  std::string name;             ///< e.g. "R.rel_l2", "impulse", "contact_start"
  std::optional<double> value;  ///< the error (>= 0); empty when it could not be computed
  std::string unit;             ///< "1" (relative), "s", "count", ...
  std::string definition;       ///< how it is computed, in words and symbols
  /// The compared scalars: the run's and the reference's values, or, when `difference` is set,
  /// the run's largest difference from the reference |a - b| (over paired intervals or bodies) and
  /// the scale it is divided by.
  std::optional<double> a, b;
  std::string unavailable;  ///< why value is empty
  bool difference = false;  ///< a and b are a difference and its scale, not the two values
};

/// @brief All norms of one comparison and how they were computed.
struct Comparison {
  std::string run, reference;    ///< directories (or labels)
  double t0 = 0.0, t1 = 0.0;     ///< s, the overlap of both histories compared
  double grid_step = 0.0;        ///< s, spacing of the common grid
  double window = 0.0;           ///< s, width of the force averaging window
  double merge_gap = 0.0;        ///< s, contact samples closer than this form one interval
  double force_threshold = 0.0;  ///< N, R above this counts as contact
  std::vector<Norm> norms;
  std::vector<std::string> notes;  ///< warnings (short overlap, missing columns, ...)

  /// @brief The norm of this name, or nullptr.
  const Norm* find(const std::string& name) const;
  /// @brief JSON document (what `compare --json` writes).
  nlohmann::json to_json() const;
  /// @brief Human-readable table with the definitions, for the terminal: per norm its error and
  /// unit, the run's and the reference's values with their difference (scalar norms), or the
  /// largest difference and its scale (norms whose `difference` is set).
  std::string to_text() const;
};

}  // namespace beamimpact::verification
