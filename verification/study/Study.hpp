#pragma once
/// @file Study.hpp
/// @brief A parameter study (`beamimpact study STUDY.toml`): one scene, parameters over scene
/// keys (a grid or a Latin hypercube with a fixed seed), the methods under test and the reference
/// each point is compared with. Loaded and validated in one place (Study::load).

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace beamimpact::study {

/// @brief One parameter of the study and what it changes in the scene.
struct Parameter {
  /// @brief What a value sets: a scene key (`key = "contacts[0].friction"`), the element
  /// multiplier of every body (`mesh = true`), or the rake angle of a striker (`rake = "A"`:
  /// body A turned about its end node to this angle from the x axis, in degrees, moving along its
  /// axis toward that end at its scene speed; the paper's S4 geometry).
  enum class Kind { kKey, kMesh, kRake };
  std::string name;  ///< column name ("alpha0", "mu", "mesh")
  Kind kind = Kind::kKey;
  std::string target;              ///< the scene key (kKey) or the body name (kRake)
  std::vector<double> values;      ///< the levels (grid: every one; Latin hypercube: strata of from..to)
  std::optional<double> from, to;  ///< continuous range (Latin hypercube), also the source of values
};

/// @brief The reference each point is compared with: a method with extra overrides on top of
/// the point's own ("time.fraction=0.0625" makes a converged self-reference).
struct Reference {
  std::string method;
  std::vector<std::string> set;
};

/// @brief Where a case counts as "the integrator's assumptions broke" in the report (any rule).
struct BreakRule {
  std::string metric = "impulse";  ///< a comparison norm
  double above = 0.1;              ///< the norm value above which a case is listed
};

/// @brief The most points a design may have: each is held in memory (a grid of 1e7 points of a few
/// parameters is about 1 GB with its results).
inline constexpr double kMostStudyPoints = 1e7;

/// @brief A whole study file, validated.
struct Study {
  enum class Design { kGrid, kLatinHypercube };
  std::filesystem::path file;  ///< the study file (absolute)
  std::string name, description;
  std::filesystem::path scene;  ///< absolute
  std::vector<std::string> methods;
  Reference reference;
  std::vector<std::string> set;  ///< fixed overrides of every run
  std::vector<Parameter> parameters;
  Design design = Design::kGrid;
  long samples = 0;                ///< Latin hypercube points
  std::uint64_t seed = 1;          ///< Latin hypercube seed
  double energy_growth = 0.05;     ///< stability bound: energy created / E0 above this is "energy"
  std::vector<std::string> norms;  ///< table columns (comparison norms)
  std::vector<BreakRule> breaks{BreakRule{}};  ///< `breaks = [{ metric, above }, ...]`
  bool keep_runs = false;                      ///< keep each run's history.csv / summary.json under DIR/runs
  bool allow_long_run = false;                 ///< run a study beyond kOrdinaryWork DOF-steps in total

  /// @brief Reads and checks a study file. Throws InputError (file, key, what was expected) for a
  /// missing scene, an unknown method or norm, a parameter without values, a bad design, a design
  /// of more than kMostStudyPoints points, or runs adding up to more than kOrdinaryWork DOF-steps
  /// (run_cost.hpp) without allow_long_run = true; the message states the estimate.
  /// @param file the study file (TOML)
  static Study load(const std::filesystem::path& file);
};

/// @brief One point of the design: a value per parameter, in the study's parameter order.
struct Point {
  std::vector<double> values;
};

/// @brief The points of the design: the full grid (first parameter slowest), or `samples`
/// Latin hypercube points from the study's seed (the same on every machine: a 64-bit
/// SplitMix generator, no library distribution).
/// @param s the study
std::vector<Point> design_points(const Study& s);

/// @brief The --set overrides of one point: the study's fixed set, then each parameter's. The
/// rake transform reads the scene (with the overrides before it) for the body's end, length and
/// speed. Throws InputError naming the study file and the parameter when it cannot apply.
/// @param s the study
/// @param p the point
std::vector<std::string> overrides(const Study& s, const Point& p);

}  // namespace beamimpact::study
