#include <solver/util/Progress.hpp>

#include <unistd.h>
#include <cstdio>

namespace beamimpact {
namespace {
bool g_enabled = true;  // set by the CLI before any run starts; a study silences it while it runs
std::function<void(const std::string&, double, double)> g_listener;
}  // namespace

void Progress::set_enabled(bool enabled) { g_enabled = enabled; }

bool Progress::enabled() { return g_enabled; }

void Progress::set_listener(std::function<void(const std::string&, double, double)> listener) {
  g_listener = std::move(listener);
}

Progress::Progress(std::string label, double total)
    : label_(std::move(label)), total_(total), start_(std::chrono::steady_clock::now()), last_(start_) {}

void Progress::report(double value) {
  using namespace std::chrono;
  const auto now = steady_clock::now();
  if (!g_enabled || now - start_ < seconds(1) || now - last_ < milliseconds(500)) return;
  last_ = now;
  if (g_listener) {
    g_listener(label_, value, total_);
    return;
  }
  const double pct = total_ > 0 ? 100.0 * value / total_ : 0.0;
  char cost[64] = "";
  if (dofs_ > 0)
    std::snprintf(cost, sizeof cost, ", %.3g ns per DOF-step",
                  1e9 * duration<double>(now - start_).count() /
                      (static_cast<double>(dofs_) * static_cast<double>(updates_)));
  // On a terminal, one line rewritten in place; in a log, one line per update.
  const bool tty = isatty(fileno(stderr));
  std::fprintf(stderr, "%s%s: %3.0f%% (%.4g of %.4g%s)%s", tty ? "\r" : "", label_.c_str(), pct, value,
               total_, cost, tty ? "" : "\n");
  std::fflush(stderr);
  printed_ = tty;
}

Progress::~Progress() {
  if (printed_) std::fprintf(stderr, "\n");
}

}  // namespace beamimpact
