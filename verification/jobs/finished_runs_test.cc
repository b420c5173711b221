// A finished run is taken again only from the same program, known by its bytes, not by its
// version string: two builds of an edited tree have the same `-dirty` version, and a verify after
// a code change must judge the new code on its own runs.
#include <verification/jobs/finished_runs.hpp>
#include <verification/jobs/program_id.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <solver/testing/test_scenes.hpp>
#include <solver/util/sha256.hpp>

namespace beamimpact::jobs {
namespace {

namespace fs = std::filesystem;

std::string read(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// This test program links the libraries statically: the code is in its own executable, whose
// bytes are the id.
TEST(FinishedRuns, TheProgramIsNamedByTheBytesOfItsCode) {
  const fs::path exe = fs::read_symlink("/proc/self/exe");
  EXPECT_EQ(fs::canonical(program_code_file()), fs::canonical(exe));
  const std::string sha = file_sha256(exe);
  ASSERT_EQ(sha.size(), 64u);
  EXPECT_EQ(program_input().at("program_sha256"), sha);
  EXPECT_EQ(&program_sha256(), &program_sha256());  // read once, kept
}

/// Runs `exe verify matrix --out out` in the source root; what it printed.
std::string verify(const fs::path& exe, const fs::path& matrix, const fs::path& out) {
  const fs::path log = out.string() + ".log";
  const std::string cmd = fmt::format("cd '{}' && '{}' verify '{}' --out '{}' > '{}' 2>&1", BEAMIMPACT_SOURCE,
                                      exe.string(), matrix.string(), out.string(), log.string());
  const int status = std::system(cmd.c_str());
  EXPECT_EQ(status, 0) << read(log);
  return read(log);
}

// The program copied twice: `a` byte for byte, `b` with one byte appended (the same code, the
// same version string, another build's bytes). Runs made by `a` are taken by `a` and by an
// identical copy anywhere, never by `b`; `b`'s own runs are then taken by `b`.
TEST(FinishedRuns, AnotherBuildWithTheSameVersionRunsAgain) {
  const fs::path tmp = testing::temp_path("builds");
  fs::create_directories(tmp / "a");
  fs::create_directories(tmp / "a2");
  fs::create_directories(tmp / "b");
  for (const char* d : {"a", "a2", "b"}) fs::copy_file(BEAMIMPACT_EXE, tmp / d / "beamimpact");
  std::ofstream(tmp / "b/beamimpact", std::ios::app | std::ios::binary) << '\n';
  for (const char* d : {"a", "a2", "b"})
    fs::permissions(tmp / d / "beamimpact", fs::perms::owner_all, fs::perm_options::add);
  fs::copy_file(testing::paper_scene("s1_central"), tmp / "s1.toml");
  std::ofstream(tmp / "m.toml")
      << "[settings]\nroot = \".\"\n[scenes]\ns1 = \"s1.toml\"\n[[case]]\n"
         "scene = \"s1\"\nmethod = \"paper\"\nreference = { method = \"exact\" }\n"
         "gates = [{ metric = \"impulse\", tol = 0.05, why = \"the paper at the scene step is within 0.2 % "
         "of the exact impulse; a loose bound: this test is about reuse\" }]\n";
  const fs::path out = tmp / "v";
  const std::string resumed = "resumed: 2 of 2 runs";
  EXPECT_EQ(verify(tmp / "a/beamimpact", tmp / "m.toml", out).find("resumed:"), std::string::npos);
  EXPECT_NE(verify(tmp / "a/beamimpact", tmp / "m.toml", out).find(resumed), std::string::npos);
  EXPECT_NE(verify(tmp / "a2/beamimpact", tmp / "m.toml", out).find(resumed), std::string::npos)
      << "the same bytes elsewhere are the same program";
  const std::string rebuilt = verify(tmp / "b/beamimpact", tmp / "m.toml", out);
  EXPECT_EQ(rebuilt.find("resumed:"), std::string::npos) << rebuilt;
  EXPECT_NE(verify(tmp / "b/beamimpact", tmp / "m.toml", out).find(resumed), std::string::npos);
}

}  // namespace
}  // namespace beamimpact::jobs
