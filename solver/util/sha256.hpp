#pragma once
/// @file sha256.hpp
/// @brief SHA-256 of a byte string (FIPS 180-4), to identify the scene a result came from.

#include <filesystem>
#include <string>
#include <string_view>

namespace beamimpact {

/// @brief Lower-case hex SHA-256 digest of `data`.
std::string sha256_hex(std::string_view data);

/// @brief Lower-case hex SHA-256 digest of a file's bytes; "" when it cannot be read.
/// @param file the file
std::string file_sha256(const std::filesystem::path& file);

}  // namespace beamimpact
