// Fuzz target: the scene loader (TOML + --set overrides) and the run-cost guard.
// Input: a scene file; optional --set overrides follow a line "#--set", one per line.
// Contract: a scene loads, or load_scene throws InputError (exit 2 in the CLI). Anything else
// (another exception, a crash, a sanitizer report) is a finding.
#include <sstream>
#include <vector>

#include <solver/scene/run_cost.hpp>
#include <solver/scene/scene_io.hpp>
#include <solver/util/InputError.hpp>

#include "fuzz_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace beamimpact;
  const auto [toml, sets] = fuzz::split(data, size, "\n#--set\n");
  std::vector<std::string> overrides;
  std::istringstream lines{std::string(sets)};
  for (std::string line; std::getline(lines, line);) overrides.push_back(line);
  const auto path = fuzz::write("scene.toml", toml);
  try {
    const Scene s = load_scene(path, overrides);
    check_run_cost(s, planned_dt(s));
  } catch (const InputError&) {
  }
  return 0;
}
