// `mpirun -n 2 beamimpact verify|sweep|study` against the serial run: the same verdicts and the
// same numbers to the last digit (JSON doubles are written with 17 significant digits, so an
// exact comparison of the parsed values is a comparison to the last bit). Only timing fields,
// the start time, the command line and the output directory may differ. Registered when the
// build has MPI. As root, OpenMPI needs OMPI_ALLOW_RUN_AS_ROOT(_CONFIRM), set here.
#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <thread>
#include <vector>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <tools/beamimpact/testing/cli_run.hpp>

extern char** environ;

namespace beamimpact {
namespace {

namespace fs = std::filesystem;

class MpiIdentity : public testing::CliTest {
 protected:
  void SetUp() override {
    CliTest::SetUp();
    if (::geteuid() == 0) {
      ::setenv("OMPI_ALLOW_RUN_AS_ROOT", "1", 1);
      ::setenv("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1", 1);
    }
  }

  /// Runs beamimpact with args (OUT replaced by out) serially or under mpirun -n 2; what it printed.
  static std::string run(const std::string& args, const fs::path& out, bool mpi) {
    const std::string prefix = mpi ? fmt::format("'{}' --oversubscribe -n 2", MPIEXEC) : "";
    std::string a = args;
    a.replace(a.find("OUT"), 3, out.string());
    const testing::CliResult r = testing::run_cli(a, prefix);
    EXPECT_EQ(r.code, 0) << r.output;
    if (mpi) {
      EXPECT_NE(r.output.find("rank 1"), std::string::npos) << "rank 1 did no work:\n" << r.output;
    }
    return r.output;
  }

