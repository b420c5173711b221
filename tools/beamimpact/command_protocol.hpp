#pragma once
/// @file command_protocol.hpp
/// @brief `beamimpact conform NAME` (an external method checked against every rule of the
/// protocol) and `beamimpact score NAME` (a method's scorecard on the benchmark set).

#include <CLI/CLI.hpp>

namespace beamimpact {

/// @brief Registers `conform` and `score` on app.
void add_protocol_commands(CLI::App& app);

}  // namespace beamimpact
