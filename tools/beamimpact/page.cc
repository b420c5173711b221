#include "page.hpp"

#include <fstream>

#include <fmt/format.h>

#include <api/child_process.hpp>
#include <api/methods_file.hpp>

namespace beamimpact {
namespace {

namespace fs = std::filesystem;

/// The last non-empty line of a file ("" when none).
std::string last_line(const fs::path& file) {
  std::ifstream in(file);
  std::string line, last;
  while (std::getline(in, line))
    if (!line.empty()) last = line;
  return last;
}

}  // namespace

PageOutcome render_page(const std::string& page, const fs::path& dir, const fs::path& python,
                        const fs::path& root) {
  const fs::path script = (root.empty() ? fs::path("reports") : root / "reports") / "render.py";
  const fs::path html = dir / (page + ".html");
  PageOutcome o;
  o.command = fmt::format("python3 {} {} {}", script.string(), page, dir.string());
  const auto not_made = [&](const std::string& why) {
    o.line = fmt::format("page: not made ({}); make it with: {}", why, o.command);
    return o;
  };
  std::error_code ec;
  fs::remove(html, ec);  // never a page older than the JSON beside it
  if (python.empty() || !fs::is_regular_file(python, ec))
    return not_made(python.empty() ? "python3 is not on PATH" : python.string() + " not found");
  if (root.empty() || !fs::is_regular_file(script, ec))
    return not_made(root.empty() ? "no data root holding reports/render.py" : script.string() + " not found");
  const fs::path log = dir / (page + ".render.log");
  fs::remove(log, ec);
  const ProcessResult r = spawn_and_wait({python.string(), script.string(), page, dir.string()}, log, 120.0);
  const std::string said = last_line(log);
  fs::remove(log, ec);
  if (r.exit_code == 0 && fs::is_regular_file(html, ec)) {
    o.made = true;
    o.line = "page: " + html.string();
    return o;
  }
  if (r.exit_code == 3) return not_made("Jinja2 is missing: Debian's python3-jinja2");
  if (!r.error.empty()) return not_made(r.error);
  return not_made(fmt::format("render.py exited {}{}", r.exit_code, said.empty() ? "" : ": " + said));
}

void print_page(const std::string& page, const fs::path& dir) {
  const std::string python = on_path("python3");
  fmt::print("{}\n", render_page(page, dir, python, data_root()).line);
}

}  // namespace beamimpact
