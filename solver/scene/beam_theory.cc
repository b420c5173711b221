#include <solver/scene/beam_theory.hpp>

#include <fmt/format.h>

namespace beamimpact {

void read_beam_theory(TableReader& r, Body& b) {
  const bool given = r.has("theory");
  const std::string theory =
      given ? r.choice_or("theory", "euler-bernoulli", {"euler-bernoulli", "timoshenko"}) : "euler-bernoulli";
  b.theory = theory == "timoshenko" ? BeamTheory::kTimoshenko : BeamTheory::kEulerBernoulli;
  if (b.theory != BeamTheory::kTimoshenko) {
    for (const char* key : {"shear_coefficient", "poisson"})
      if (r.has(key)) r.fail(key, "is used only with theory = \"timoshenko\"; remove it or set theory");
    return;
  }
  if (b.rigid) r.fail("theory", "expected no beam theory on a rigid body (rigid = true)");
  b.shear_coefficient = r.number_or("shear_coefficient", 5.0 / 6.0, "a shear coefficient in (0, 10] (-)");
  if (!(b.shear_coefficient > 0.0 && b.shear_coefficient <= 10.0))
    r.fail("shear_coefficient",
           fmt::format("expected a shear coefficient in (0, 10] (-), got {}", b.shear_coefficient));
  b.poisson = r.number_or("poisson", 0.3, "Poisson's ratio in (-1, 0.5] (-)");
  if (!(b.poisson > -1.0 && b.poisson <= 0.5))
    r.fail("poisson", fmt::format("expected Poisson's ratio in (-1, 0.5] (-), got {}", b.poisson));
}

void check_beam_theory(const Scene& sc) {
  if (sc.model.kinematics != Kinematics::kCorotational) return;
  for (std::size_t i = 0; i < sc.bodies.size(); ++i)
    if (sc.bodies[i].theory == BeamTheory::kTimoshenko)
      throw InputError(sc.file, "bodies[" + std::to_string(i) + "].theory",
                       "\"timoshenko\" runs with model.kinematics = \"linear\" only (the corotational "
                       "element is Euler-Bernoulli); expected \"euler-bernoulli\" or linear kinematics");
}

}  // namespace beamimpact
