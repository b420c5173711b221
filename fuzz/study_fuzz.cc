// Fuzz target: the study-file loader (design, parameters, reference, breaks, cost check, and the
// first point's overrides applied to the scene).
// Input: a study file, written to SCRATCH/studies/study.toml; SCRATCH/scenes links to the source
// tree's verification/scenes/, so the shipped studies (scene = "../scenes/...") find their scene.
// Contract: Study::load returns a study or throws InputError. Anything else is a finding.
#include <solver/util/InputError.hpp>
#include <verification/study/Study.hpp>

#include "fuzz_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace beamimpact;
  static const bool linked = [] {
    std::filesystem::create_directories(fuzz::scratch() / "studies");
    std::filesystem::create_directory_symlink(
        std::filesystem::path(BEAMIMPACT_SOURCE) / "verification/scenes", fuzz::scratch() / "scenes");
    return true;
  }();
  (void)linked;
  const auto path =
      fuzz::write("studies/study.toml", std::string_view(reinterpret_cast<const char*>(data), size));
  try {
    (void)study::Study::load(path);
  } catch (const InputError&) {
  }
  return 0;
}
