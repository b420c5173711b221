// Fuzz target: the verification matrix loader and its tier expansion.
// Input: a matrix file, written to SCRATCH/m/matrix.toml; SCRATCH/verification links to the
// source tree's verification/, so the shipped matrix (root = "..") finds its scenes.
// Contract: load() returns a matrix or throws InputError. Anything else is a finding.
#include <solver/util/InputError.hpp>
#include <verification/matrix/VerificationMatrix.hpp>

#include "fuzz_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace beamimpact;
  static const bool linked = [] {
    std::filesystem::create_directories(fuzz::scratch() / "m");
    std::filesystem::create_directory_symlink(std::filesystem::path(BEAMIMPACT_SOURCE) / "verification",
                                              fuzz::scratch() / "verification");
    return true;
  }();
  (void)linked;
  const auto path = fuzz::write("m/matrix.toml", std::string_view(reinterpret_cast<const char*>(data), size));
  try {
    const auto m = verification::VerificationMatrix::load(path);
    for (const char* tier : {"quick", "full"}) (void)m.runs(tier);
  } catch (const InputError&) {
  }
  return 0;
}
