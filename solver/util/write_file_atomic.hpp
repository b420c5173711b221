#pragma once
/// @file write_file_atomic.hpp
/// @brief Writes a whole file or nothing: a reader never sees a half-written result.

#include <filesystem>
#include <string>

namespace beamimpact {

/// @brief Writes text to file.partial, then renames it over file. Throws std::runtime_error on error.
void write_file_atomic(const std::filesystem::path& file, const std::string& text);

}  // namespace beamimpact