 public:
  /// The document without timing fields, start time and command, output directory replaced.
  static nlohmann::json stripped(const fs::path& file, const fs::path& out) {
    std::string text = read(file);
    for (std::size_t p; (p = text.find(out.string())) != std::string::npos;)
      text.replace(p, out.string().size(), "OUT");
    nlohmann::json j = nlohmann::json::parse(text);
    strip(j);
    return j;
  }
  static void strip(nlohmann::json& j) {
    if (j.is_object()) {
      for (const char* k : {"started_utc", "command"}) j.erase(k);
      for (auto it = j.begin(); it != j.end();) {
        if (it.key().ends_with("_seconds") || it.key() == "time") {
          it = j.erase(it);
        } else {
          strip(*it);
          ++it;
        }
      }
    } else if (j.is_array()) {
      for (auto& e : j) strip(e);
    }
  }
};

// Subset of the quick tier: every S1 case, ladder and check (23 runs of paper, IDA, exact and
// FEniCSx, about 3 s); the whole quick tier takes minutes (notes/issue17.md: identical too).
TEST_F(MpiIdentity, VerifyGivesTheSameVerdictsAndNorms) {
  const std::string args = "verify verification/matrix.toml --tier quick --only s1_central --out OUT";
  run(args, tmp_ / "serial", false);
  run(args, tmp_ / "mpi", true);
  const auto a = stripped(tmp_ / "serial/norms.json", tmp_ / "serial");
  const auto b = stripped(tmp_ / "mpi/norms.json", tmp_ / "mpi");
  ASSERT_FALSE(a.at("items").empty());
  EXPECT_EQ(a, b);
}

TEST_F(MpiIdentity, SweepGivesTheSameNorms) {
  const std::string args =
      "sweep verification/scenes/paper/s1_central.toml --dt 0.01,0.005 --mesh 1,2 --out OUT";
  run(args, tmp_ / "serial", false);
  run(args, tmp_ / "mpi", true);
  const auto a = stripped(tmp_ / "serial/sweep.json", tmp_ / "serial");
  ASSERT_EQ(a.at("points").size(), 4u);
  EXPECT_EQ(a, stripped(tmp_ / "mpi/sweep.json", tmp_ / "mpi"));
}

/// A 12-point study of S4 (time.end in s: 0.03 takes a few hundredths of a second a point).
fs::path write_study(const fs::path& dir, double end) {
  const fs::path study = dir / "s.toml";
  std::ofstream(study)
      << "name = \"mpi\"\nscene = \"" << BEAMIMPACT_SOURCE
      << "/verification/scenes/paper/s4_oblique_90.toml\"\nmethods = [\"paper\"]\n"
         "reference = { method = \"paper\", set = [\"time.fraction=0.125\"] }\n"
         "set = [\"model.kinematics=linear\", \"time.end="
      << end
      << "\", \"bodies.A.end=[5.0, 0.001]\"]\n"
         "[design]\nkind = \"lhs\"\nsamples = 12\n"
         "[[parameter]]\nname = \"alpha0\"\nrake = \"A\"\nfrom = 5.0\nto = 90.0\n"
         "[[parameter]]\nname = \"mu\"\nkey = \"contacts[0].friction\"\nfrom = 0.0\nto = 1.0\n"
         "[[parameter]]\nname = \"mesh\"\nmesh = true\nvalues = [1, 2]\n";
  return study;
}

TEST_F(MpiIdentity, StudyTablesAreByteIdentical) {
  const fs::path study = write_study(tmp_, 0.03);
  run("study " + study.string() + " --out OUT", tmp_ / "serial", false);
  run("study " + study.string() + " --out OUT", tmp_ / "mpi", true);
  for (const char* f : {"study.csv", "study.json"}) {
    const std::string a = read(tmp_ / "serial" / f);
    ASSERT_FALSE(a.empty()) << f;
    EXPECT_EQ(a, read(tmp_ / "mpi" / f)) << f;
  }
}

/// The process of MPI rank `rank` whose command line mentions `text` (0 when there is none).
pid_t rank_process(int rank, const std::string& text) {
  const std::string tag = fmt::format("OMPI_COMM_WORLD_RANK={}", rank);
  for (const auto& e : fs::directory_iterator("/proc")) {
    const std::string name = e.path().filename();
    if (name.find_first_not_of("0123456789") != std::string::npos) continue;
    std::string env = testing::read_file(e.path() / "environ");
    std::replace(env.begin(), env.end(), '\0', '\n');
    if (testing::read_file(e.path() / "cmdline").find(text) != std::string::npos &&
        (env + "\n").find("\n" + tag + "\n") != std::string::npos)
      return std::stoi(name);
  }
  return 0;
}

// A worker rank killed (SIGKILL) once two points are recorded ends the MPI job (rank 0 goes on
// recording until mpirun ends it); the same command again takes the recorded points and runs the
// rest, and the tables equal the serial run's byte for byte (time.end 1 s: a few tenths of a
// second a point, so the job ends before the last point).
TEST_F(MpiIdentity, StudyWithAKilledRankResumesToTheSameTables) {
  const fs::path study = write_study(tmp_, 1.0);
  run("study " + study.string() + " --out OUT", tmp_ / "serial", false);
  const fs::path out = tmp_ / "mpi";
  std::vector<std::string> args = {MPIEXEC, "--oversubscribe", "-n",    "2",         BEAMIMPACT_EXE,
                                   "study", study.string(),    "--out", out.string()};
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t fa;
  posix_spawn_file_actions_init(&fa);
  posix_spawn_file_actions_addopen(&fa, 1, (tmp_ / "killed.log").c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&fa, 1, 2);
  posix_spawn_file_actions_addchdir_np(&fa, BEAMIMPACT_SOURCE);
  pid_t mpirun = 0;
  ASSERT_EQ(posix_spawn(&mpirun, argv[0], &fa, nullptr, argv.data(), environ), 0);
  posix_spawn_file_actions_destroy(&fa);
  auto recorded = [&] {
    std::error_code ec;
    int n = 0;
    for (const auto& e : fs::directory_iterator(out / "points", ec)) n += e.path().extension() == ".json";
    return n;
  };
  int status = 0;
  pid_t worker = 0;
  while (recorded() < 2 || (worker = rank_process(1, out.string())) == 0) {  // polled, not timed
    ASSERT_EQ(waitpid(mpirun, &status, WNOHANG), 0) << "the study ended first:\n"
                                                    << read(tmp_ / "killed.log");
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  kill(worker, SIGKILL);
  ASSERT_EQ(waitpid(mpirun, &status, 0), mpirun);
  EXPECT_FALSE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << read(tmp_ / "killed.log");
  ASSERT_FALSE(fs::exists(out / "study.csv")) << read(tmp_ / "killed.log");
  const int finished = recorded();
  ASSERT_LT(finished, 12);
  const std::string log = run("study " + study.string() + " --out OUT", out, true);
  EXPECT_NE(log.find(fmt::format("resumed: {} of 12 points", finished)), std::string::npos) << log;
  for (const char* f : {"study.csv", "study.json"}) EXPECT_EQ(read(out / f), read(tmp_ / "serial" / f)) << f;
}

}  // namespace
}  // namespace beamimpact
