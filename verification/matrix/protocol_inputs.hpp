#pragma once
/// @file protocol_inputs.hpp
/// @brief What `score` and `conform` (the protocol's commands, docs/protocol.md) need before they
/// start, refused as bad input (InputError) when it is not there: a method that runs here, and the
/// shipped scenes and cards.

#include <filesystem>
#include <string>

#include <api/registry.hpp>

namespace beamimpact::verification {

/// @brief The method `name`, which must run here. Throws InputError naming --methods for an unknown
/// name, and its methods file and "check" for a method whose program cannot run here.
/// @param name the method (`beamimpact methods`); @param command "score" or "conform", for messages
const Method& runnable_method(const std::string& name, const std::string& command);

/// @brief The data root (the repository or the installed share/beamimpact, data_root()). Throws
/// InputError when there is none: the command needs the shipped scenes.
/// @param command "score" or "conform", for the message
std::filesystem::path shipped_data(const std::string& command);

}  // namespace beamimpact::verification
