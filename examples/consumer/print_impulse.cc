/// @file print_impulse.cc
/// @brief Example consumer of the installed beamimpact package: runs a scene with a method of
/// the registry and prints each contact's normal impulse.
/// Usage: print_impulse SCENE.toml [METHOD]   (METHOD: paper, exact or ida; default paper)

#include <cstdio>
#include <exception>

#include <beamimpact/api/run.hpp>

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: %s SCENE.toml [METHOD]\n", argv[0]);
    return 2;
  }
  try {
    const beamimpact::SimulationResult r = beamimpact::run(argv[1], argc > 2 ? argv[2] : "paper");
    for (const beamimpact::ContactSummary& c : r.contacts)
      std::printf("%s -> %s: impulse %.9g N s (%s)\n", c.striker.c_str(), c.target.c_str(), c.impulse_normal,
                  r.method.c_str());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 2;
  }
  return 0;
}
