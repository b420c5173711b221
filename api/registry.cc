#include <api/registry.hpp>

#include <solver/paper/solve.hpp>
#include <solver/scene/SceneError.hpp>
#ifdef BEAMIMPACT_HAVE_exact
#include <references/exact/solve.hpp>
#endif
#ifdef BEAMIMPACT_HAVE_ida
#include <references/ida/solve.hpp>
#endif

namespace beamimpact {

const std::vector<Method>& methods() {
  static const std::vector<Method> table = [] {
    std::vector<Method> t;
    Method paper;
    paper.name = "paper";
    paper.summary = "Pu & Chi (2011) explicit dynamic-contact integrator (solver/)";
    paper.options_table = "paper";
    paper.solve = [](const Scene& scene) { return paper::solve(scene); };
    paper.solve_with_fields = paper::solve;
    t.push_back(paper);
#ifdef BEAMIMPACT_HAVE_exact
    Method exact;
    exact.name = "exact";
    exact.summary =
        "exact and semi-analytic solutions: d'Alembert rods, rod on a simply supported beam "
        "(references/exact/)";
    exact.options_table = "exact";
    exact.accepts = {
        .dt = true, .overrides = true, .mesh_factor = false, .friction = false, .rotation = false};
    exact.solve = exact::solve;
    t.push_back(exact);
#endif
#ifdef BEAMIMPACT_HAVE_ida
    Method ida;
    ida.name = "ida";
    ida.summary = "SUNDIALS IDA with penalty contact on the same beam model (references/ida/)";
    ida.options_table = "ida";
    ida.accepts.rotation = false;
    ida.solve = ida::solve;
    t.push_back(ida);
#endif
    Method fenicsx;
    fenicsx.name = "fenicsx";
    fenicsx.summary =
        "FEniCSx 2D plane-stress continuum, dolfinx 0.5 (references/fenicsx/, external program)";
    fenicsx.options_table = "fenicsx";
    fenicsx.accepts = {
        .dt = false, .overrides = false, .mesh_factor = false, .friction = true, .rotation = true};
    fenicsx.slow = true;
    fenicsx.command = {"/usr/bin/python3", "references/fenicsx/run.py"};
    fenicsx.check = {"/usr/bin/python3", "-c", "import dolfinx"};
    fenicsx.mesh_option = "--mesh";
    fenicsx.output_step_option = "--output-interval";
    t.push_back(fenicsx);
    return t;
  }();
  return table;
}

const Method* find_method(std::string_view name) {
  for (const Method& m : methods())
    if (m.name == name) return &m;
  return nullptr;
}

std::string method_names() {
  std::string names;
  for (const Method& m : methods()) names += (names.empty() ? "" : ", ") + m.name;
  return names;
}

const Method& method(std::string_view name, const std::string& file, const std::string& key) {
  if (const Method* m = find_method(name)) return *m;
  throw SceneError(file, key,
                   "expected a method name (" + method_names() + "), got '" + std::string(name) + "'");
}

}  // namespace beamimpact
