#include "methods_option.hpp"

#include <api/methods_file.hpp>

namespace beamimpact {

CLI::Option* add_methods_option(CLI::App* sub) {
  return sub
      ->add_option_function<std::vector<std::string>>(
          "--methods",
          [](const std::vector<std::string>& files) {
            for (const auto& f : files) load_methods_file(f);
          },
          "Methods file (TOML) declaring external methods, in addition to BEAMIMPACT_METHODS and "
          "verification/methods.toml (repeatable; docs/protocol.md)")
      ->type_name("FILE");
}

}  // namespace beamimpact
