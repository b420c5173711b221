#pragma once
/// @file cli_run.hpp
/// @brief The CLI tests' one fixture: run the built `beamimpact` program in the source root and
/// keep what it printed and its exit code, read a file whole, and a scratch folder per test.

#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace beamimpact::testing {

/// @brief How a command ended and what it printed.
struct CliResult {
  int code;            ///< exit code; -1 when a signal ended it
  std::string output;  ///< stdout and stderr together, in the order written
};

/// @brief Runs `prefix beamimpact args` through the shell in the source root (relative paths in
/// args are the repository's) and waits for its end.
/// @param args the arguments as shell words: the caller quotes what needs it (see shell_words)
/// @param prefix words before the program, e.g. "timeout 120" or "mpirun -n 2" ("" none)
CliResult run_cli(const std::string& args, const std::string& prefix = "");

/// @brief The arguments as one string of single-quoted shell words (a ' inside is escaped).
/// @param args the arguments, each one word whatever it holds
std::string shell_words(const std::vector<std::string>& args);

/// @brief The cores this test process may run on, from the system's own answers (not the
/// program's): the hardware threads, fewer under a CPU affinity mask (taskset, a cpuset). A run
/// asked for more threads takes this many.
int cores_of_this_process();

/// @brief The file's bytes; "" when it cannot be opened (the caller's check then fails).
/// @param file the file to read
std::string read_file(const std::filesystem::path& file);

/// @brief The processes whose command line (/proc/PID/cmdline) mentions `text`.
/// @param text what the command line holds, e.g. an output folder
/// @param except a process id left out (the caller's child whose arguments hold the text; 0 none)
std::vector<int> processes_mentioning(const std::string& text, int except = 0);

/// @brief A temporary path private to this test process and test (temp_path of
/// solver/testing/test_scenes.hpp), removed with everything in it if it exists; not created.
/// @param name the path's last part, unique within the test
std::filesystem::path fresh_dir(const std::string& name);

/// @brief A test with its own empty scratch folder tmp_, made before each test and removed after.
class CliTest : public ::testing::Test {
 protected:
  void SetUp() override;
  void TearDown() override;
  /// @brief run_cli(args, prefix).
  /// @param args the arguments as shell words
  /// @param prefix words before the program ("" none)
  static CliResult run(const std::string& args, const std::string& prefix = "") {
    return run_cli(args, prefix);
  }
  /// @brief read_file(file).
  /// @param file the file to read
  static std::string read(const std::filesystem::path& file) { return read_file(file); }

  std::filesystem::path tmp_;  ///< this test's scratch folder
};

}  // namespace beamimpact::testing
