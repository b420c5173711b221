#include <solver/util/ThreadTeam.hpp>

#include <chrono>

namespace beamimpact {
namespace {

/// How long a waiting thread spins before it sleeps: about the serial part between two jobs of a
/// step loop (the contact solve and the recording of a step take microseconds), so that a
/// running loop never sleeps, and an idle or oversubscribed one spins at most this long.
constexpr std::chrono::microseconds kSpin{50};

inline void relax() {
#if defined(__x86_64__) || defined(__i386__)
  __builtin_ia32_pause();
#endif
}

/// Returns when `value` differs from `old`: spins up to kSpin, then sleeps in value.wait().
template <class T>
void wait_while_equal(const std::atomic<T>& value, T old) {
  using Clock = std::chrono::steady_clock;
  const Clock::time_point until = Clock::now() + kSpin;
  for (int i = 1;; ++i) {
    if (value.load(std::memory_order_acquire) != old) return;
    relax();
    if (i % 64 == 0 && Clock::now() > until) break;
  }
  while (value.load(std::memory_order_acquire) == old) value.wait(old, std::memory_order_acquire);
}

}  // namespace

ThreadTeam::ThreadTeam(int size) : size_(size < 1 ? 1 : size) {
  workers_.reserve(static_cast<std::size_t>(size_ - 1));
  for (int t = 1; t < size_; ++t) workers_.emplace_back([this] { work(); });
}

ThreadTeam::~ThreadTeam() {
  stop_.store(true, std::memory_order_relaxed);
  generation_.fetch_add(1, std::memory_order_release);
  generation_.notify_all();
  for (std::thread& w : workers_) w.join();
}

void ThreadTeam::start(void (*fn)(void*, int), void* job) {
  if (size_ == 1) {
    fn(job, 0);
    return;
  }
  fn_ = fn;
  job_ = job;
  finished_.store(0, std::memory_order_relaxed);
  const std::uint32_t g = generation_.load(std::memory_order_relaxed) + 1;
  claim_.store(static_cast<std::uint64_t>(g) << 32, std::memory_order_release);
  generation_.store(g, std::memory_order_release);  // publishes fn_, job_, finished_ and claim_
  generation_.notify_all();
  run_parts(g);
  for (int done = finished_.load(std::memory_order_acquire); done != size_;
       done = finished_.load(std::memory_order_acquire))
    wait_while_equal(finished_, done);
}

void ThreadTeam::run_parts(std::uint32_t generation) {
  for (;;) {
    std::uint64_t c = claim_.load(std::memory_order_acquire);
    // A late worker may see a later job's claims: it takes parts of its own job only.
    if (static_cast<std::uint32_t>(c >> 32) != generation) return;
    const int part = static_cast<int>(c & 0xffffffffu);
    if (part >= size_) return;
    if (!claim_.compare_exchange_weak(c, c + 1, std::memory_order_acq_rel)) continue;
    fn_(job_, part);  // the job stays published until this part is counted as finished
    if (finished_.fetch_add(1, std::memory_order_acq_rel) + 1 == size_) finished_.notify_one();
  }
}

void ThreadTeam::work() {
  std::uint32_t seen = 0;
  for (;;) {
    wait_while_equal(generation_, seen);
    seen = generation_.load(std::memory_order_acquire);
    if (stop_.load(std::memory_order_relaxed)) return;
    run_parts(seen);
  }
}

}  // namespace beamimpact
