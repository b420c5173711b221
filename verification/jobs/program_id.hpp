#pragma once
/// @file program_id.hpp
/// @brief What identifies the program that makes a result: the SHA-256 of the bytes of the file
/// holding the running code (the `beamimpact` executable, or the Python module's shared object),
/// so that two builds of different code never pass for one, even with the same version string
/// (every build of an edited tree is `<semver>+<commit>-dirty`), and a rebuild of the same code
/// to the same bytes stays the same program.

#include <filesystem>
#include <string>

namespace beamimpact::jobs {

/// @brief The file holding the code of this process that calls it: the mapping of this
/// function's own address in /proc/self/maps (the executable the libraries are linked into, or
/// the shared object they are in); /proc/self/exe when that cannot be read.
std::filesystem::path program_code_file();

/// @brief Lower-case hex SHA-256 of program_code_file()'s bytes, read once per process (the
/// first call; later calls return the same string). When the file cannot be read, an id of this
/// process alone ("unread:" and the process id and start time), which no other process shares:
/// its records are then never taken by another.
const std::string& program_sha256();

}  // namespace beamimpact::jobs
