#include <api/child_process.hpp>

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>

#include <chrono>
#include <cstring>
#include <thread>

extern char** environ;

namespace beamimpact {

ProcessResult spawn_and_wait(const std::vector<std::string>& argv, const std::filesystem::path& log,
                             double timeout_seconds, const std::function<int()>& interrupted,
                             bool own_group) {
  ProcessResult r;
  const auto start = std::chrono::steady_clock::now();
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
  // Own process group, so that a time-out also ends the children (mpirun, python workers).
  if (own_group) {
    posix_spawnattr_setflags(&attr, POSIX_SPAWN_SETPGROUP);
    posix_spawnattr_setpgroup(&attr, 0);
  }
  // A run started from a rank of an MPI job must not think it is one of its ranks (a FEniCSx run
  // would join the job): the launcher's variables are left out, so it runs as its own job.
  std::vector<char*> env;
  for (char** e = environ; *e; ++e)
    if (std::strncmp(*e, "OMPI_", 5) != 0 && std::strncmp(*e, "PMIX_", 5) != 0 &&
        std::strncmp(*e, "PMI_", 4) != 0)
      env.push_back(*e);
  env.push_back(nullptr);
  pid_t pid = 0;
  const int rc = posix_spawn(&pid, cargv[0], &fa, &attr, cargv.data(), env.data());
  posix_spawn_file_actions_destroy(&fa);
  posix_spawnattr_destroy(&attr);
  if (rc != 0) {
    r.error = std::string("could not start ") + argv[0] + ": " + std::strerror(rc);
    return r;
  }
  int status = 0;
  for (;;) {
    const pid_t w = waitpid(pid, &status, WNOHANG);
    if (w == pid) break;
    if (w < 0) {
      r.error = std::string("waitpid failed: ") + std::strerror(errno);
      return r;
    }
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const int sig = interrupted ? interrupted() : 0;
    if (sig != 0) {  // forward: SIGTERM to the run's group, SIGKILL if still there after 2 s
      kill(own_group ? -pid : pid, SIGTERM);
      for (int i = 0; i < 100 && waitpid(pid, &status, WNOHANG) == 0; ++i)
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
      kill(own_group ? -pid : pid, SIGKILL);  // the group's other members (mpirun's, python's children) too
      if (waitpid(pid, &status, WNOHANG) == 0) waitpid(pid, &status, 0);
      r.timed_out = true;
      r.error = "interrupted (signal " + std::to_string(sig) + ")";
      break;
    }
    if (elapsed > timeout_seconds) {
      kill(own_group ? -pid : pid, SIGKILL);  // the whole group of this one run, by its id
      waitpid(pid, &status, 0);
      r.timed_out = true;
      r.error = "killed after the time limit of " + std::to_string(static_cast<long>(timeout_seconds)) + " s";
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
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
