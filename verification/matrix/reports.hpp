#pragma once
/// @file reports.hpp
/// @brief The three outputs of `beamimpact verify`: JUnit XML (CI), JSON of every norm, and a
/// Markdown summary with a table per scene.

#include <filesystem>
#include <string>
#include <vector>

#include <solver/util/write_file_atomic.hpp>
#include <verification/matrix/evaluate.hpp>

namespace beamimpact::verification {

/// @brief How the report was made (written at the top of every output).
struct ReportContext {
  std::string command;        ///< the command line
  std::string matrix;         ///< matrix file
  std::string tier;           ///< quick | full
  std::string version;        ///< kVersion of the binary
  std::string started;        ///< UTC time stamp
  double wall_seconds = 0.0;  ///< s, whole verify
  int jobs = 1;
  std::string incomplete;  ///< why the report is incomplete (e.g. "interrupted by signal 2"), "" if complete
};

/// @brief The current UTC time as "2026-01-31T12:00:00Z" (ReportContext::started, sweep.md).
std::string utc_now();

/// @brief JUnit XML: one testsuite per scene, one testcase per gate, named
/// "<scene> <method> dt=<dt> vs <reference>: <metric>" (classname "<scene>.<method>.dt=<dt>").
void write_junit(const std::filesystem::path& file, const ReportContext& ctx,
                 const std::vector<ItemResult>& items);

/// @brief JSON with the context, every gate and every norm of every comparison: "verdict"
/// ("PASS" | "FAIL", verification_passed()), the counts "gates", "passed", "failed", "skipped",
/// and per gate "status", "passed" (bool) and "margin" (GateResult::margin()).
void write_json(const std::filesystem::path& file, const ReportContext& ctx,
                const std::vector<ItemResult>& items);

/// @brief The JSON write_json writes (norms.json; the Python module's beamimpact.verify returns it).
nlohmann::json norms_json(const ReportContext& ctx, const std::vector<ItemResult>& items);

/// @brief Markdown: how it was made, totals, a table per scene (method, dt, reference, norm,
/// value, limit, result, wall time), the observed orders of each ladder, and the definitions.
void write_markdown(const std::filesystem::path& file, const ReportContext& ctx,
                    const std::vector<ItemResult>& items);

/// @brief Text made safe for XML and HTML (& < > " ' escaped, control characters blanked).
std::string xml_escape(const std::string& s);

}  // namespace beamimpact::verification
