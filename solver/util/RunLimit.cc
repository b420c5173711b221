#include <solver/util/RunLimit.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>

#include <fmt/format.h>

namespace beamimpact {
namespace {

thread_local const RunLimit* t_limit = nullptr;

double now() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

}  // namespace

RunLimit::RunLimit(double seconds, std::function<int()> interrupted)
    : outer_(t_limit), deadline_(now() + seconds), seconds_(seconds), interrupted_(std::move(interrupted)) {
  if (!(seconds > 0.0))
    throw std::invalid_argument(fmt::format("RunLimit: expected a budget > 0 s, got {}", seconds));
  t_limit = this;
}

RunLimit::~RunLimit() { t_limit = outer_; }

void RunLimit::check() {
  const RunLimit* l = t_limit;
  if (!l) return;
  if (l->interrupted_)
    if (const int signal = l->interrupted_())
      throw RunStopped(fmt::format("interrupted by signal {}", signal));
  if (now() > l->deadline_) throw RunStopped(fmt::format("time limit of {:g} s reached", l->seconds_));
}

double RunLimit::seconds_left() {
  const RunLimit* l = t_limit;
  if (!l || std::isinf(l->deadline_)) return std::numeric_limits<double>::infinity();
  return std::max(0.0, l->deadline_ - now());
}

std::function<int()> RunLimit::interruption() {
  return t_limit ? t_limit->interrupted_ : std::function<int()>{};
}

}  // namespace beamimpact
