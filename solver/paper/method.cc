#include <solver/paper/method.hpp>

#include <solver/integrator/ExplicitContactIntegrator.hpp>
#include <solver/paper/solve.hpp>

namespace beamimpact::paper {

Method method() {
  Method m;
  m.name = "paper";
  m.summary = "Pu & Chi (2011) explicit dynamic-contact integrator (solver/)";
  m.options_table = "paper";
  m.max_threads = kMaxThreads;
  m.solve = [](const Scene& scene, const Method::Request& q) {
    return solve(scene, q.fields_dir, q.threads);
  };
  m.writes_fields = true;
  return m;
}

}  // namespace beamimpact::paper
