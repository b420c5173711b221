// Fuzz target: the run reader (summary.json + history.csv of a run directory).
// Input: summary.json text, a line "#--history.csv", then history.csv text.
// Contract: StoredRun::read returns a run or throws InputError; a run read answers contacts()
// and output_step(). Anything else is a finding.
#include <solver/util/InputError.hpp>
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
  } catch (const InputError&) {
  }
  return 0;
}
