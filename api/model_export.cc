#include <api/model_export.hpp>

#include <array>
#include <string>
#include <vector>

#include <fmt/format.h>

#include <solver/contact/ContactPair.hpp>
#include <solver/model/Effects.hpp>
#include <solver/model/critical_dt.hpp>
#include <solver/model/load_vector.hpp>
#include <solver/util/InputError.hpp>
#include <solver/util/OutputLock.hpp>
#include <solver/util/write_file_atomic.hpp>

namespace beamimpact {
namespace {

using nlohmann::json;

/// A sparse matrix as Matrix Market text (coordinate, real, general; 1-based indices).
std::string matrix_market(const SparseMatrix& A, const std::string& comment) {
  std::string s = "%%MatrixMarket matrix coordinate real general\n% " + comment + "\n";
  s += fmt::format("{} {} {}\n", A.rows(), A.cols(), A.nonZeros());
  for (int j = 0; j < A.outerSize(); ++j)
    for (SparseMatrix::InnerIterator it(A, j); it; ++it)
      s += fmt::format("{} {} {:.17g}\n", it.row() + 1, it.col() + 1, it.value());
  return s;
}

/// The equations of rigid body b's centre (x, y, theta; rod layout: the axial one first), -1
/// when fixed: read from the projection of its first node, u_x = u_c,x - theta (Y - Y_c).
std::array<int, 3> rigid_equations(const Model& model, int b) {
  const int n = model.node_id(b, 0);
  const int theta = model.equation(n, 2);
  std::array<int, 3> eq{-1, -1, theta};
  const Vec2 axis = model.dofs_per_node() == 1 ? model.rod_axis() : Vec2{1.0, 0.0};
  for (int c = 0; c < (model.dofs_per_node() == 1 ? 1 : 2); ++c) {
    const Vec2 d = c == 0 ? axis : Vec2{0.0, 1.0};
    for (const DofTerm& t : model.project(n, d))
      if (t.eq != theta) eq[c] = t.eq;
  }
  return eq;
}

/// The centre of body b (m): the midpoint of its start and end.
Vec2 centre(const Body& body) {
  return {0.5 * (body.start[0] + body.end[0]), 0.5 * (body.start[1] + body.end[1])};
}

/// One row per node (rigid bodies: one row for the centre, node -1): which equation holds each
/// of its components, -1 when fixed or absent.
std::string dofs_csv(const Scene& scene, const Model& model) {
  std::string s = "body,node,x,y,eq_x,eq_y,eq_theta,axis_x,axis_y\n";
  const Vec2 global_x = model.dofs_per_node() == 1 ? model.rod_axis() : Vec2{1.0, 0.0};
  for (int b = 0; b < model.num_bodies(); ++b) {
    if (model.rigid(b)) {
      const std::array<int, 3> r = rigid_equations(model, b);
      const Vec2 c = centre(scene.bodies[b]);
      s += fmt::format("{},-1,{:.17g},{:.17g},{},{},{},{:.17g},{:.17g}\n", b, c[0], c[1], r[0], r[1], r[2],
                       global_x[0], global_x[1]);
      continue;
    }
    const int first = model.node_id(b, 0);
    for (int i = 0; i < scene.bodies[b].nodes(); ++i) {
      const int n = first + i;
      const Vec2& x = model.node_position(n);
      const Vec2 a = model.dofs_per_node() == 1 ? global_x : model.node_axis(n);
      s += fmt::format("{},{},{:.17g},{:.17g},{},{},{},{:.17g},{:.17g}\n", b, i, x[0], x[1],
                       model.equation(n, 0), model.equation(n, 1), model.equation(n, 2), a[0], a[1]);
    }
  }
  return s;
}

/// Columns of vectors over the equations: "equation,<name>,...".
std::string vectors_csv(const std::vector<std::string>& names, const std::vector<Eigen::VectorXd>& cols,
                        int n) {
  std::string s = "equation";
  for (const std::string& name : names) s += "," + name;
  s += "\n";
  for (int i = 0; i < n; ++i) {
    s += std::to_string(i);
    for (const Eigen::VectorXd& c : cols) s += fmt::format(",{:.17g}", c(i));
    s += "\n";
  }
  return s;
}

std::string momentum_csv(const Model& model) {
  std::vector<std::string> names;
  std::vector<Eigen::VectorXd> cols;
  for (int b = 0; b < model.num_bodies(); ++b)
    for (int c = 0; c < 2; ++c) {
      names.push_back(fmt::format("p{}_{}", b, c == 0 ? "x" : "y"));
      cols.push_back(model.momentum_covector(b, c));
    }
  return vectors_csv(names, cols, model.size());
}

json row_json(const std::vector<DofTerm>& terms) {
  json r = json::array();
  for (const DofTerm& d : terms) r.push_back({d.eq, d.coeff});
  return r;
}

/// The linear surface interpolation of the struck point's displacement along d.
std::vector<DofTerm> target_row(const Model& model, const paper::ContactPair& pair, const Vec2& d) {
  std::vector<DofTerm> row;
  const int n1 = model.node_id(pair.target_body(), 0) + pair.element();
  if (pair.xi1() != 0.0) model.append_projection(n1, d, pair.xi1(), row);
  if (pair.xi2() != 0.0) model.append_projection(n1 + 1, d, pair.xi2(), row);
  return row;
}

json contact_json(const Scene& scene, const Model& model, int k) {
  const paper::ContactPair pair(model, scene, k, paper::SurfaceInterpolation::kLinear);
  const Contact& c = scene.contacts[k];
  const int striker_first = model.node_id(c.striker, 0);
  return {{"striker", scene.bodies[c.striker].name},
          {"target", scene.bodies[c.target].name},
          {"striker_node", c.node},
          {"striker_node_global", striker_first + c.node},
          {"kind", to_string(pair.kind())},
          {"friction", c.friction},
          {"g0", pair.g0()},
          {"normal", pair.normal()},
          {"tangent", pair.tangent()},
          {"target_element", pair.element()},
          {"xi1", pair.xi1()},
          {"xi2", pair.xi2()},
          {"can_slide", pair.can_slide()},
          {"rows",
           {{"normal", row_json(pair.normal_row())},
            {"tangent", row_json(pair.tangent_row())},
            {"striker_x", row_json(model.project(pair.striker_node(), {1.0, 0.0}))},
            {"striker_y", row_json(model.project(pair.striker_node(), {0.0, 1.0}))},
            {"target_x", row_json(target_row(model, pair, {1.0, 0.0}))},
            {"target_y", row_json(target_row(model, pair, {0.0, 1.0}))}}}};
}

json bodies_json(const Scene& scene, const Model& model) {
  json out = json::array();
  for (int b = 0; b < model.num_bodies(); ++b) {
    const Body& body = scene.bodies[b];
    out.push_back({{"name", body.name},
                   {"index", b},
                   {"rigid", model.rigid(b)},
                   {"elements", body.elements},
                   {"nodes", body.nodes()},
                   {"first_node_global", model.node_id(b, 0)},
                   {"start", body.start},
                   {"end", body.end},
                   {"centre", centre(body)},
                   {"length", body.length()},
                   {"mass", model.body_mass(b)},
                   {"E", body.E},
                   {"rho", body.rho},
                   {"area", body.area},
                   {"inertia", body.inertia},
                   {"velocity", body.velocity},
                   {"theory", to_string(body.theory)}});
    if (body.theory == BeamTheory::kTimoshenko) {  // M and K are the Timoshenko element's
      out.back()["shear_coefficient"] = body.shear_coefficient;
      out.back()["poisson"] = body.poisson;
    }
  }
  return out;
}

/// The step the paper integrator would take (the scene's, or its fraction of the critical step)
/// and the critical step of explicit central differences on this model.
json time_json(const Scene& scene, const Model& model) {
  const CriticalStep cs = critical_step(model);
  const bool stiff = cs.bound != CriticalBound::kNone;
  const double dt = scene.time.dt ? *scene.time.dt : scene.time.fraction * cs.dt;
  if (!scene.time.dt && !stiff)
    throw InputError(scene.file, "time.dt",
                     "\"auto\" takes a fraction of the critical step, and a scene of rigid bodies has "
                     "none (no stiffness); expected a step in seconds");
  return {{"dt", dt},
          {"dt_source", scene.time.dt ? "scene" : "auto"},
          {"fraction", scene.time.fraction},
          {"end", scene.time.end},
          {"output_every", scene.time.output_every},
          {"critical_dt", stiff ? json(cs.dt) : json(nullptr)},
          {"critical_dt_bound", to_string(cs.bound)}};
}

json files_json(const Model& model) {
  const bool rod = model.dofs_per_node() == 1;
  const std::string mass_units = rod ? "kg" : "kg on translations, kg m^2 on rotations, kg m coupling";
  const std::string stiff_units = rod ? "N/m" : "N/m on translations, N m/rad on rotations, N/rad coupling";
  const std::string mm = "Matrix Market coordinate real general, 1-based, equations x equations";
  return {{"M", {{"path", "M.mtx"}, {"format", mm}, {"units", mass_units}, {"what", "mass matrix"}}},
          {"K", {{"path", "K.mtx"}, {"format", mm}, {"units", stiff_units}, {"what", "stiffness matrix"}}},
          {"C",
           {{"path", "C.mtx"},
            {"format", mm},
            {"units", "N s/m on translations (N m s on rotations)"},
            {"what", "Rayleigh damping rayleigh_mass M + rayleigh_stiffness K (no entries when undamped)"}}},
          {"dofs",
           {{"path", "dofs.csv"},
            {"format", "CSV: body,node,x,y,eq_x,eq_y,eq_theta,axis_x,axis_y"},
            {"units",
             "x, y in m (reference position); eq_* 0-based equation, -1 fixed or absent; axis_* a unit "
             "vector (global axes)"},
            {"what",
             "one row per node; eq_x is the displacement along (axis_x, axis_y) and eq_y along that turned "
             "+90 deg: (1, 0), global x and y, except at a node whose supports hold one direction of its "
             "inclined body's own axes (fix = [\"normal\"] or [\"axial\"]), whose axis is its body's "
             "axial direction; a rigid body has one row for its centre (node -1) and its nodes move as "
             "u = u_c + theta (-(Y - Y_c), X - X_c); rod layout: eq_x is the equation of the "
             "displacement along rod_axis (= axis)"}}},
          {"initial_state",
           {{"path", "initial_state.csv"},
            {"format", "CSV: equation,u0,v0"},
            {"units", "m or rad; m/s or rad/s"},
            {"what", "displacement and velocity at t = 0"}}},
          {"load",
           {{"path", "load.csv"},
            {"format", "CSV: equation,F"},
            {"units", "N on translations, N m on rotations"},
            {"what", "constant external load vector F (zero when the scene has no loads)"}}},
          {"momentum",
           {{"path", "momentum.csv"},
            {"format", "CSV: equation,p<b>_x,p<b>_y for each body b (index into bodies)"},
            {"units", "kg (kg m on rotations)"},
            {"what",
             "momentum covectors: body b's linear momentum along x is sum(p<b>_x * v); its "
             "centre-of-mass velocity is that over bodies[b].mass"}}}};
}

/// What the export's format cannot hold (its own limits, not a method's capabilities): its
/// contact rows are of one declared striker node and of the hard law (gap >= 0, no spring).
void refuse_unexportable_contacts(const Scene& scene) {
  for (std::size_t i = 0; i < scene.contacts.size(); ++i) {
    const Contact& c = scene.contacts[i];
    const std::string key = fmt::format("contacts[{}]", i);
    if (c.search)
      throw InputError(scene.file, key + ".node",
                       "node = \"all\" (contact search) cannot be exported: the model's contact rows are of "
                       "one declared node; expected \"start\", \"end\" or a node index");
    if (c.law == ContactLaw::kHertz)
      throw InputError(
          scene.file, key + ".law",
          "\"hertz\" cannot be exported: the model's contact rows are the hard law's (gap >= 0, no "
          "spring); expected \"hard\" (or no law)");
  }
}

}  // namespace

nlohmann::json export_model(const Scene& scene_in, const std::filesystem::path& dir) {
  const OutputLock lock(dir);                   // the only writer of dir until the export returns
  std::filesystem::remove(dir / "model.json");  // nothing of an earlier export vouches for this one
  refuse_unexportable_contacts(scene_in);
  const Effects effects = derive_effects(scene_in);
  if (effects.corotational)
    throw InputError(scene_in.file, "model.kinematics",
                     "expected \"linear\" for the model export: a corotational model's matrices change "
                     "every step and cannot be written once");
  const Scene scene = effective_scene(scene_in, effects);
  const Model model(scene, effects.bending);
  json doc = {
      {"format", "beamimpact-model"},
      {"format_version", kModelFormatVersion},
      {"scene", scene.name},
      {"description", scene.description},
      {"scene_file", scene.file},
      {"scene_sha256", scene.sha256},
      {"overrides", scene.overrides},
      {"assumed", scene.assumed},
      {"units", "SI: m, s, kg, N, rad"},
      {"equation",
       "M a + C v + K u = F + sum_k (R_k G_k + tau_k T_k); gap_k = g0_k + G_k . u; G_k, T_k: "
       "contacts[k].rows.normal, .tangent as [equation, coefficient] pairs"},
      {"layout", model.dofs_per_node() == 3 ? "frame" : "rod"},
      {"dofs_per_node", model.dofs_per_node()},
      {"rod_axis", model.dofs_per_node() == 1 ? json(model.rod_axis()) : json(nullptr)},
      {"equations", model.size()},
      {"effects", effects.names()},
      {"mass", to_string(scene.model.mass)},
      {"rotary_inertia", to_string(scene.model.rotary_inertia)},
      {"kinematics", "linear"},
      {"surface_interpolation", "linear (the paper's Eq. 14-20)"},
      {"damping",
       {{"rayleigh_mass", model.rayleigh_mass()}, {"rayleigh_stiffness", model.rayleigh_stiffness()}}},
      {"time", time_json(scene, model)},
      {"bodies", bodies_json(scene, model)},
      {"contacts", json::array()},
      {"files", files_json(model)}};
  for (int k = 0; k < static_cast<int>(scene.contacts.size()); ++k) {
    doc["contacts"].push_back(contact_json(scene, model, k));
    // The scene's coefficient, also where the model does not simulate it (an end-to-end contact
    // has no tangent): a solver without friction refuses what the registry refuses.
    doc["contacts"].back()["friction"] = scene_in.contacts[k].friction;
  }

  std::filesystem::create_directories(dir);
  const SparseMatrix C = model.rayleigh_mass() * model.M() + model.rayleigh_stiffness() * model.K();
  write_file_atomic(dir / "M.mtx", matrix_market(model.M(), "mass (" + scene.name + ")"));
  write_file_atomic(dir / "K.mtx", matrix_market(model.K(), "stiffness (" + scene.name + ")"));
  write_file_atomic(dir / "C.mtx", matrix_market(C.pruned(), "Rayleigh damping (" + scene.name + ")"));
  write_file_atomic(dir / "dofs.csv", dofs_csv(scene, model));
  const Eigen::VectorXd u0 = Eigen::VectorXd::Zero(model.size());
  write_file_atomic(dir / "initial_state.csv",
                    vectors_csv({"u0", "v0"}, {u0, model.initial_velocity()}, model.size()));
  Eigen::VectorXd F = load_vector(model, scene);  // size 0 for a scene without loads
  if (F.size() == 0) F = Eigen::VectorXd::Zero(model.size());
  write_file_atomic(dir / "load.csv", vectors_csv({"F"}, {F}, model.size()));
  write_file_atomic(dir / "momentum.csv", momentum_csv(model));
  write_file_atomic(dir / "model.json", doc.dump(2) + "\n");
  return doc;
}

}  // namespace beamimpact
