#pragma once
/// @file SceneError.hpp
/// @brief The one error type for bad input: it names the file, the key and what was expected.

#include <stdexcept>
#include <string>

namespace beamimpact {

/// @brief Bad user input (scene file, --set override, unstable dt). The CLI prints what() and
/// exits with code 2; no output is written.
class SceneError : public std::runtime_error {
 public:
  /// @brief file: the scene path; key: dotted key such as "bodies[1].area" (may be empty);
  /// message: what was expected and what was found.
  SceneError(std::string file, std::string key, const std::string& message)
      : std::runtime_error(format(file, key, message)), file_(std::move(file)), key_(std::move(key)) {}

  /// @brief The scene file the error is about.
  const std::string& file() const { return file_; }
  /// @brief The dotted key the error is about ("" when it concerns the whole file).
  const std::string& key() const { return key_; }

 private:
  static std::string format(const std::string& file, const std::string& key, const std::string& msg) {
    return file + (key.empty() ? std::string() : ": key '" + clip(key) + "'") + ": " + clip(msg);
  }
  /// Cuts every run of more than 80 non-blank characters (an echoed value) to 80, marked "...".
  static std::string clip(const std::string& text) {
    constexpr std::size_t kLongest = 80;
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
  std::string file_;
  std::string key_;
};

}  // namespace beamimpact
