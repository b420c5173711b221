#pragma once
/// @file dict_to_toml.hpp
/// @brief Scene.from_dict and Scene.with_overrides: Python values (dicts, lists, strings, numbers,
/// booleans, numpy scalars and arrays) made into TOML values directly, so that the scene is read
/// and validated by exactly the scene loader of the CLI without passing through text.

#include <string>
#include <vector>

#include <pybind11/pybind11.h>
#include <toml++/toml.h>

#include <solver/scene/Override.hpp>

namespace beamimpact::python {

/// @brief The TOML table of a dict: dicts become tables, lists (and tuples, numpy arrays) arrays,
/// ints integers, floats floats. Throws InputError naming `label` and the key for None or an
/// integer beyond 64 bits, and TypeError for a value of another kind.
/// @param tables the scene's tables ({"name": ..., "time": {...}, "bodies": [...]})
/// @param label what the messages call the scene ("<dict>")
toml::table table_from_dict(const pybind11::dict& tables, const std::string& label);

/// @brief The overrides of a Python scene: "key=value" text (as --set) or (key, value, text)
/// triples, whose value becomes a TOML value directly and whose text is what the run records.
/// @param items str or (key, value, text) each; @param label what messages name as the file
std::vector<Override> overrides_from_python(const pybind11::list& items, const std::string& label);

}  // namespace beamimpact::python
