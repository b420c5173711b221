#include <solver/integrator/CorotationalMass.hpp>

#include <solver/model/frame_element.hpp>

namespace beamimpact::paper {

CorotationalMass::CorotationalMass(const Model& model, const InternalForce& fint)
    : model_(model),
      fint_(fint),
      dir_(fint.corotational_elements().size()),
      rotating_body_(model.num_bodies(), 0) {
  // Pattern: the full M plus explicit zeros where rotating elements may put mass at any angle
  // (their 6x6 blocks); values: M minus the rotating elements' reference contribution.
  std::vector<Eigen::Triplet<double>> t;
  for (int e : fint.corotational_elements()) {
    const Model::Element& el = model.elements()[e];
    rotating_body_[el.body] = 1;
    const Eigen::MatrixXd& Me = model.reference_mass(e);
    const Eigen::Matrix<int, 6, 1> eq = model.element_equations(e);
    for (int i = 0; i < 6; ++i)
      for (int j = 0; j < 6; ++j)
        if (eq(i) >= 0 && eq(j) >= 0) t.emplace_back(eq(i), eq(j), -Me(i, j));
  }
  SparseMatrix R(model.size(), model.size());
  R.setFromTriplets(t.begin(), t.end());
  M_fixed_ = model.M() + R;  // keeps the union pattern (entries may be zero)
  M_ = model.M() + 0.0 * R;  // same pattern, reference values
  M_fixed_.makeCompressed();
  M_.makeCompressed();
}

void CorotationalMass::update(const Eigen::VectorXd& U) {
  std::copy(M_fixed_.valuePtr(), M_fixed_.valuePtr() + M_fixed_.nonZeros(), M_.valuePtr());
  const auto& els = fint_.corotational_elements();
  for (std::size_t k = 0; k < els.size(); ++k) {
    const int e = els[k];
    dir_[k] = fint_.chord_direction(e, U);
    const Mat6 Me = to_global(frame_mass_consistent_local(model_.elements()[e].rho, model_.elements()[e].area,
                                                          model_.elements()[e].length),
                              dir_[k][0], dir_[k][1]);
    const Eigen::Matrix<int, 6, 1> eq = model_.element_equations(e);
    for (int i = 0; i < 6; ++i)
      for (int j = 0; j < 6; ++j)
        if (eq(i) >= 0 && eq(j) >= 0) M_.coeffRef(eq(i), eq(j)) += Me(i, j);
  }
}

double CorotationalMass::momentum(int b, int c, const Eigen::VectorXd& V) const {
  if (!rotating_body_[b]) return model_.momentum_covector(b, c).dot(V);
  // Sum over the body's elements of (M_e r_c) . V_e at the current angles.
  double p = 0.0;
  const auto& els = fint_.corotational_elements();
  for (std::size_t k = 0; k < els.size(); ++k) {
    const int e = els[k];
    if (model_.elements()[e].body != b) continue;
    const Model::Element& el = model_.elements()[e];
    const Mat6 Me =
        to_global(frame_mass_consistent_local(el.rho, el.area, el.length), dir_[k][0], dir_[k][1]);
    Vec6 r = Vec6::Zero();
    r(c) = r(3 + c) = 1.0;
    const Vec6 mr = Me * r;
    const Eigen::Matrix<int, 6, 1> eq = model_.element_equations(e);
    for (int i = 0; i < 6; ++i)
      if (eq(i) >= 0) p += mr(i) * V(eq(i));
  }
  return p;
}

}  // namespace beamimpact::paper
