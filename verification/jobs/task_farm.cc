#include <verification/jobs/task_farm.hpp>

#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <deque>
#include <mutex>
#include <thread>

#ifdef BEAMIMPACT_HAVE_MPI
#include <mpi.h>
#endif

namespace beamimpact::jobs {
namespace {

int g_rank = 0, g_size = 1;
#ifdef BEAMIMPACT_HAVE_MPI
bool g_mpi = false;  // MPI_Init was called (so MPI_Finalize is due)
#endif

// What each computing thread of this process runs now, for the crash message (written by a
// signal handler: preformatted, async-signal-safe write only).
char g_running[2][400];
std::atomic<int> g_slot{0};
thread_local int t_slot = -1;

constexpr int kCrashSignals[] = {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT};
struct sigaction g_previous[std::size(kCrashSignals)];

void on_crash(int sig) {
  for (const char* m : g_running)
    if (m[0]) {
      const ssize_t w = ::write(2, m, std::strlen(m));
      (void)w;
    }
  // Hand the signal to whoever handled it before (a sanitizer's report, or the default action).
  for (std::size_t i = 0; i < std::size(kCrashSignals); ++i)
    if (kCrashSignals[i] == sig) sigaction(sig, &g_previous[i], nullptr);
  std::raise(sig);
}

void install_crash_report() {
  static bool installed = false;
  if (installed) return;
  installed = true;
  struct sigaction sa {};
  sa.sa_handler = on_crash;
  sigemptyset(&sa.sa_mask);
  for (std::size_t i = 0; i < std::size(kCrashSignals); ++i) sigaction(kCrashSignals[i], &sa, &g_previous[i]);
}

const std::function<std::string(std::size_t)>* g_label = nullptr;

void mark_running(std::size_t task) {
  if (t_slot < 0) t_slot = std::min(1, g_slot++);
  const std::string label = g_label && *g_label ? (*g_label)(task) : std::to_string(task);
  std::snprintf(g_running[t_slot], sizeof g_running[t_slot],
                "beamimpact: rank %d ended by a signal while running %s\n", g_rank, label.c_str());
}

void clear_running() {
  if (t_slot >= 0) g_running[t_slot][0] = '\0';
}

bool started_by_mpirun() {
  for (const char* v : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_SIZE", "MPI_LOCALNRANKS"})
    if (std::getenv(v)) return true;
  return false;
}

#ifdef BEAMIMPACT_HAVE_MPI
constexpr int kTagResult = 1, kTagTask = 2;

/// A worker's message: the index of the task it finished (-1: first request) then its result.
void send_result(std::int64_t index, const std::string& payload) {
  std::string buf(sizeof index, '\0');
  std::memcpy(buf.data(), &index, sizeof index);
  buf += payload;
  MPI_Send(buf.data(), static_cast<int>(buf.size()), MPI_CHAR, 0, kTagResult, MPI_COMM_WORLD);
}

void worker(const std::function<std::string(std::size_t)>& work) {
  std::int64_t finished = -1;
  std::string result;
  for (;;) {
    send_result(finished, result);
    std::int64_t task = -1;
    MPI_Recv(&task, 1, MPI_INT64_T, 0, kTagTask, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    if (task < 0) return;
    mark_running(static_cast<std::size_t>(task));
    result = work(static_cast<std::size_t>(task));
    clear_running();
    finished = task;
  }
}

void master(const std::vector<std::size_t>& order, const std::function<std::string(std::size_t)>& work,
            const std::function<void(std::size_t, const std::string&, int)>& done) {
  std::mutex mu;
  std::size_t next = 0;
  std::deque<std::pair<std::size_t, std::string>> local;  // results of rank 0's own thread
  auto take = [&]() -> std::int64_t {
    std::lock_guard lock(mu);
    return next < order.size() ? static_cast<std::int64_t>(order[next++]) : -1;
  };
  std::thread own([&] {
    for (std::int64_t t = take(); t >= 0; t = take()) {
      mark_running(static_cast<std::size_t>(t));
      std::string r = work(static_cast<std::size_t>(t));
      clear_running();
      std::lock_guard lock(mu);
      local.emplace_back(static_cast<std::size_t>(t), std::move(r));
    }
  });
  std::size_t received = 0;
  int stopped = 0;
  std::string buf;
  while (received < order.size() || stopped < g_size - 1) {
    bool busy = false;
    int flag = 0;
    MPI_Status st;
    MPI_Iprobe(MPI_ANY_SOURCE, kTagResult, MPI_COMM_WORLD, &flag, &st);
    if (flag) {
      busy = true;
      int count = 0;
      MPI_Get_count(&st, MPI_CHAR, &count);
      buf.resize(static_cast<std::size_t>(count));
      MPI_Recv(buf.data(), count, MPI_CHAR, st.MPI_SOURCE, kTagResult, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
      std::int64_t index = -1;
      std::memcpy(&index, buf.data(), sizeof index);
      if (index >= 0) {
        done(static_cast<std::size_t>(index), buf.substr(sizeof index), st.MPI_SOURCE);
        ++received;
      }
      const std::int64_t t = take();
      MPI_Send(&t, 1, MPI_INT64_T, st.MPI_SOURCE, kTagTask, MPI_COMM_WORLD);
      stopped += t < 0;
    }
    std::deque<std::pair<std::size_t, std::string>> mine;
    {
      std::lock_guard lock(mu);
      mine.swap(local);
    }
    for (auto& [i, r] : mine) {
      done(i, r, 0);
      ++received;
      busy = true;
    }
    if (!busy) std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  own.join();
}
#endif

}  // namespace

World::World(int& argc, char**& argv) {
  (void)argc;
  (void)argv;
#ifdef BEAMIMPACT_HAVE_MPI
  if (!started_by_mpirun()) return;
  int provided = 0;
  MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided);
  g_mpi = true;
  MPI_Comm_rank(MPI_COMM_WORLD, &g_rank);
  MPI_Comm_size(MPI_COMM_WORLD, &g_size);
#else
  if (started_by_mpirun())
    std::fprintf(stderr, "beamimpact: started by mpirun, but this build has no MPI: every rank runs alone\n");
#endif
}

World::~World() {
#ifdef BEAMIMPACT_HAVE_MPI
  if (g_mpi) MPI_Finalize();
#endif
}

int World::rank() { return g_rank; }
int World::size() { return g_size; }

void World::abort(int code) {
#ifdef BEAMIMPACT_HAVE_MPI
  if (g_mpi && g_size > 1) MPI_Abort(MPI_COMM_WORLD, code);
#endif
  std::exit(code);
}

std::string World::broadcast(std::string text) {
#ifdef BEAMIMPACT_HAVE_MPI
  if (g_size > 1) {
    std::uint64_t n = text.size();
    MPI_Bcast(&n, 1, MPI_UINT64_T, 0, MPI_COMM_WORLD);
    text.resize(n);
    MPI_Bcast(text.data(), static_cast<int>(n), MPI_CHAR, 0, MPI_COMM_WORLD);
  }
#endif
  return text;
}

std::vector<std::size_t> longest_first(const std::vector<double>& cost) {
  std::vector<std::size_t> order;
  for (std::size_t i = 0; i < cost.size(); ++i)
    if (!(cost[i] < 0.0)) order.push_back(i);
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return cost[a] > cost[b]; });
  return order;
}

bool farm(const std::vector<double>& cost, const std::function<std::string(std::size_t)>& work,
          const std::function<void(std::size_t, const std::string&, int)>& done,
          const std::function<std::string(std::size_t)>& label) {
  const std::vector<std::size_t> order = longest_first(cost);
  install_crash_report();
  g_label = &label;
#ifdef BEAMIMPACT_HAVE_MPI
  if (g_size > 1) {
    if (g_rank == 0) {
      master(order, work, done);
      return true;
    }
    worker(work);
    return false;
  }
#endif
  for (std::size_t i : order) {
    mark_running(i);
    const std::string r = work(i);
    clear_running();
    done(i, r, 0);
  }
  return true;
}

}  // namespace beamimpact::jobs
