#pragma once
/// @file FieldWriter.hpp
/// @brief Field output for ParaView ([output] fields = true): one VTK XML UnstructuredGrid
/// (.vtu) per output row and a .pvd collection with the times, streamed step by step (each row's
/// file written on the writer's own thread while the run goes on; nothing of earlier rows is kept
/// in memory).
///
/// Layout in the run directory: fields.pvd and fields/step_NNNNNN.vtu. Points are the nodes in
/// their reference position (ParaView's "Warp By Vector" with `displacement` shows the deformed
/// beams); one polyline cell per body. Point data per node: displacement, velocity (3
/// components, z = 0), rotation (rad), axial_force (N, tension > 0), bending_moment (N m,
/// M = EI kappa in the element's left-normal convention, averaged over the elements meeting at a
/// node) and contact_force (N: the contact forces on the nodes, the striker's and the reaction
/// shared over the target's nodes as the pair's rows apply it). Cell data: body (index into the
/// scene).
/// Numbers are stored as output.field_format says: VTK's appended raw binary (the default: each
/// array a block of little-endian values behind a UInt64 byte count, after the XML header) or
/// ASCII in shortest round-trip form; real numbers in output.field_precision (Float32, the
/// default, each the double rounded to nearest; or Float64), node indices as Int32. Both
/// encodings read back bit for bit; ParaView reads all four combinations.

#include <array>
#include <condition_variable>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include <Eigen/Core>

#include <solver/model/Model.hpp>
#include <solver/scene/Scene.hpp>
#include <solver/util/ThreadTeam.hpp>

namespace beamimpact {

/// @brief Writes one run's fields (see the file comment).
class FieldWriter {
 public:
  /// @brief Removes any fields of an earlier run in `dir` (the folder of its files is moved aside
  /// at once and deleted on the writer's thread) and starts the collection.
  /// @param model the beam model (nodes, elements, equations)
  /// @param dir the run directory (fields.pvd and fields/ go there)
  /// @param format how the numbers are stored (binary or ASCII)
  /// @param precision the real numbers' precision (single or double)
  FieldWriter(const Model& model, std::filesystem::path dir, FieldFormat format = FieldFormat::kBinary,
              FieldPrecision precision = FieldPrecision::kSingle);
  FieldWriter(const FieldWriter&) = delete;
  FieldWriter& operator=(const FieldWriter&) = delete;
  /// @brief An unfinished collection (the run failed) is removed: no .pvd vouches for it.
  ~FieldWriter();

  /// @brief Makes the .vtu of one output row and lists it in the collection. The file is written
  /// by the writer's own thread while the run goes on (write() and finish() first wait for the
  /// last one, and throw if it could not be written).
  /// @param t time (s)
  /// @param U displacements, the model's equation vector
  /// @param V velocities, the model's equation vector
  /// @param contact_force per node, the contact forces on it (N, global x and y)
  /// @param end_forces per element: axial force N (N, tension > 0) and the end moments M1, M2
  ///        (N m) the element exerts on its nodes' rotations (InternalForce::end_forces)
  /// @param team threads for the values (the nodes split in one range per thread; the file is the
  ///        same whatever their number), or null for this thread alone. Idle until called.
  void write(double t, const Eigen::VectorXd& U, const Eigen::VectorXd& V,
             const std::vector<Vec2>& contact_force, const std::vector<std::array<double, 3>>& end_forces,
             ThreadTeam* team = nullptr);

  /// @brief Waits for the last file and closes the collection: fields.pvd appears (atomically)
  /// only now.
  void finish();

  /// @brief The .pvd of the run directory `dir`.
  static std::filesystem::path collection(const std::filesystem::path& dir) { return dir / "fields.pvd"; }

 private:
  /// The number of point data arrays in a row (point_arrays).
  static constexpr int kPointArrays = 6;

  /// The axial force (moment = false) or bending moment at node i: the end forces of the elastic
  /// elements meeting there, averaged (0 where none meets).
  double section_force(int i, const std::vector<std::array<double, 3>>& end_forces, bool moment) const;

  /// Calls f(name, components, tuple) for each of the kPointArrays point data arrays of a row, in
  /// the file's order: components a std::integral_constant (1 or 3), tuple(i, v) writing node i's
  /// components into v.
  template <typename F>
  void point_arrays(const Eigen::VectorXd& U, const Eigen::VectorXd& V,
                    const std::vector<Vec2>& contact_force,
                    const std::vector<std::array<double, 3>>& end_forces, const F& f) const;

  /// Where an earlier run's fields/ goes to be removed by the writer thread.
  std::filesystem::path stale() const { return dir_ / ".fields.removing"; }
  /// Waits until no file is being written; throws the first write error.
  void wait_idle();
  /// The writer thread: writes file_ from xml_, geometry_raw_ and raw_ whenever it is set, until stop_.
  void write_files();
  /// Writes the row in the buffers to `path`; false when that failed.
  bool write_file(const std::filesystem::path& path) const;

  /// Appends the point data of one row, as T, to xml_ and raw_.
  template <typename T>
  void write_point_data(const Eigen::VectorXd& U, const Eigen::VectorXd& V,
                        const std::vector<Vec2>& contact_force,
                        const std::vector<std::array<double, 3>>& end_forces, ThreadTeam* team);

  const Model& model_;
  std::filesystem::path dir_;
  FieldFormat format_;
  FieldPrecision precision_;
  std::ofstream pvd_;  ///< fields.pvd.part while the run goes on
  long count_ = 0;
  /// The elastic elements meeting at each node, in element order: node i's are
  /// touch_[touch_start_[i] .. touch_start_[i + 1]), each 2 e + (0 at its first node, 1 at its second).
  std::vector<int> touch_start_, touch_;
  /// Each node's x, y, theta equations (-1: fixed or absent) when its displacement is read off
  /// them directly (a frame node of an elastic body in global axes), else x = -2 (node_vector()).
  std::vector<std::array<int, 3>> eq_;
  std::string geometry_;      ///< each .vtu's points, cells and cell data (the same every step)
  std::string geometry_raw_;  ///< binary: their appended blocks (the same every step)
  std::string xml_, raw_;     ///< the step being written: its XML and (binary) appended blocks
  std::size_t raw_used_ = 0;  ///< bytes of raw_ that are the step's (raw_ keeps its size)
  // The writer thread and what it shares with write(): the buffers above are the writer's while
  // file_ is set.
  std::mutex mutex_;
  std::condition_variable changed_;  ///< file_ or stop_ changed
  std::filesystem::path file_;       ///< the file to write from the buffers; empty when idle
  std::string error_;                ///< the first file that could not be written
  bool stop_ = false;
  std::thread writer_;
};

}  // namespace beamimpact
