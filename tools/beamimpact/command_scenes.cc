#include "command_scenes.hpp"

#include <fmt/format.h>

#include <api/methods_file.hpp>
#include <api/shipped_scenes.hpp>
#include <solver/util/InputError.hpp>

namespace beamimpact {
namespace {

void print_scenes() {
  const std::vector<ShippedScene> scenes = shipped_scenes();
  if (scenes.empty())
    throw InputError("verification/scenes", "",
                     "not found from the program or the working directory upwards (an installed tree or the "
                     "repository has it)");
  for (const ShippedScene& s : scenes) fmt::print("{:<28} {}\n", s.name, s.file.string());
  fmt::print("{} scenes under {}; `beamimpact run NAME` runs one by name when no file NAME exists here\n",
             scenes.size(), (data_root() / "verification/scenes").string());
}

}  // namespace

void add_command_scenes(CLI::App& app) {
  app.add_subcommand("scenes",
                     "List the shipped scenes: name and file (a name works wherever a scene file does)")
      ->callback(print_scenes);
}

CLI::Validator scene_argument() {
  return CLI::Validator(
      [](std::string& arg) -> std::string {
        try {
          arg = resolve_scene(arg).string();
        } catch (const InputError& e) {
          return e.what();
        }
        return {};
      },
      "");
}

}  // namespace beamimpact
