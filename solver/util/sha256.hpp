#pragma once
/// @file sha256.hpp
/// @brief SHA-256 of a byte string (FIPS 180-4), to identify the scene a result came from.

#include <string>
#include <string_view>

namespace beamimpact {

/// @brief Lower-case hex SHA-256 digest of `data`.
std::string sha256_hex(std::string_view data);

}  // namespace beamimpact
