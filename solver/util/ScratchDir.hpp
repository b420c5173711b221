#pragma once
/// @file ScratchDir.hpp
/// @brief A folder made on construction and removed, with everything in it, on destruction
/// (tests and fuzz targets leave nothing behind).

#include <filesystem>
#include <string>
#include <system_error>

namespace beamimpact {

/// @brief Owns a scratch folder. Typically a function-local static: removed at process exit.
class ScratchDir {
 public:
  /// @brief path: the folder to make (with its parents).
  explicit ScratchDir(std::filesystem::path path) : path_(std::move(path)) {
    std::filesystem::create_directories(path_);
  }
  ~ScratchDir() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;
  /// @brief The folder.
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

}  // namespace beamimpact
