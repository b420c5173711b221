#include <verification/matrix/interruption.hpp>

#include <api/child_process.hpp>

namespace beamimpact::verification {

void forward_interruptions() { catch_interruptions(); }

int interruption() { return caught_signal(); }

}  // namespace beamimpact::verification
