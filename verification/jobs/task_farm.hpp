#pragma once
/// @file task_farm.hpp
/// @brief Independent tasks spread over the ranks of an MPI job (`mpirun -n N beamimpact ...`)
/// with a master-worker queue, longest task first; the serial build and a run without mpirun do
/// the same work in this process. Results are strings (JSON), gathered on rank 0.

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace beamimpact::jobs {

/// @brief The MPI job this process belongs to. MPI is initialised only when this build has MPI
/// and the process was started by mpirun (its environment says so); otherwise one rank.
class World {
 public:
  /// @brief Initialises MPI (thread level funneled) when started by mpirun.
  /// @param argc, argv main()'s arguments
  World(int& argc, char**& argv);
  ~World();
  World(const World&) = delete;
  World& operator=(const World&) = delete;
  /// @brief This process's rank (0 without MPI).
  static int rank();
  /// @brief The number of ranks (1 without MPI).
  static int size();
  /// @brief Rank 0's `text` on every rank (every rank must call it; one rank: `text` itself).
  static std::string broadcast(std::string text);
  /// @brief Ends every rank of the job with this exit code (after an error on one rank).
  [[noreturn]] static void abort(int code);
};

/// @brief Runs tasks 0..cost.size()-1, each exactly once, the most costly first; a task of
/// negative cost is not run (done elsewhere: a study point finished earlier).
/// One rank: in this thread, in that order. N ranks: rank 0 is the master (its queue hands the
/// next task to whichever worker asks) and also computes in a second thread; ranks 1..N-1 ask,
/// compute and send results back. If a rank dies (a signal), it prints which task it was running.
/// @param cost work estimate of each task (only the order matters; negative: not run)
/// @param work computes task i and returns its result (called on any rank; must not throw)
/// @param done called on rank 0, in its main thread, for each result as it arrives, with the
///        rank that computed it
/// @param label names task i in the message of a rank that dies while running it
/// @return true on rank 0 (every result was passed to done), false on the workers
bool farm(const std::vector<double>& cost, const std::function<std::string(std::size_t)>& work,
          const std::function<void(std::size_t, const std::string&, int)>& done,
          const std::function<std::string(std::size_t)>& label = {});

/// @brief The order farm() hands tasks out: by cost, largest first, ties by index; tasks of
/// negative cost left out.
std::vector<std::size_t> longest_first(const std::vector<double>& cost);

}  // namespace beamimpact::jobs
