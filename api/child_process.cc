#include <api/child_process.hpp>

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>

#include <array>
#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <mutex>
#include <thread>

extern char** environ;

namespace beamimpact {
namespace {

// The live children's process group ids (0: a free slot). Lock-free atomics: read by the signal
// handler, which may only use async-signal-safe calls (kill, waitpid, nanosleep, raise).
constexpr int kMaxChildren = 256;
std::array<std::atomic<pid_t>, kMaxChildren> g_children{};
volatile std::sig_atomic_t g_signal = 0;
std::atomic<bool> g_carry_on{false};

void sleep_ms(long ms) {
  timespec ts{ms / 1000, (ms % 1000) * 1000000L};
  nanosleep(&ts, nullptr);
}

/// True while some process of group `pgid` exists (its leader reaped here if it has ended).
bool group_alive(pid_t pgid) {
  int status = 0;
  waitpid(pgid, &status, WNOHANG);  // reap the leader when it is a zombie; ECHILD if reaped already
  return kill(-pgid, 0) == 0;
}

/// SIGTERM to every registered group, SIGKILL to those still there after 2 s; returns when all
/// are gone (async-signal-safe).
void end_children() {
  for (auto& c : g_children)
    if (const pid_t g = c.load(); g > 0) kill(-g, SIGTERM);
  for (int i = 0; i < 100; ++i) {
    bool any = false;
    for (auto& c : g_children)
      if (const pid_t g = c.load(); g > 0) any = any || group_alive(g);
    if (!any) return;
    sleep_ms(20);
  }
  for (auto& c : g_children)
    if (const pid_t g = c.load(); g > 0) {
      kill(-g, SIGKILL);
      for (int i = 0; i < 250 && group_alive(g); ++i) sleep_ms(20);
    }
}

extern "C" void on_ending_signal(int sig) {
  g_signal = sig;
  end_children();
  if (g_carry_on.load()) return;
  std::signal(sig, SIG_DFL);  // end by the same signal once the handler returns
  std::raise(sig);
}

extern "C" void end_children_at_exit() { end_children(); }

std::string fmt_seconds(double s) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", s);
  return buf;
}

constexpr int kEndingSignals[] = {SIGINT, SIGTERM, SIGHUP};

/// The handlers: in every signal still at its default action (or all of them, recording, from
/// catch_interruptions), and the exit hook. Once per process.
void install_handlers(bool force) {
  static std::mutex mu;
  static bool at_exit = false;
  std::lock_guard lock(mu);
  for (int sig : kEndingSignals) {
    struct sigaction old {};
    sigaction(sig, nullptr, &old);
    if (!force && (old.sa_handler != SIG_DFL || (old.sa_flags & SA_SIGINFO))) continue;
    struct sigaction sa {};
    sa.sa_handler = on_ending_signal;
    sigemptyset(&sa.sa_mask);
    for (int other : kEndingSignals) sigaddset(&sa.sa_mask, other);  // one ending at a time
    sigaction(sig, &sa, nullptr);
  }
  if (!at_exit) at_exit = std::atexit(end_children_at_exit) == 0;
}

/// Registers a live child's group for the handlers; false when every slot is taken.
bool register_child(pid_t pid) {
  for (auto& c : g_children) {
    pid_t free = 0;
    if (c.compare_exchange_strong(free, pid)) return true;
  }
  return false;
}

void unregister_child(pid_t pid) {
  for (auto& c : g_children) {
    pid_t mine = pid;
    if (c.compare_exchange_strong(mine, 0)) return;
  }
}

/// Starts argv in its own process group with stdout and stderr appended to log: posix_spawn's
/// error number (0 when started) and the child's pid.
int start_child(const std::vector<std::string>& argv, const std::filesystem::path& log, pid_t& pid) {
  std::vector<char*> cargv;
  for (const auto& a : argv) cargv.push_back(const_cast<char*>(a.c_str()));
  cargv.push_back(nullptr);

  // posix_spawn rather than fork: safe with the worker threads of the runner.
  posix_spawn_file_actions_t fa;
  posix_spawn_file_actions_init(&fa);
  posix_spawn_file_actions_addopen(&fa, 1, log.c_str(), O_WRONLY | O_CREAT | O_APPEND, 0644);
  posix_spawn_file_actions_adddup2(&fa, 1, 2);
  posix_spawnattr_t attr;
  posix_spawnattr_init(&attr);
  // Own process group, so that a time-out or beamimpact's end also ends the children (mpirun,
  // python workers). The ending signals' dispositions are reset in the child (a handler of ours
  // would not survive exec anyway; an ignored signal would).
  posix_spawnattr_setflags(&attr, POSIX_SPAWN_SETPGROUP | POSIX_SPAWN_SETSIGDEF | POSIX_SPAWN_SETSIGMASK);
  posix_spawnattr_setpgroup(&attr, 0);
  sigset_t defaults, none;
  sigemptyset(&defaults);
  for (int sig : kEndingSignals) sigaddset(&defaults, sig);
  sigemptyset(&none);
  posix_spawnattr_setsigdefault(&attr, &defaults);
  posix_spawnattr_setsigmask(&attr, &none);
  // A run started from a rank of an MPI job must not think it is one of its ranks (a FEniCSx run
  // would join the job): the launcher's variables are left out, so it runs as its own job.
  std::vector<char*> env;
  for (char** e = environ; *e; ++e)
    if (std::strncmp(*e, "OMPI_", 5) != 0 && std::strncmp(*e, "PMIX_", 5) != 0 &&
        std::strncmp(*e, "PMI_", 4) != 0)
      env.push_back(*e);
  env.push_back(nullptr);
  const int rc = posix_spawn(&pid, cargv[0], &fa, &attr, cargv.data(), env.data());
  posix_spawn_file_actions_destroy(&fa);
  posix_spawnattr_destroy(&attr);
  return rc;
}

}  // namespace

