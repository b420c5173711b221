#include <tools/beamimpact/testing/cli_run.hpp>

#include <sched.h>
#include <sys/wait.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <thread>

#include <solver/testing/test_scenes.hpp>

namespace beamimpact::testing {

namespace fs = std::filesystem;

CliResult run_cli(const std::string& args, const std::string& prefix) {
  const std::string cmd = std::string("cd ") + shell_words({BEAMIMPACT_SOURCE}) + " && " + prefix + " " +
                          shell_words({BEAMIMPACT_EXE}) + " " + args + " 2>&1";
  FILE* pipe = popen(cmd.c_str(), "r");
  if (!pipe) return {-1, "popen failed: " + cmd};
  std::string out;
  std::array<char, 4096> buf;
  while (std::fgets(buf.data(), buf.size(), pipe)) out += buf.data();
  const int status = pclose(pipe);
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, out};
}

std::string shell_words(const std::vector<std::string>& args) {
  std::string words;
  for (const std::string& a : args) {
    if (!words.empty()) words += ' ';
    words += '\'';
    for (const char c : a) words += c == '\'' ? std::string("'\\''") : std::string(1, c);
    words += '\'';
  }
  return words;
}

int cores_of_this_process() {
  int cores = std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  cpu_set_t set;
  CPU_ZERO(&set);
  if (sched_getaffinity(0, sizeof(set), &set) == 0 && CPU_COUNT(&set) > 0)
    cores = std::min(cores, CPU_COUNT(&set));
  return cores;
}

std::string read_file(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::vector<int> processes_mentioning(const std::string& text, int except) {
  std::vector<int> found;
  std::error_code ec;  // a process that ends while listed is passed over
  for (const auto& e : fs::directory_iterator("/proc", ec)) {
    const std::string name = e.path().filename();
    if (name.find_first_not_of("0123456789") != std::string::npos || std::stoi(name) == except) continue;
    if (read_file(e.path() / "cmdline").find(text) != std::string::npos) found.push_back(std::stoi(name));
  }
  return found;
}

fs::path fresh_dir(const std::string& name) {
  const fs::path d = temp_path(name);
  fs::remove_all(d);
  return d;
}

void CliTest::SetUp() {
  tmp_ = fresh_dir("tmp");
  fs::create_directories(tmp_);
}

void CliTest::TearDown() { fs::remove_all(tmp_); }

}  // namespace beamimpact::testing
