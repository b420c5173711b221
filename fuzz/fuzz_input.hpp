#pragma once
/// @file fuzz_input.hpp
/// @brief Shared by the fuzz targets: a per-process scratch folder and file writing. The loaders
/// read files, so each input is written to a file first (tmpfs or page cache: cheap).

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>

#include <unistd.h>

#include <solver/util/ScratchDir.hpp>

namespace beamimpact::fuzz {

/// @brief TMPDIR/beamimpact_fuzz_<pid>, made on first use and removed at exit.
inline const std::filesystem::path& scratch() {
  static const ScratchDir dir(std::filesystem::temp_directory_path() /
                              ("beamimpact_fuzz_" + std::to_string(getpid())));
  return dir.path();
}

/// @brief Writes `text` to scratch()/name and returns the path.
inline std::filesystem::path write(const std::string& name, std::string_view text) {
  const std::filesystem::path p = scratch() / name;
  std::ofstream(p, std::ios::binary).write(text.data(), static_cast<std::streamsize>(text.size()));
  return p;
}

/// @brief Splits the input at the first `separator`: {before, after} ("" after when absent).
inline std::pair<std::string_view, std::string_view> split(const uint8_t* data, size_t size,
                                                           std::string_view separator) {
  const std::string_view all(reinterpret_cast<const char*>(data), size);
  const auto at = all.find(separator);
  if (at == std::string_view::npos) return {all, {}};
  return {all.substr(0, at), all.substr(at + separator.size())};
}

}  // namespace beamimpact::fuzz
