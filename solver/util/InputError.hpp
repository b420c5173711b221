#pragma once
/// @file InputError.hpp
/// @brief The one error type for bad input: it names the file, the key and what was expected.

#include <stdexcept>
#include <string>

namespace beamimpact {

/// @brief Bad user input in any file or option: a scene, a --set override, an unstable dt, a
/// matrix, a study, a run directory's history.csv or summary.json, a command-line option. The
/// CLI prints what() and exits with code 2; no output is written. The Python module raises it
/// as beamimpact.InputError.
class InputError : public std::runtime_error {
 public:
  /// @brief file: the file's path (or the option); key: dotted key such as "bodies[1].area" or a
  /// column name (may be empty); message: what was expected and what was found.
  InputError(std::string file, std::string key, const std::string& message)
      : std::runtime_error(format(file, key, message)), file_(std::move(file)), key_(std::move(key)) {}

  /// @brief The file the error is about.
  const std::string& file() const { return file_; }
  /// @brief The dotted key the error is about ("" when it concerns the whole file).
  const std::string& key() const { return key_; }

  /// @brief Cuts every run of more than `longest` non-blank characters (an echoed value, a
  /// path) to `longest`, marked "...", so that a message stays one readable line.
  /// @param text the message or value; @param longest the longest run kept (>= 4)
  static std::string clip(const std::string& text, std::size_t longest = 80) {
    const std::size_t kLongest = longest;
    std::string out;
    std::size_t run = 0;
    for (char c : text) {
      run = (c == ' ' || c == '\n') ? 0 : run + 1;
      if (run <= kLongest - 3)
        out += c;
      else if (run == kLongest - 2)
        out += "...";
    }
    return out;
  }

 private:
  /// Paths may be long but not kilobytes long: 160 characters keep every ordinary path whole.
  static std::string format(const std::string& file, const std::string& key, const std::string& msg) {
    return clip(file, 160) + (key.empty() ? std::string() : ": key '" + clip(key) + "'") + ": " + clip(msg);
  }
  std::string file_;
  std::string key_;
};

}  // namespace beamimpact
