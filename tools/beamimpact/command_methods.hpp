#pragma once
/// @file command_methods.hpp
/// @brief `beamimpact methods` (every method, where it was declared, whether it can run here and
/// what it accepts) and `beamimpact schema` (the output schema as JSON).

#include <CLI/CLI.hpp>

namespace beamimpact {

/// @brief Registers `methods` and `schema` on app.
void add_command_methods(CLI::App& app);

}  // namespace beamimpact
