#include <references/exact/ExactCost.hpp>

#include <fmt/format.h>

#include <solver/scene/run_cost.hpp>
#include <solver/util/InputError.hpp>

namespace beamimpact::exact {

void refuse_extraordinary(const Scene& scene, const std::string& key, const std::string& what,
                          const ExactCost& cost, const std::string& remedy) {
  if (scene.time.allow_long_run || (cost.seconds <= kOrdinaryExactSeconds && cost.bytes <= kOrdinaryBytes))
    return;
  throw InputError(
      scene.file, key,
      fmt::format("{} is far beyond an ordinary run: {} (ordinary: at most {:g} min and {:g} GB); "
                  "{}, or time.allow_long_run = true (or --allow-long) to run it",
                  what, cost.text, kOrdinaryExactSeconds / 60.0, kOrdinaryBytes / 1e9, remedy));
}

}  // namespace beamimpact::exact
