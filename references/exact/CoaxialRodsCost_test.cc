// The coaxial-rod cost estimate against breakpoints counted by hand and against the pieces of
// real solutions, and the exact method refusing an extraordinary end time before it starts.
#include <references/exact/CoaxialRodsCost.hpp>

#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include <references/exact/CoaxialRods.hpp>
#include <references/exact/solve.hpp>
#include <solver/testing/test_scenes.hpp>
#include <solver/util/InputError.hpp>

namespace beamimpact::exact {
namespace {

constexpr double kMerge = 1e-12;  // s: far below every gap between the sums listed by hand

TEST(CoaxialRodsCost, BreakpointSumsByHand) {
  // T_A = 1, T_B = 1.5 s (2 T_B = 3 T_A): a + 1.5 b below 5.1 s are 0, 1, 1.5, 2, 2.5, 3, 3.5,
  // 4, 4.5, 5: ten (1 + 1.5 = 2.5 = 2.5 and 2 x 1.5 = 3 = 3 x 1 are one each).
  EXPECT_EQ(breakpoint_sums(1.0, 1.5, 5.1, kMerge), 10.0);
  // T_B = sqrt(2) s, incommensurate: b = 0: a = 0..3 (4), b = 1: a + 1.414 < 3.5, a = 0..2 (3),
  // b = 2: a + 2.828 < 3.5, a = 0 (1): eight.
  EXPECT_EQ(breakpoint_sums(1.0, std::sqrt(2.0), 3.5, kMerge), 8.0);
  // The second-contact benchmark (T_A = 2, T_B = 2.8 s: multiples m of 0.4 s with m = 5 a + 7 b)
  // over 6.5 s: m = 0, 5, 7, 10, 12, 14, 15 (16 and below), seven.
  EXPECT_EQ(breakpoint_sums(2.0, 2.8, 6.5, kMerge), 7.0);
  EXPECT_EQ(breakpoint_sums(2.0, 2.8, 0.0, kMerge), 0.0);
}

// The second-contact benchmark's rods (verification/scenes/benchmarks/two_rods_second_contact.toml):
// A 10 m, Z_A = 4 N s/m, T_A = 2 s; B 14 m clamped, Z_B = 8 N s/m, T_B = 2.8 s; 1 m/s across
// 0.5 m (t0 = 0.5 s).
const Rod kA{10.0, 100.0, 1.0, 0.4};
const Rod kB{14.0, 200.0, 2.0, 0.4};

TEST(CoaxialRodsCost, PredictsThePiecesOfARun) {
  // Clamped target: the re-contact at 4.1 s = t0 + 9 x 0.4 s starts a family of its own, whose
  // sums 9, 16 and 23 (x 0.4 s after t0) are no 5 a + 7 b: three pieces more than estimated
  // however long the run (by hand: 10 pieces to 7 s where the estimate counts 1 + 7).
  EXPECT_EQ(estimate_coaxial_rods_cost(kA, kB, 1.0, 0.5, 7.0, 0.05).pieces, 8.0);
  const CoaxialRods short_run(kA, kB, 1.0, 0.5, 7.0, FarEnd::kFixed);
  EXPECT_EQ(short_run.segments().size(), 10u);
  const CoaxialRods run(kA, kB, 1.0, 0.5, 100.0, FarEnd::kFixed);
  const CoaxialRodsCost c = estimate_coaxial_rods_cost(kA, kB, 1.0, 0.5, 100.0, 0.05);
  const double pieces = static_cast<double>(run.segments().size());
  EXPECT_LE(c.pieces, pieces);
  EXPECT_GE(c.pieces, 0.95 * pieces) << "within 5 %: the re-contact's family only";
  EXPECT_EQ(c.rows, 2001.0);  // 0, 0.05, ..., 100 s
  // Free rods (one contact period, CoaxialRodsRecontact_test.cc) with incommensurate round trips
  // (T_B = 2 sqrt(2) s): every sum is a distinct breakpoint, about span^2 / (2 T_A T_B) of them.
  const Rod b{10.0 * std::sqrt(2.0), 100.0, 1.0, 0.4};
  const CoaxialRods free_run(kA, b, 1.0, 0.5, 60.0, FarEnd::kFree);
  ASSERT_EQ(free_run.force_intervals().size(), 1u);
  EXPECT_EQ(estimate_coaxial_rods_cost(kA, b, 1.0, 0.5, 60.0, 0.05).pieces,
            static_cast<double>(free_run.segments().size()));
}

TEST(CoaxialRodsCost, ExactRefusesAnExtraordinaryEndBeforeStarting) {
  // The benchmark with B 10 sqrt(2) m long (T_B = 2 sqrt(2) s, incommensurate with T_A = 2 s) to
  // 1e5 s: about span^2 / (2 T_A T_B) = 1e10 / 11.31 = 8.84e8 pieces (78 GB). Refused
  // at once, naming the key, the estimate and the setting that allows it; the shipped 7 s are
  // ordinary.
  const Scene scene = load_scene(testing::benchmark_scene("two_rods_second_contact"),
                                 {"time.end=1e5", "bodies[1].end=[24.64213562373095, 0.0]"});
  try {
    (void)solve(scene);
    FAIL() << "solved 8.84e8 pieces";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_EQ(e.key(), "time.end") << m;
    EXPECT_NE(m.find("8.84e+08 pieces"), std::string::npos) << m;
    EXPECT_NE(m.find("time.allow_long_run = true"), std::string::npos) << m;
  }
  const CoaxialRodsCost shipped = estimate_coaxial_rods_cost(kA, kB, 1.0, 0.5, 7.0, 0.05);
  EXPECT_LT(shipped.seconds(), 1.0);
  EXPECT_LT(shipped.bytes, 1e6);
}

}  // namespace
}  // namespace beamimpact::exact
