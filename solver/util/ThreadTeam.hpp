#pragma once
/// @file ThreadTeam.hpp
/// @brief A fixed team of threads made once and reused for every job: run(job) calls job(t) once
/// for each part t = 0 .. size() - 1 and returns when all have returned (a barrier). The caller
/// and the persistent workers claim the parts one at a time, so a worker that the system has not
/// scheduled yet (an oversubscribed machine) leaves its part to the caller instead of making it
/// wait; which thread runs a part never matters to a job whose parts write apart. Made for a step
/// loop that runs up to millions of short jobs: no allocation and no thread creation per job, and
/// a wait that spins briefly and then sleeps (std::atomic::wait, a futex on Linux).

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <thread>
#include <vector>

namespace beamimpact {

/// @brief Persistent worker threads and a reusable barrier.
class ThreadTeam {
 public:
  /// @brief Starts size - 1 workers (none for size <= 1: run() then calls job(0) inline).
  /// @param size the number of parts a job is split into (the caller runs part 0)
  explicit ThreadTeam(int size);
  /// @brief Stops and joins the workers.
  ~ThreadTeam();
  ThreadTeam(const ThreadTeam&) = delete;
  ThreadTeam& operator=(const ThreadTeam&) = delete;

  /// @brief The number of parts.
  int size() const { return size_; }

  /// @brief Calls job(t) once for every part t, on this thread or a worker, and returns when all
  /// have returned: what they wrote is then visible to the caller. No allocation.
  /// @param job callable (int t); must not throw
  template <class Job>
  void run(Job& job) {
    start(&call<Job>, &job);
  }

 private:
  template <class Job>
  static void call(void* job, int t) {
    (*static_cast<Job*>(job))(t);
  }
  /// Publishes the job, runs the parts it claims, waits for the others.
  void start(void (*fn)(void*, int), void* job);
  /// Claims and runs parts of job `generation` until none is left.
  void run_parts(std::uint32_t generation);
  /// A worker's loop: waits for the next generation, runs the parts it claims.
  void work();

  int size_;
  std::vector<std::thread> workers_;
  void (*fn_)(void*, int) = nullptr;
  void* job_ = nullptr;
  std::atomic<std::uint32_t> generation_{0};  ///< bumped once per job (and to stop); waited on
  std::atomic<std::uint64_t> claim_{0};       ///< generation << 32 | the next part to claim
  std::atomic<int> finished_{0};              ///< parts of the current job that have returned
  std::atomic<bool> stop_{false};
};

/// @brief Splits [0, n) in one range per part of `team` (part t: [n t / size, n (t + 1) / size),
/// lengths equal up to one) and calls range(first, last) for each, on the team's threads; without
/// a team (null), range(0, n) on this thread.
/// @param range callable (long long first, long long last); must not throw
template <class Range>
void run_ranges(ThreadTeam* team, int n, const Range& range) {
  if (!team) {
    range(0LL, static_cast<long long>(n));
    return;
  }
  const int parts = team->size();
  auto part = [&](int t) {
    range(static_cast<long long>(n) * t / parts, static_cast<long long>(n) * (t + 1) / parts);
  };
  team->run(part);
}

/// @brief The length of a chunk of ordered_sum (entries): the chunks, and so the bits of the sum,
/// depend on the length summed only.
inline constexpr long long kSumChunk = 8192;

/// @brief A sum over [0, n) whose bits do not depend on the threads: the range is cut into fixed
/// chunks of kSumChunk, chunk k's terms are summed by sum(first, last) (in the order that callable
/// keeps), the chunks' sums are added in chunk order on this thread. With a team the chunks are
/// shared among its threads (part t takes chunks t, t + size, ...); without one (null) this
/// thread sums them all, in the same chunks: the same bits at any thread count.
/// @param team the threads, or null
/// @param n the length of the range
/// @param partial scratch for the chunks' sums (resized to the chunk count; no allocation once
///        it has that size)
/// @param sum callable (long long first, long long last) -> double; must not throw
template <class Sum>
double ordered_sum(ThreadTeam* team, long long n, std::vector<double>& partial, const Sum& sum);

/// @brief `width` ordered sums in one pass over [0, n): sums(first, last, out) writes each
/// quantity's sum over the chunk [first, last) to out[0 .. width); quantity j's total is its
/// chunks' sums added in chunk order, the same chunks as ordered_sum(), so its bits are those of
/// ordered_sum() of that quantity alone, at any thread count. One hand-over to the team and one
/// pass over memory instead of `width`.
/// @param team the threads, or null
/// @param n the length of the range
/// @param width the number of quantities (>= 1)
/// @param partial scratch for the chunks' sums (resized; no allocation once it has that size)
/// @param total the totals, `width` of them (written)
/// @param sums callable (long long first, long long last, double* out); must not throw
template <class Sums>
void ordered_sums(ThreadTeam* team, long long n, int width, std::vector<double>& partial, double* total,
                  const Sums& sums) {
  const long long chunks = (n + kSumChunk - 1) / kSumChunk;
  partial.resize(static_cast<std::size_t>(chunks * width));
  auto chunk = [&](long long k) {
    sums(k * kSumChunk, std::min(n, (k + 1) * kSumChunk), &partial[k * width]);
  };
  if (!team || chunks < 2) {
    for (long long k = 0; k < chunks; ++k) chunk(k);
  } else {
    const int parts = team->size();
    auto part = [&](int t) {
      for (long long k = t; k < chunks; k += parts) chunk(k);
    };
    team->run(part);
  }
  for (int j = 0; j < width; ++j) {
    double s = 0.0;
    for (long long k = 0; k < chunks; ++k) s += partial[k * width + j];
    total[j] = s;
  }
}

template <class Sum>
double ordered_sum(ThreadTeam* team, long long n, std::vector<double>& partial, const Sum& sum) {
  double total = 0.0;
  ordered_sums(team, n, 1, partial, &total,
               [&](long long first, long long last, double* out) { *out = sum(first, last); });
  return total;
}

}  // namespace beamimpact
