#include <api/registry.hpp>
#include <api/run.hpp>

#include <filesystem>
#include <set>

#include <gtest/gtest.h>

#include <solver/testing/test_scenes.hpp>
#include <solver/util/InputError.hpp>

namespace beamimpact {
namespace {

// The built-in methods are compiled in; FEniCSx comes from the repository's methods file
// (verification/methods.toml, found from the program upwards) through the same door as a user's.
TEST(Registry, HasEveryMethodOnceWithWhatItAccepts) {
  for (const char* name : {"paper", "exact", "ida", "fenicsx"}) ASSERT_NE(find_method(name), nullptr) << name;
  std::set<std::string> names;
  for (const Method& m : methods()) EXPECT_TRUE(names.insert(m.name).second) << m.name << " twice";
  EXPECT_EQ(methods().front().name, "paper");
  EXPECT_TRUE(find_method("paper")->in_process());
  EXPECT_EQ(find_method("paper")->origin, "built-in");
  const Method& fenicsx = *find_method("fenicsx");
  EXPECT_FALSE(fenicsx.in_process());
  EXPECT_EQ(std::filesystem::path(fenicsx.origin).filename(), "methods.toml") << fenicsx.origin;
  EXPECT_FALSE(fenicsx.accepts.dt);  // it picks its own stable step
  EXPECT_FALSE(find_method("ida")->accepts.search);
  // Exact solutions take the Hertz law for a rigid striker on a beam only and a Timoshenko beam as
  // the target of a rod only (their recogniser refuses the rest); IDA shares the element matrices
  // and runs the scene's Hertz spring; the continuum has neither.
  EXPECT_TRUE(find_method("exact")->accepts.timoshenko);
  EXPECT_TRUE(find_method("exact")->accepts.hertz);
  EXPECT_TRUE(find_method("ida")->accepts.timoshenko && find_method("ida")->accepts.hertz);
  EXPECT_FALSE(fenicsx.accepts.timoshenko || fenicsx.accepts.hertz);
  EXPECT_EQ(find_method("bogus"), nullptr);
  try {
    method("bogus", "matrix.toml", "method");
    FAIL() << "no error for an unknown method";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("matrix.toml"), std::string::npos) << m;
    EXPECT_NE(m.find("paper, exact, ida, fenicsx"), std::string::npos) << m;
  }
}

// What a method does not take (Method::Accepts) is refused by api::run, the one place that checks
// it for every method: the scene file, the key and what the scene should say instead are named.
TEST(Api, RefusesWhatTheMethodDoesNotTakeNamingFileKeyAndExpected) {
  struct Case {
    std::string method;
    std::vector<std::string> set;
    std::string key, expected;
  };
  const Case cases[] = {
      {"ida", {"contacts[0].node=\"all\""}, "contacts[0].node", "expected one declared node"},
      {"exact", {"contacts[0].node=\"all\""}, "contacts[0].node", "expected one declared node"},
      {"fenicsx", {"bodies.B.theory=timoshenko"}, "bodies[1].theory", "expected \"euler-bernoulli\""},
  };
  for (const Case& c : cases) {
    try {
      run(testing::paper_scene("s1_central"), c.method, RunOptions{c.set, std::nullopt});
      ADD_FAILURE() << c.method << " ran " << c.key;
    } catch (const InputError& e) {
      const std::string what = e.what();
      EXPECT_EQ(e.key(), c.key) << what;
      EXPECT_NE(what.find("s1_central.toml"), std::string::npos) << what;
      EXPECT_NE(what.find("not applicable: method '" + c.method + "' does not take"), std::string::npos)
          << what;
      EXPECT_NE(what.find(c.expected), std::string::npos) << what;
    }
  }
}

// S1 (two equal free rods, references.md 1): the exact impulse is m v0 / 2 = 4 N s. The
// one-call API must give it through the registry, and the paper's 10-element run is within its
// documented mesh error (-3.6 %, 5 % bound).
TEST(Api, RunsASceneFileByMethodName) {
  const auto scene = testing::paper_scene("s1_central");
  EXPECT_NEAR(run(scene, "exact").contacts.at(0).impulse_normal, 4.0, 1e-9);
  const SimulationResult p = run(scene, "paper");
  EXPECT_EQ(p.method, "paper");
  EXPECT_NEAR(p.contacts.at(0).impulse_normal, 4.0, 0.2);
  EXPECT_FALSE(p.contact_sampling.empty());
}

TEST(Api, WritesTheRunDirectoryAndNeedsOneForExternalMethods) {
  const auto dir = std::filesystem::temp_directory_path() / ("beamimpact_api_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  run(testing::paper_scene("s1_central"), "paper", RunOptions{{"time.end=1.0"}, dir});
  EXPECT_TRUE(std::filesystem::exists(dir / "summary.json"));
  EXPECT_TRUE(std::filesystem::exists(dir / "history.csv"));
  std::filesystem::remove_all(dir);
  // An external method writes its run into a directory: none given is bad input.
  EXPECT_THROW(run(testing::paper_scene("s1_central"), "fenicsx"), InputError);
  EXPECT_THROW(run(testing::paper_scene("s1_central"), "no_such_method"), InputError);
}

}  // namespace
}  // namespace beamimpact