void catch_interruptions() {
  g_carry_on = true;
  install_handlers(true);
}

int caught_signal() { return g_signal; }

ProcessResult spawn_and_wait(const std::vector<std::string>& argv, const std::filesystem::path& log,
                             double timeout_seconds, const std::function<int()>& interrupted,
                             bool own_group) {
  (void)own_group;  // every child has its own group (the file's brief)
  ProcessResult r;
  const auto start = std::chrono::steady_clock::now();
  install_handlers(false);
  if (g_signal != 0) {
    r.error = "interrupted (signal " + std::to_string(static_cast<int>(g_signal)) + ") before it started";
    return r;
  }
  pid_t pid = 0;
  const int rc = start_child(argv, log, pid);
  if (rc != 0) {
    r.error = std::string("could not start ") + argv[0] + ": " + std::strerror(rc);
    return r;
  }
  const bool registered = register_child(pid);
  int status = 0;
  for (;;) {
    const pid_t w = waitpid(pid, &status, WNOHANG);
    if (w == pid) break;
    const int sig = g_signal != 0 ? static_cast<int>(g_signal) : interrupted ? interrupted() : 0;
    if (w < 0 && !(errno == ECHILD && sig != 0)) {  // ECHILD: the handler reaped it
      r.error = std::string("waitpid failed: ") + std::strerror(errno);
      break;
    }
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (sig != 0) {  // forward: SIGTERM to the run's group, SIGKILL if still there after 2 s
      kill(-pid, SIGTERM);
      for (int i = 0; i < 100 && group_alive(pid); ++i)
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
      kill(-pid, SIGKILL);  // the group's other members (mpirun's, python's children) too
      while (group_alive(pid)) std::this_thread::sleep_for(std::chrono::milliseconds(20));
      r.timed_out = true;
      r.error = "interrupted (signal " + std::to_string(sig) + ")";
      break;
    }
    if (elapsed > timeout_seconds) {
      kill(-pid, SIGKILL);  // the whole group of this one run, by its id
      while (group_alive(pid)) std::this_thread::sleep_for(std::chrono::milliseconds(20));
      r.timed_out = true;
      r.error = "killed after the time limit of " + fmt_seconds(timeout_seconds) + " s";
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  // The group's other members outlive a leader that exited: they end with it.
  if (kill(-pid, 0) == 0) {
    kill(-pid, SIGKILL);
    while (group_alive(pid)) std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  if (registered) unregister_child(pid);
  r.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!r.timed_out) {
    if (WIFEXITED(status))
      r.exit_code = WEXITSTATUS(status);
    else if (WIFSIGNALED(status))
      r.error = std::string("ended by signal ") + strsignal(WTERMSIG(status));
  }
  return r;
}

}  // namespace beamimpact
