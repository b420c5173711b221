// Fuzz target: the run reader (summary.json + history.csv of a run directory).
// Input: summary.json text, a line "#--history.csv", then history.csv text.
// Contract: StoredRun::read returns a run or throws SceneError; a run read answers contacts()
// and output_step(). Anything else is a finding.
#include <solver/scene/SceneError.hpp>
#include <verification/compare/StoredRun.hpp>

#include "fuzz_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace beamimpact;
  const auto [summary, history] = fuzz::split(data, size, "\n#--history.csv\n");
  fuzz::write("summary.json", summary);
  fuzz::write("history.csv", history);
  try {
    const auto run = verification::StoredRun::read(fuzz::scratch());
    (void)run.contacts();
    (void)run.output_step();
  } catch (const SceneError&) {
  }
  return 0;
}
