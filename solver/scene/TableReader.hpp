#pragma once
/// @file TableReader.hpp
/// @brief Typed, checked access to one TOML table of a scene: every read names the file and the
/// full key in its error, every default used is recorded, and finish() rejects unknown keys.
/// Used by the scene loader and by each method for its own table ([ida], [exact], ...).

#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include <toml++/toml.h>

#include <solver/scene/Scene.hpp>
#include <solver/util/InputError.hpp>

namespace beamimpact {

/// @brief While one is alive, every key that a TableReader of this thread asks about is added to it
/// by its full path ("time.dt", "bodies[0].supports[1].fix"): the keys the readers accept, since
/// finish() refuses every other. It lists the scene format's keys for the test of
/// docs/scene-format.md (docs/scene_format_keys.cc); with none alive a read costs one null test.
class KeyLog {
 public:
  KeyLog();
  ~KeyLog();
  KeyLog(const KeyLog&) = delete;
  KeyLog& operator=(const KeyLog&) = delete;
  /// @brief The keys asked about since this log was made.
  const std::set<std::string>& keys() const { return keys_; }

 private:
  friend class TableReader;
  std::set<std::string> keys_;
  KeyLog* outer_;  ///< the log this one hides while alive
};

/// @brief Reads keys of one table; `prefix` is the dotted path of the table ("time", "bodies[0]").
class TableReader {
 public:
  /// @brief assumed (may be null) receives "prefix.key" -> default for every default used.
  TableReader(const toml::table& table, std::string file, std::string prefix,
              std::map<std::string, std::string>* assumed);

  /// @brief A required number (integers accepted). `what` describes it ("a positive number (m)").
  double number(const std::string& key, const std::string& what);
  /// @brief An optional number; fallback recorded as assumed when the key is absent.
  double number_or(const std::string& key, double fallback, const std::string& what);
  /// @brief A required integer.
  long integer(const std::string& key, const std::string& what);
  /// @brief An optional integer.
  long integer_or(const std::string& key, long fallback, const std::string& what);
  /// @brief A required string.
  std::string string(const std::string& key, const std::string& what);
  /// @brief An optional string restricted to `allowed` (empty = any).
  std::string choice_or(const std::string& key, const std::string& fallback,
                        const std::vector<std::string>& allowed);
  /// @brief An optional boolean.
  bool boolean_or(const std::string& key, bool fallback);
  /// @brief An optional boolean with no default (empty when absent).
  std::optional<bool> boolean_opt(const std::string& key);
  /// @brief An array of strings; empty when absent unless `required` (then a missing key fails).
  /// @param key the key in this table; @param required whether the key must be present
  std::vector<std::string> strings(const std::string& key, bool required = false);
  /// @brief A required array of two numbers.
  Vec2 vec2(const std::string& key, const std::string& what);
  /// @brief True when the key is present (marks it as known).
  bool has(const std::string& key);
  /// @brief The raw node (marks it as known); nullptr when absent.
  const toml::node* raw(const std::string& key);
  /// @brief Throws InputError for a value that fails a check (positivity, range, ...).
  [[noreturn]] void fail(const std::string& key, const std::string& message) const;
  /// @brief Throws InputError for a required key that is absent ("missing; expected `what`"),
  /// naming any key of the table no read asked for within a spelling of it (`dtt` for `dt`).
  [[noreturn]] void missing(const std::string& key, const std::string& what) const;
  /// @brief Throws InputError naming the first key that no read asked for.
  void finish() const;
  /// @brief "prefix.key" (or "key" when the prefix is empty).
  std::string path(const std::string& key) const;
  /// @brief The scene file.
  const std::string& file() const { return file_; }

 private:
  const toml::node* find(const std::string& key);
  /// Records the key as known (finish() accepts it) and in the thread's KeyLog.
  void mark(const std::string& key);
  void assume(const std::string& key, const std::string& value);
  const toml::table& table_;
  std::string file_, prefix_;
  std::map<std::string, std::string>* assumed_;
  std::set<std::string> seen_;
};

/// @brief A reader over a method's own table ("ida", "exact", ...) of the scene; an absent
/// table reads as empty. It reads the scene's table in place: keep the scene alive while reading.
class MethodOptions {
 public:
  /// @brief Reads scene.method_tables[method]; assumed defaults go to `assumed`.
  /// @param scene the scene whose table is read; @param method the table's name ("ida")
  /// @param assumed receives "method.key" -> default for every default used (may be null)
  MethodOptions(const Scene& scene, const std::string& method, std::map<std::string, std::string>* assumed);
  MethodOptions(const MethodOptions&) = delete;
  MethodOptions& operator=(const MethodOptions&) = delete;
  /// @brief The reader; call finish() on it after the last read.
  TableReader& reader() { return reader_; }

 private:
  toml::table empty_;  ///< read when the scene has no such table
  TableReader reader_;
};

}  // namespace beamimpact
