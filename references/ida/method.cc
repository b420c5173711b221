#include <references/ida/method.hpp>

#include <references/ida/solve.hpp>

namespace beamimpact::ida {

Method method() {
  Method m;
  m.name = "ida";
  m.summary = "SUNDIALS IDA with penalty contact on the same beam model (references/ida/)";
  m.options_table = "ida";
  // No contact search; a corotational scene runs IDA's own corotational elements (lumped mass;
  // with consistent mass in global axes, said in `assumed` and settings.model.kinematics).
  m.accepts.search = false;
  // As a reference, converged beyond its defaults: time tolerances 100 times tighter (rtol
  // 1e-10, atol 1e-13), the friction regularisation at 1e-5 m/s (the matrix's converged value; no
  // effect on a frictionless contact) and a penalty 10 times stiffer (1e4 EA/le), so that its
  // step and penetration errors fall below the defaults' by about those factors. The same run at
  // the card's penalty is the reference's own uncertainty check.
  m.as_reference.rank = ReferenceRank::kConverged;
  m.as_reference.converged = {"ida.rtol=1e-10", "ida.atol=1e-13", "ida.friction_velocity=1e-5"};
  m.as_reference.stiffer = {"ida.kn_factor=1e4"};
  m.as_reference.stiffness_keys = {"ida.kn", "ida.kn_factor"};
  m.as_reference.converged_words =
      "IDA converged beyond its defaults: rtol 1e-10, atol 1e-13, friction regularised at 1e-5 m/s, penalty "
      "1e4 EA/le, with the card's own settings; its spread against the same run at the card's penalty is "
      "its uncertainty";
  m.solve = [](const Scene& scene, const Method::Request&) { return solve(scene); };
  return m;
}

}  // namespace beamimpact::ida
