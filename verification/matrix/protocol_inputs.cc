#include <verification/matrix/protocol_inputs.hpp>

#include <api/methods_file.hpp>
#include <solver/util/InputError.hpp>

namespace beamimpact::verification {

const Method& runnable_method(const std::string& name, const std::string& command) {
  const Method& m = method(name, "--methods", command);
  if (const std::string why = unavailable(m); !why.empty())
    throw InputError(m.origin, "check", "the method cannot run here: " + why);
  return m;
}

std::filesystem::path shipped_data(const std::string& command) {
  const std::filesystem::path root = data_root();
  if (root.empty())
    throw InputError("verification/methods.toml", "",
                     "not found from the program or the working directory upwards; `beamimpact " + command +
                         "` needs the shipped scenes (run it inside the repository or an installed tree)");
  return root;
}

}  // namespace beamimpact::verification
