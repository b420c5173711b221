#pragma once
/// @file test_scenes.hpp
/// @brief Helpers for tests: paths of the shipped scenes and small scenes built in code.

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>
#include <unistd.h>

#include <solver/scene/Scene.hpp>
#include <solver/scene/scene_io.hpp>
#include <solver/util/ScratchDir.hpp>

namespace beamimpact::testing {

/// @brief Root of the source tree: env BEAMIMPACT_SOURCE_DIR if set (to test another checkout),
/// else the path compiled in.
inline std::filesystem::path source_dir() {
  if (const char* s = std::getenv("BEAMIMPACT_SOURCE_DIR")) return s;
  return BEAMIMPACT_SOURCE_DIR_DEFAULT;
}

/// @brief The folder of this test process's temporary files, TempDir()/beamimpact_<pid>: made on
/// first use, removed with everything in it when the process exits (tests leave nothing behind).
inline const std::filesystem::path& temp_root() {
  static const ScratchDir root(std::filesystem::path(::testing::TempDir()) /
                               ("beamimpact_" + std::to_string(getpid())));
  return root.path();
}

/// @brief A temporary path private to this test process and test: ctest runs test cases as
/// parallel processes, so a fixed name in the temp folder would be shared between them.
inline std::filesystem::path temp_path(const std::string& name) {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const std::string test = info ? std::string(info->test_suite_name()) + "." + info->name() : "none";
  return temp_root() / (test + "_" + name);
}

/// @brief Path of a paper scene, e.g. paper_scene("s1_central").
inline std::string paper_scene(const std::string& name) {
  return (source_dir() / "verification/scenes/paper" / (name + ".toml")).string();
}

/// @brief Path of a benchmark scene, e.g. benchmark_scene("rod_on_wall").
inline std::string benchmark_scene(const std::string& name) {
  return (source_dir() / "verification/scenes/benchmarks" / (name + ".toml")).string();
}

/// @brief Path of a hard-case scene, e.g. hard_scene("slide_off_roller").
inline std::string hard_scene(const std::string& name) {
  return (source_dir() / "verification/scenes/hard" / (name + ".toml")).string();
}

/// @brief A paper scene loaded with --set style overrides (e.g. "time.end=1.5").
inline Scene load_paper_scene(const std::string& name, const std::vector<std::string>& overrides = {}) {
  return load_scene(paper_scene(name), overrides);
}

/// @brief A straight body from (x0, y0) to (x1, y1) with the paper's soft material (E 100, rho 1, A 0.4).
inline Body soft_body(const std::string& name, Vec2 a, Vec2 b, int elements, Vec2 v = {0, 0}) {
  Body body;
  body.name = name;
  body.start = a;
  body.end = b;
  body.elements = elements;
  body.E = 100.0;
  body.rho = 1.0;
  body.area = 0.4;
  body.inertia = 0.4 * 0.4 * 0.4 / 12.0;
  body.velocity = v;
  return body;
}

/// @brief The scene rotated by `degrees` about the origin: every body's start, end and velocity
/// (90 degrees exactly: cos 0, sin 1). Supports are left as they are: a caller whose scene has a
/// roller in global axes gives it in body axes for the same problem (Support::fix_normal).
inline Scene rotated_scene(Scene s, double degrees) {
  const double c = degrees == 90.0 ? 0.0 : std::cos(degrees * M_PI / 180.0);
  const double sn = degrees == 90.0 ? 1.0 : std::sin(degrees * M_PI / 180.0);
  const auto turn = [&](Vec2& p) { p = {c * p[0] - sn * p[1], sn * p[0] + c * p[1]}; };
  for (Body& b : s.bodies) {
    turn(b.start);
    turn(b.end);
    turn(b.velocity);
  }
  return s;
}

/// @brief S2 (the paper's transverse impact on a simply supported beam) rotated by `degrees`, its
/// target's roller across the target (fix = ["normal"]; global_roller: S2's ["y"] kept, which on
/// an inclined target is another problem).
inline Scene rotated_s2(double degrees, bool global_roller = false) {
  Scene s = rotated_scene(load_paper_scene("s2_transverse"), degrees);
  Support& roller = s.bodies[1].supports[1];
  if (!global_roller) {
    roller.fix_y = false;
    roller.fix_normal = true;
  }
  return s;
}

}  // namespace beamimpact::testing
