#include "beamimpact/methods.hpp"

#include "run/run_paper.hpp"
#ifdef BEAMIMPACT_HAVE_exact
#include "exact/run_exact.hpp"
#endif
#ifdef BEAMIMPACT_HAVE_ida
#include "ida/run_ida.hpp"
#endif

namespace beamimpact {

const std::map<std::string, MethodFn>& methods() {
  static const std::map<std::string, MethodFn> table = {
      {"paper", run_paper},
#ifdef BEAMIMPACT_HAVE_exact
      {"exact", run_exact},
#endif
#ifdef BEAMIMPACT_HAVE_ida
      {"ida", run_ida},
#endif
  };
  return table;
}

}  // namespace beamimpact
