#pragma once
/// @file write_file_atomic.hpp
/// @brief Outputs that never lie: a file is written whole or not at all, and a command removes
/// the outputs of an earlier run from its directory before anything can refuse or fail, so that
/// a directory holds a complete result or visibly none.

#include <filesystem>
#include <initializer_list>
#include <string>

namespace beamimpact {

/// @brief Writes text to file.partial, then renames it over file. Throws std::runtime_error on error.
void write_file_atomic(const std::filesystem::path& file, const std::string& text);

/// @brief Removes dir/name (and dir/name.partial) for each name that exists; nothing else of the
/// directory is touched. Throws std::runtime_error naming the file when one cannot be removed.
/// @param dir the output directory (need not exist; empty: none, nothing is removed)
/// @param names the files a command writes there (its result, reports, collections)
void remove_stale_outputs(const std::filesystem::path& dir, std::initializer_list<const char*> names);

}  // namespace beamimpact
