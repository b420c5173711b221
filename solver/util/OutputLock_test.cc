// One writer per output directory: a second lock is refused while the first is held, and the
// lock is free again after its holder ends normally or is killed.
#include <solver/util/OutputLock.hpp>

#include <csignal>
#include <fstream>
#include <string>

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <solver/testing/test_scenes.hpp>
#include <solver/util/InputError.hpp>

namespace {

namespace fs = std::filesystem;
using beamimpact::InputError;
using beamimpact::OutputLock;

fs::path fresh(const std::string& name) {
  const fs::path d = beamimpact::testing::temp_path("lock_" + name);
  fs::remove_all(d);
  return d;
}

/// The message of the refusal to lock dir ("" when the lock was taken).
std::string refusal(const fs::path& dir) {
  try {
    const OutputLock second(dir);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(OutputLock, SecondWriterRefusedNamingTheDirectoryAndTheHolder) {
  const fs::path d = fresh("second");
  const OutputLock first(d);
  std::ofstream(d / "summary.json") << "{\"complete\": true}\n";  // the first writer's output
  const std::string why = refusal(d);
  EXPECT_NE(why.find(d.string()), std::string::npos) << why;
  EXPECT_NE(why.find("pid " + std::to_string(getpid())), std::string::npos) << why;
  EXPECT_EQ(why.find('\n'), std::string::npos) << "one line: " << why;
  std::ifstream in(d / "summary.json");
  EXPECT_EQ(std::string(std::istreambuf_iterator<char>(in), {}), "{\"complete\": true}\n") << "untouched";
}

TEST(OutputLock, FreeAfterTheHolderEnds) {
  const fs::path d = fresh("free");
  { const OutputLock first(d); }
  EXPECT_EQ(refusal(d), "");
  EXPECT_TRUE(fs::exists(OutputLock::file(d))) << "the file stays; only the lock goes";
}

TEST(OutputLock, FreeAfterTheHolderIsKilled) {
  const fs::path d = fresh("killed");
  int ready[2];
  ASSERT_EQ(pipe(ready), 0);
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {  // the holder: takes the lock, says so, then waits to be killed
    try {
      const OutputLock held(d);
      (void)!write(ready[1], "1", 1);
      for (;;) pause();
    } catch (...) {
      _exit(1);  // never back into the test framework
    }
  }
  char c = 0;
  ASSERT_EQ(read(ready[0], &c, 1), 1);
  EXPECT_NE(refusal(d).find("pid " + std::to_string(child)), std::string::npos) << "held by the child";
  kill(child, SIGKILL);
  int status = 0;
  waitpid(child, &status, 0);
  ASSERT_TRUE(WIFSIGNALED(status));
  EXPECT_EQ(refusal(d), "") << "the kernel released the killed holder's lock";
  close(ready[0]);
  close(ready[1]);
}

TEST(OutputLock, NoDirectoryNoLock) {
  EXPECT_NO_THROW({
    const OutputLock none{fs::path()};
    const OutputLock again{fs::path()};  // nothing is locked, so nothing refuses
  });
}

}  // namespace
