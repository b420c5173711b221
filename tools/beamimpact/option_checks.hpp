#pragma once
/// @file option_checks.hpp
/// @brief The range checks of the commands' numeric options, one per kind, so that every command
/// refuses a bad value alike (exit 2, the option named by CLI11): a time limit in seconds and a
/// count of parallel jobs.

#include <cmath>
#include <cstdlib>
#include <string>

#include <CLI/CLI.hpp>

namespace beamimpact {

/// @brief Seconds: a finite number > 0 (refuses 0, negatives, nan and inf).
inline CLI::Validator positive_seconds() {
  return CLI::Validator(
      [](std::string& v) -> std::string {
        char* end = nullptr;
        const double s = std::strtod(v.c_str(), &end);
        if (v.empty() || *end != '\0' || !std::isfinite(s) || !(s > 0.0))
          return "expected a finite number of seconds > 0, got '" + v + "'";
        return {};
      },
      "SECONDS > 0");
}

/// @brief Parallel jobs: a whole number >= 1.
inline CLI::Validator job_count() {
  return CLI::Validator(
      [](std::string& v) -> std::string {
        char* end = nullptr;
        const long n = std::strtol(v.c_str(), &end, 10);
        if (v.empty() || *end != '\0' || n < 1 || n > 4096)
          return "expected a whole number of jobs 1..4096, got '" + v + "'";
        return {};
      },
      "1..4096");
}

}  // namespace beamimpact
