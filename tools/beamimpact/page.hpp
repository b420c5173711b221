#pragma once
/// @file page.hpp
/// @brief The HTML page of a command's JSON result (DIR/scorecard.json of `beamimpact score`,
/// DIR/conform.json of `beamimpact conform`), made by the one page generator, reports/render.py
/// (Jinja2 templates in reports/templates), found under the data root: the repository, or the
/// installed share/beamimpact. The program writes JSON only and the JSON carries the verdict: a
/// page that cannot be made (no python3, no render.py, no Jinja2) is one line saying so and
/// naming the command that makes it, never an error and never a change of the exit code.

#include <filesystem>
#include <string>

namespace beamimpact {

/// @brief What became of a page.
struct PageOutcome {
  bool made = false;  ///< DIR/PAGE.html was written
  std::string line;   ///< what to print: "page: DIR/PAGE.html", or "page: not made (why); make it with: ..."
  std::string command;  ///< the command that makes the page: python3 ROOT/reports/render.py PAGE DIR
};

/// @brief Renders DIR/PAGE.html from DIR/PAGE.json with `python ROOT/reports/render.py PAGE DIR`
/// (at most 120 s). An earlier DIR/PAGE.html is removed first, so that no page older than the
/// JSON is left beside it. Never throws for a renderer that is missing or fails.
/// @param page "scorecard" or "conform"
/// @param dir the folder holding PAGE.json
/// @param python the Python interpreter's path ("" when none was found)
/// @param root the data root holding reports/render.py ("" when none was found)
PageOutcome render_page(const std::string& page, const std::filesystem::path& dir,
                        const std::filesystem::path& python, const std::filesystem::path& root);

/// @brief render_page with python3 from PATH and data_root(), its line printed on stdout.
/// @param page "scorecard" or "conform"
/// @param dir the folder holding PAGE.json
void print_page(const std::string& page, const std::filesystem::path& dir);

}  // namespace beamimpact
