#include <verification/jobs/interruption.hpp>

#include <api/child_process.hpp>

namespace beamimpact::jobs {

void forward_interruptions() { catch_interruptions(); }

int interruption() { return caught_signal(); }

}  // namespace beamimpact::jobs
