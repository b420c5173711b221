#pragma once
/// @file dict_to_toml.hpp
/// @brief Scene.from_dict: a scene given as JSON-like data (Python dicts and lists) written as
/// TOML text, so that it is read and validated by exactly the scene loader of the CLI.

#include <string>

namespace beamimpact::python {

/// @brief The TOML text of a JSON object: objects become tables, arrays of objects arrays of
/// tables, numbers stay integers or floats. Throws InputError naming `label` and the key for a
/// value TOML cannot hold (null, mixed arrays).
/// @param json_text a JSON object (Python's json.dumps of the dict)
/// @param label what the messages call the scene ("<dict>")
std::string toml_from_json(const std::string& json_text, const std::string& label);

}  // namespace beamimpact::python
