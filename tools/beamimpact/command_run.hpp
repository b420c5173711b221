#pragma once
/// @file command_run.hpp
/// @brief `beamimpact run SCENE --out DIR [--method M] [--dt S] [--mesh M] [--set key=value ...]`.

#include <string>

#include <CLI/CLI.hpp>

namespace beamimpact {

/// @brief Registers the `run` subcommand on app.
void add_command_run(CLI::App& app);

/// @brief Adds --threads (1..1024, every bad value refused naming the option) to a subcommand.
/// @param sub the subcommand; @param threads receives the value (left as is when not given)
/// @param help what the count applies to
void add_threads_option(CLI::App* sub, int& threads, const std::string& help);

}  // namespace beamimpact
