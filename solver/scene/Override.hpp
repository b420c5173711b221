#pragma once
/// @file Override.hpp
/// @brief A scene override: a value put at a key of the parsed scene before it is read. The one
/// path of every override: `--set key=value` text is parsed into one once (parse_override), a
/// typed edit (a run's step, its mesh) is built as one directly (make_override).

#include <memory>
#include <string>
#include <vector>

#include <toml++/toml.h>

namespace beamimpact {

/// @brief One override of the scene's parsed TOML.
struct Override {
  /// @brief Where: "time.dt", "bodies[1].elements", "bodies.B.E", "contacts.0.friction".
  std::string key;
  /// @brief The value put there (any TOML node: a number, a string, an array, a table).
  std::shared_ptr<const toml::node> value;
  /// @brief The value as summary.json "overrides" and Scene::overrides record it ("0.005").
  std::string text;
};

/// @brief An override of `value` (copied) at `key`, recorded as `text`.
/// @param key the dotted key; @param value the TOML value; @param text its recorded form
Override make_override(std::string key, const toml::node& value, std::string text);

/// @brief Parses "key=value" (the value TOML: "0.005", "[1, 0]", "true", "\"lumped\""; a bare
/// word is a string). Throws InputError naming `file` and the assignment when it has no key.
/// @param assignment the --set text; @param file what messages name as the file
Override parse_override(const std::string& assignment, const std::string& file);

/// @brief parse_override() of each assignment, in order.
/// @param assignments the --set texts; @param file what messages name as the file
std::vector<Override> parse_overrides(const std::vector<std::string>& assignments, const std::string& file);

/// @brief Puts o.value at o.key in root: a missing table on the way is made, an array of tables
/// is entered by an index from 0 or by a body's name. Throws InputError naming `file` and the key
/// for a key that leads through something else.
/// @param root the parsed scene; @param file what messages name as the file; @param o the override
void apply_override(toml::table& root, const std::string& file, const Override& o);

}  // namespace beamimpact
