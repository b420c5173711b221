#include <solver/scene/run_cost.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include <solver/util/InputError.hpp>

namespace beamimpact {
namespace {

/// Bytes per degree of freedom of the assembled model: sparse K, M, C and their factorisations,
/// the integrator's state vectors and element frames (a few hundred doubles and indices per
/// node). An estimate for the order of magnitude, not an allocation limit.
constexpr double kBytesPerDof = 2000.0;
/// Bytes per recorded history row and contact (about 20 doubles: gap, R, tau, u, v of both
/// points, energies, momentum).
constexpr double kBytesPerRowAndContact = 200.0;
/// Bytes per node of one field file (output.fields): 16 numbers (reference point, displacement,
/// velocity, rotation, section forces, contact force, and the polyline's node index). Binary: 4
/// bytes a number in single precision, 8 in double (the index is Int32 either way). ASCII: up to
/// 16 characters a number in single precision, 25 in double. Checked against the files by
/// output_files_test (ratios within 10 %).
double field_bytes_per_node(const OutputSettings& o) {
  const bool single = o.field_precision == FieldPrecision::kSingle;
  if (o.field_format == FieldFormat::kAscii) return single ? 16.0 * 16 : 16.0 * 25;
  return single ? 16.0 * 4 : 15.0 * 8 + 4;
}
/// The XML around the numbers: 1.7 kB a file (S1's files, 22 nodes: 3117 B single, 4439 B double).
constexpr double kFieldBytesPerFile = 1700.0;

}  // namespace

std::string RunCost::to_string() const {
  return fmt::format(
      "{:.3g} steps (the fastest wave needs {:.3g}) x {:.3g} DOFs = {:.3g} DOF-steps, about {:.3g} GB "
      "of memory",
      steps, wave_steps, dofs, work, bytes / 1e9);
}

RunCost estimate_run_cost(const Scene& scene, double dt) {
  RunCost c;
  for (const Body& b : scene.bodies) c.dofs += 3.0 * (static_cast<double>(b.elements) + 1.0);
  c.steps = dt > 0.0 && std::isfinite(dt) ? std::ceil(scene.time.end / dt - 1e-9)
                                          : std::numeric_limits<double>::infinity();
  c.wave_steps = scene.time.end / (estimate_auto_dt(scene) / scene.time.fraction);
  c.work = std::max(c.steps, c.wave_steps) * c.dofs;
  const double rows = c.steps / std::max(1, scene.time.output_every);
  c.bytes = c.dofs * kBytesPerDof + rows * kBytesPerRowAndContact *
                                        static_cast<double>(std::max<std::size_t>(1, scene.contacts.size()));
  if (scene.output.fields)
    c.field_bytes = (rows + 1.0) * (c.dofs / 3.0 * field_bytes_per_node(scene.output) + kFieldBytesPerFile);
  return c;
}

double estimate_auto_dt(const Scene& scene) {
  double dt = std::numeric_limits<double>::infinity();
  for (const Body& b : scene.bodies)
    if (!b.rigid) dt = std::min(dt, b.length() / b.elements * std::sqrt(b.rho / b.E));  // rigid: no waves
  return scene.time.fraction * dt;
}

RunCost check_run_cost(const Scene& scene, double dt) {
  const RunCost c = estimate_run_cost(scene, dt);
  if (!(c.steps <= kMostSteps))
    throw InputError(scene.file, "time.dt",
                     fmt::format("expected a step that divides time.end = {:g} s into at most {:g} steps, "
                                 "got dt = {:g} s ({:.3g} steps)",
                                 scene.time.end, kMostSteps, dt, c.steps));
  if ((c.work > kOrdinaryWork || c.bytes > kOrdinaryBytes) && !scene.time.allow_long_run)
    throw InputError(
        scene.file, "time.allow_long_run",
        fmt::format("this run is far beyond an ordinary one: {} (ordinary: at most {:g} DOF-steps "
                    "and {:g} GB); set time.allow_long_run = true (or --allow-long) to run it",
                    c.to_string(), kOrdinaryWork, kOrdinaryBytes / 1e9));
  if (c.field_bytes > kOrdinaryFieldBytes && !scene.time.allow_long_run) {
    const double every = std::ceil(scene.time.output_every * c.field_bytes / kOrdinaryFieldBytes);
    throw InputError(
        scene.file, "output.fields",
        fmt::format("the field files would take about {:.3g} GB ({:.3g} files, one per output row; "
                    "ordinary: at most {:g} GB); write fewer with time.output_every = {:g} or more, "
                    "or set time.allow_long_run = true to write them all",
                    c.field_bytes / 1e9, c.steps / scene.time.output_every + 1.0, kOrdinaryFieldBytes / 1e9,
                    every));
  }
  return c;
}

double check_model_cost(const Scene& scene) {
  double dofs = 0.0;
  for (const Body& b : scene.bodies) dofs += 3.0 * (static_cast<double>(b.elements) + 1.0);
  const double bytes = dofs * kBytesPerDof;
  if (bytes > kOrdinaryBytes && !scene.time.allow_long_run)
    throw InputError(
        scene.file, "time.allow_long_run",
        fmt::format("this model is far beyond an ordinary one: {:.3g} DOFs, about {:.3g} GB of "
                    "memory (ordinary: at most {:g} GB); set time.allow_long_run = true to build it",
                    dofs, bytes / 1e9, kOrdinaryBytes / 1e9));
  return bytes;
}

long step_count(const Scene& scene, double dt) {
  const RunCost c = estimate_run_cost(scene, dt);
  if (!(c.steps <= kMostSteps)) check_run_cost(scene, dt);  // throws with the message
  return static_cast<long>(c.steps);
}

}  // namespace beamimpact
