// Fuzz target: the methods-file loader ([[method]] tables: command, check, accepts, slow) and
// the run placeholders of the commands it returns. Nothing is started: reading a methods file
// only checks that each command's program exists.
// Input: a methods file, written to SCRATCH/verification/methods.toml; SCRATCH/references links
// to the source tree's references/, so the shipped file's "{here}/../references/..." scripts exist.
// Contract: read_methods_file returns methods or throws InputError. Anything else is a finding.
#include <api/methods_file.hpp>
#include <solver/util/InputError.hpp>

#include "fuzz_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace beamimpact;
  static const bool linked = [] {
    std::filesystem::create_directories(fuzz::scratch() / "verification");
    std::filesystem::create_directory_symlink(std::filesystem::path(BEAMIMPACT_SOURCE) / "references",
                                              fuzz::scratch() / "references");
    return true;
  }();
  (void)linked;
  const auto path =
      fuzz::write("verification/methods.toml", std::string_view(reinterpret_cast<const char*>(data), size));
  const std::map<std::string, std::string> values = {
      {"scene", "s.toml"}, {"out", "o"}, {"dt", "0.001"}, {"mesh", "2"}, {"end", ""}};
  try {
    for (Method& m : read_methods_file(path, "/usr/bin/beamimpact"))
      for (std::string& arg : m.command) (void)expand_placeholders(arg, values);
  } catch (const InputError&) {
  }
  return 0;
}
