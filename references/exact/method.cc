#include <references/exact/method.hpp>

#include <references/exact/solve.hpp>

namespace beamimpact::exact {

Method method() {
  Method m;
  m.name = "exact";
  m.summary =
      "exact and semi-analytic solutions: d'Alembert rods, rod or Hertz ball on a simply supported beam, "
      "rigid rod (references/exact/)";
  m.options_table = "exact";
  m.accepts.mesh_factor = false;  // an exact solution has no mesh
  // Friction only in the rigid-rod closed form (recognise_rigid_rod); every other solution is
  // frictionless (check_one_frictionless_undamped_contact, recognise_scene.cc).
  m.accepts.friction = false;
  m.accepts.rigid_friction = true;
  m.accepts.rotation = false;
  m.accepts.search = false;
  m.accepts.several_contacts = false;
  m.accepts.timoshenko = true;  // a rod on a Timoshenko beam only (its recogniser refuses the rest)
  m.accepts.hertz = true;       // a rigid striker on a beam only (its recogniser refuses the rest)
  m.as_reference.rank = ReferenceRank::kExact;
  m.solve = [](const Scene& scene, const Method::Request&) { return solve(scene); };
  return m;
}

}  // namespace beamimpact::exact
