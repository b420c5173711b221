#pragma once
/// @file methods_option.hpp
/// @brief `--methods FILE` for every subcommand: each file's methods join the registry as the
/// option is parsed, before the subcommand runs (docs/protocol.md).

#include <CLI/CLI.hpp>

namespace beamimpact {

/// @brief Adds the repeatable option --methods FILE to `sub`.
CLI::Option* add_methods_option(CLI::App* sub);

}  // namespace beamimpact
