#pragma once
/// @file FieldWriter.hpp
/// @brief Field output for ParaView ([output] fields = true): one VTK XML UnstructuredGrid
/// (.vtu) per output row and a .pvd collection with the times, streamed step by step (a file
/// per row is written and closed at once; nothing of earlier rows is kept in memory).
///
/// Layout in the run directory: fields.pvd and fields/step_NNNNNN.vtu. Points are the nodes in
/// their reference position (ParaView's "Warp By Vector" with `displacement` shows the deformed
/// beams); one polyline cell per body. Point data per node: displacement, velocity (3
/// components, z = 0), rotation (rad), axial_force (N, tension > 0), bending_moment (N m,
/// M = EI kappa in the element's left-normal convention, averaged over the elements meeting at a
/// node) and contact_force (N: the force on each striker node, and its reaction shared over the
/// target's nodes as the contact's struck point is). Cell data: body (index into the scene).
/// Numbers are written in shortest round-trip form, so they read back bit for bit.

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <Eigen/Core>

#include <beamimpact/model/Model.hpp>

namespace beamimpact {

/// @brief A force (N, global axes) acting on one global node.
struct NodalForce {
  int node = 0;
  Vec2 force{};
};

/// @brief Writes one run's fields (see the file comment).
class FieldWriter {
 public:
  /// @brief Removes any fields of an earlier run in `dir` and starts the collection.
  /// @param model the beam model (nodes, elements, equations)
  /// @param scene the scene (body names, kinematics)
  /// @param dir the run directory (fields.pvd and fields/ go there)
  FieldWriter(const Model& model, const Scene& scene, std::filesystem::path dir);
  FieldWriter(const FieldWriter&) = delete;
  FieldWriter& operator=(const FieldWriter&) = delete;
  /// @brief An unfinished collection (the run failed) is removed: no .pvd vouches for it.
  ~FieldWriter();

  /// @brief Writes the .vtu of one output row and lists it in the collection.
  /// @param t time (s)
  /// @param U displacements, the model's equation vector
  /// @param V velocities, the model's equation vector
  /// @param contact_forces forces on nodes from the contacts (summed per node)
  void write(double t, const Eigen::VectorXd& U, const Eigen::VectorXd& V,
             const std::vector<NodalForce>& contact_forces);

  /// @brief Closes the collection: fields.pvd appears (atomically) only now.
  void finish();

  /// @brief The .pvd of the run directory `dir`.
  static std::filesystem::path collection(const std::filesystem::path& dir) { return dir / "fields.pvd"; }

 private:
  /// Axial force and bending moment at each node from U (element end forces, averaged).
  void section_forces(const Eigen::VectorXd& U);

  const Model& model_;
  bool corotational_;
  std::filesystem::path dir_;
  std::ofstream pvd_;  ///< fields.pvd.part while the run goes on
  long count_ = 0;
  std::vector<double> axial_, moment_;
  std::vector<int> touching_;  ///< elements meeting at each node
  std::vector<Vec2> contact_;
};

}  // namespace beamimpact
