// The reflection memory's interpolation against functions known in closed form.
#include <references/exact/DelayMemory.hpp>

#include <cmath>

#include <gtest/gtest.h>

namespace beamimpact::exact {
namespace {

TEST(DelayMemory, InterpolatesSmoothPiecesAndKeepsJumps) {
  // sin(w t) sampled a quarter radian apart: the degree-11 Lagrange bound is (h w)^12 / 12
  // = 5e-9 at a piece end (see DelayMemory.cc); a jump at t = 1 must not leak into either side.
  const double w = 3.0, h = 0.25 / w;
  DelayMemory m;
  m.start_piece(0.0);
  for (double t = 0.0; t < 1.0; t += h) m.add(t, std::sin(w * t));
  m.add(1.0, std::sin(w * 1.0));
  m.start_piece(1.0);
  for (double t = 1.0; t <= 2.0 + 1e-12; t += h) m.add(t, 5.0 + std::cos(w * t));
  for (double t : {0.013, 0.37, 0.999}) EXPECT_NEAR(m.value(t), std::sin(w * t), 5e-9) << t;
  for (double t : {1.0, 1.001, 1.5, 1.99}) EXPECT_NEAR(m.value(t), 5.0 + std::cos(w * t), 5e-9) << t;
  EXPECT_EQ(m.value(-0.1), 0.0);  // nothing before the first piece
  EXPECT_EQ(m.piece_at(0.999), 0);
  EXPECT_EQ(m.piece_at(1.0), 1);
  // Asking piece 0 explicitly right at its end uses its own samples, not the jump.
  EXPECT_NEAR(m.value(0, 1.0), std::sin(w * 1.0), 5e-9);
}

}  // namespace
}  // namespace beamimpact::exact
