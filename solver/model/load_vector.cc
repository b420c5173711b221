#include <solver/model/load_vector.hpp>

#include <cmath>

#include <fmt/format.h>

#include <solver/util/InputError.hpp>

namespace beamimpact {
namespace {

/// Refuses a load across the axis of a rod model: |a x axis| above 1e-12 |a|.
void check_along_axis(const Model& model, const Scene& scene, const Vec2& a, const std::string& key) {
  if (model.dofs_per_node() != 1) return;
  const Vec2& e = model.rod_axis();
  const double across = std::abs(a[0] * e[1] - a[1] * e[0]), size = std::hypot(a[0], a[1]);
  if (across > 1e-12 * size)
    throw InputError(scene.file, key,
                     fmt::format("this scene is modelled as axial rods along ({:.6g}, {:.6g}) (collinear, no "
                                 "bending), and the load ({:.6g}, {:.6g}) has a component across that axis; "
                                 "expected a load along the axis, or set effects.bending = true",
                                 e[0], e[1], a[0], a[1]));
}

}  // namespace

Eigen::VectorXd load_vector(const Model& model, const Scene& scene) {
  if (!scene.loads.any()) return {};
  const Vec2& g = scene.loads.gravity;
  check_along_axis(model, scene, g, "loads.gravity");
  Eigen::VectorXd F = Eigen::VectorXd::Zero(model.size());
  if (g[0] != 0.0 || g[1] != 0.0) {
    const Eigen::VectorXd T = model.translation(std::vector<Vec2>(scene.bodies.size(), g));
    if (model.lumped())
      F = model.lumped_mass().cwiseProduct(T);
    else
      F = model.M() * T;
  }
  std::vector<DofTerm> terms;
  for (std::size_t i = 0; i < scene.loads.point.size(); ++i) {
    const PointLoad& p = scene.loads.point[i];
    check_along_axis(model, scene, p.force, fmt::format("loads.point[{}].force", i));
    // Virtual work F . du(node) = sum coeff dU[eq] over the node's projection along F.
    terms.clear();
    model.append_projection(model.node_id(p.body, p.node), p.force, 1.0, terms);
    for (const DofTerm& t : terms) F(t.eq) += t.coeff;
  }
  return F;
}

Vec2 net_load_force(const Model& model, const Eigen::VectorXd& load) {
  Vec2 F{0.0, 0.0};
  if (load.size() == 0) return F;
  for (int c = 0; c < 2; ++c) {
    const std::vector<Vec2> along(model.num_bodies(), Vec2{c == 0 ? 1.0 : 0.0, c == 1 ? 1.0 : 0.0});
    F[c] = load.dot(model.translation(along));
  }
  return F;
}

}  // namespace beamimpact
