// A sliding contact re-forms its response columns dt^2 H G every step it moves along the target.
// With dt^2 H diagonal (lumped, undamped) they are formed on the row's equations alone: the
// forces, gaps and slips must be those of the columns formed through apply_H over every
// equation, to the bit, also after the contact point has moved to other elements (whose
// earlier entries must then be gone from the column).
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <Eigen/Core>

#include <solver/contact/ContactSolver.hpp>
#include <solver/contact/contact_search.hpp>
#include <solver/model/Effects.hpp>
#include <solver/model/MassSolver.hpp>
#include <solver/model/Model.hpp>
#include <solver/scene/scene_io.hpp>
#include <solver/testing/test_scenes.hpp>

namespace beamimpact::paper {
namespace {

TEST(ContactSolver, ColumnsOnTheRowsEquationsGiveTheForcesOfTheFullProduct) {
  // Every striker node a pair (a contact search): the solve reads each pair's row against the
  // others' columns, so a column must hold nothing at its earlier equations.
  const std::vector<std::string> sets = {"contacts[0].friction=0.3", "bodies.A.elements=20",
                                         "bodies.B.elements=40"};
  const int declared = load_scene(testing::paper_scene("s2_transverse"), sets).contacts[0].node;
  std::vector<std::string> search = sets;
  search.push_back("contacts[0].node=\"all\"");
  const Scene s = load_scene(testing::paper_scene("s2_transverse"), search);
  const Model m(s, derive_effects(s).bending);
  const MassSolver minv(m);
  const double dt = 1e-6;
  const auto apply_H = [&](const Eigen::VectorXd& f, Eigen::VectorXd& out) {
    minv.apply(f, out);
    out *= dt * dt;
  };
  ContactPairs full = make_contact_pairs(m, s, SurfaceInterpolation::kLinear);
  ContactPairs diag = make_contact_pairs(m, s, SurfaceInterpolation::kLinear);
  const std::vector<double> mu(full.pairs.size(), 0.3), tol(full.pairs.size(), 1e-12);
  ContactSolver a(full.pairs, mu, true, m.size(), tol, apply_H);
  ContactSolver b(diag.pairs, mu, true, m.size(), tol, apply_H);
  b.set_diagonal_response(&minv.inverse_diagonal(), dt * dt);

  const Contact& c = s.contacts[0];
  const int node = m.node_id(c.striker, declared);
  const int ex = m.equation(node, 0), ey = m.equation(node, 1);
  Eigen::VectorXd U = Eigen::VectorXd::Zero(m.size()), Ubar = U;
  std::size_t k0 = 0;  // the pressed node's pair
  while (k0 < full.pairs.size() && full.pairs[k0].striker_node() != node) ++k0;
  ASSERT_LT(k0, full.pairs.size());
  const double gap = a.solve(Ubar, U)[k0].gap_next;  // open: the initial gap
  (void)b.solve(Ubar, U);
  ASSERT_GT(gap, 0.0);
  ASSERT_GT(full.pairs.size(), 2u);
  const double element = s.bodies[c.target].length() / s.bodies[c.target].elements;
  int slipping = 0;
  for (int p = 1; p <= 40; ++p) {
    // The striker's node pressed 1 mm into the beam while it slides 0.1 element a step: four
    // elements in all, so its contact point moves on to other elements.
    Ubar(ey) = -(gap + 1e-3);
    Ubar(ex) = 0.1 * element * p;
    const std::vector<ContactForce>& fa = a.solve(Ubar, U);
    const std::vector<ContactForce>& fb = b.solve(Ubar, U);
    ASSERT_GT(fa[k0].R, 0.0) << "step " << p;
    slipping += fa[k0].state == ContactState::kSlip;
    for (std::size_t k = 0; k < fa.size(); ++k) {
      EXPECT_EQ(fb[k].R, fa[k].R) << "step " << p;
      EXPECT_EQ(fb[k].tau, fa[k].tau) << "step " << p;
      EXPECT_EQ(fb[k].gap_next, fa[k].gap_next) << "step " << p;
      EXPECT_EQ(fb[k].slip_next, fa[k].slip_next) << "step " << p;
      EXPECT_EQ(fb[k].state, fa[k].state) << "step " << p;
    }
    U = Ubar;
  }
  EXPECT_GT(slipping, 10) << "the steps compared must slide (and relocate the contact point)";
}

}  // namespace
}  // namespace beamimpact::paper
