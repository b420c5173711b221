#include <references/ida/ContactKinematics.hpp>

#include <algorithm>
#include <cmath>

#include <solver/util/InputError.hpp>

namespace beamimpact::ida {
namespace {

double dot(const Vec2& a, const Vec2& b) { return a[0] * b[0] + a[1] * b[1]; }

double apply(const std::vector<DofTerm>& terms, const Eigen::VectorXd& x) {
  double s = 0.0;
  for (const DofTerm& d : terms) s += d.coeff * x(d.eq);
  return s;
}

void append_scaled(std::vector<DofTerm>& out, const std::vector<DofTerm>& in, double scale) {
  for (const DofTerm& d : in) out.push_back({d.eq, scale * d.coeff});
}

}  // namespace

double ContactFrame::gap(const Eigen::VectorXd& U) const {
  return beyond > 0.0 ? beyond : g0 + apply(n_terms, U);
}
double ContactFrame::normal_rate(const Eigen::VectorXd& V) const {
  return apply(n_terms, V) - rate_coupling * apply(t_terms, V);
}
double ContactFrame::force_rate(const Eigen::VectorXd& V) const { return apply(n_terms, V); }
double ContactFrame::tangential_rate(const Eigen::VectorXd& V) const { return apply(t_terms, V); }

ModelContact::ModelContact(const Model& model, const Scene& scene, int contact_index) : model_(model) {
  const Contact& c = scene.contacts[contact_index];
  const Body& striker = scene.bodies[c.striker];
  const Body& target = scene.bodies[c.target];
  const std::string key = "contacts[" + std::to_string(contact_index) + "]";
  striker_node_ = model.node_id(c.striker, c.node);
  target_first_node_ = model.node_id(c.target, 0);
  target_elements_ = target.elements;
  const double L = target.length();
  le_ = L / target.elements;
  k_elem_ = std::max(striker.E * striker.area / (striker.length() / striker.elements),
                     target.E * target.area / le_);

  const Vec2 d{(target.end[0] - target.start[0]) / L, (target.end[1] - target.start[1]) / L};
  const Vec2 n0{-d[1], d[0]};
  const Vec2 xa = model.node_position(striker_node_);
  const Vec2 rel{xa[0] - target.start[0], xa[1] - target.start[1]};
  const double s = dot(d, rel), h = dot(n0, rel);
  const double tol = 1e-9 * L;
  if (std::abs(h) <= tol && (s < -tol || s > L + tol)) {
    kind_ = ContactKind::kEndToEnd;
    const bool at_start = s < 0.0;
    n_ = at_start ? Vec2{-d[0], -d[1]} : d;
    end_node_ = at_start ? target_first_node_ : target_first_node_ + target.elements;
    const Vec2& xe = model.node_position(end_node_);
    g0_ = dot(n_, {xa[0] - xe[0], xa[1] - xe[1]});
    t_ = {-n_[1], n_[0]};
    end_n_ = model.project(end_node_, n_);
    end_t_ = model.project(end_node_, t_);
  } else {
    if (std::abs(h) <= tol)
      throw InputError(scene.file, key, "the striker node lies on the target's axis inside it");
    if (s < -tol || s > L + tol)
      throw InputError(scene.file, key,
                       "the striker node does not lie over the target (its foot on the target's "
                       "line is outside the target)");
    n_ = h > 0.0 ? n0 : Vec2{-n0[0], -n0[1]};
    t_ = d;
    g0_ = std::abs(h);
    s_ref_ = std::clamp(s, 0.0, L);
    const double r = s_ref_ / le_;
    kind_ = std::abs(r - std::round(r)) < 1e-9 ? ContactKind::kNodeToNode : ContactKind::kNodeToSurface;
  }
  striker_n_ = model.project(striker_node_, n_);
  striker_t_ = model.project(striker_node_, t_);
}

double ModelContact::coordinate(const Eigen::VectorXd& U, double* beyond) const {
  // The struck material point is where the target's displaced line passes under the striker:
  // s + t.u_b(s) = s_ref + t.u_a. Two fixed-point sweeps are exact to O(strain^2).
  const double L = le_ * target_elements_;
  const Vec2 ua = model_.node_vector(U, striker_node_);
  const double sa = s_ref_ + dot(t_, ua);
  double s = sa;
  for (int it = 0; it < 2; ++it) {
    const double r = std::clamp(s, 0.0, L) / le_;
    const int j = std::clamp(static_cast<int>(std::floor(r)), 0, target_elements_ - 1);
    const double xi2 = r - j;
    const Vec2 u1 = model_.node_vector(U, target_first_node_ + j);
    const Vec2 u2 = model_.node_vector(U, target_first_node_ + j + 1);
    const Vec2 ub{(1 - xi2) * u1[0] + xi2 * u2[0], (1 - xi2) * u1[1] + xi2 * u2[1]};
    s = sa - dot(t_, ub);
  }
  if (beyond) *beyond = s < 0.0 ? -s : (s > L ? s - L : 0.0);
  return std::clamp(s, 0.0, L);
}

ContactFrame ModelContact::evaluate(const Eigen::VectorXd& U) const {
  ContactFrame f;
  f.g0 = g0_;
  f.n_terms = striker_n_;
  f.t_terms = striker_t_;
  if (kind_ == ContactKind::kEndToEnd) {
    append_scaled(f.n_terms, end_n_, -1.0);
    append_scaled(f.t_terms, end_t_, -1.0);
    f.segment = end_node_ == target_first_node_ ? 0 : target_elements_ - 1;
    f.xi2 = end_node_ == target_first_node_ ? 0.0 : 1.0;
    return f;
  }
  const double r = coordinate(U, &f.beyond) / le_;
  f.segment = std::clamp(static_cast<int>(std::floor(r)), 0, target_elements_ - 1);
  f.xi2 = r - f.segment;
  const int n1 = target_first_node_ + f.segment, n2 = n1 + 1;
  // Both nodes always appear (possibly with weight 0) so the Jacobian's pattern only changes
  // when the struck point crosses into another element.
  append_scaled(f.n_terms, model_.project(n1, n_), -(1.0 - f.xi2));
  append_scaled(f.n_terms, model_.project(n2, n_), -f.xi2);
  append_scaled(f.t_terms, model_.project(n1, t_), -(1.0 - f.xi2));
  append_scaled(f.t_terms, model_.project(n2, t_), -f.xi2);
  if (f.beyond == 0.0) {
    const Vec2 u1 = model_.node_vector(U, n1), u2 = model_.node_vector(U, n2);
    const Vec2 slope{(u2[0] - u1[0]) / le_, (u2[1] - u1[1]) / le_};
    f.rate_coupling = dot(n_, slope) / (1.0 + dot(t_, slope));
  }
  return f;
}

std::array<int, 2> ModelContact::segment_nodes(const ContactFrame& f) const {
  if (kind_ == ContactKind::kEndToEnd) return {end_node_, end_node_};
  return {target_first_node_ + f.segment, target_first_node_ + f.segment + 1};
}

}  // namespace beamimpact::ida
