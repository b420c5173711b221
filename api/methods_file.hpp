#pragma once
/// @file methods_file.hpp
/// @brief Methods files: external solvers declared in TOML, with no C++ edit (docs/protocol.md).
///
/// @code
///   [[method]]
///   name = "mysolver"
///   summary = "my penalty code"
///   command = ["/usr/bin/python3", "{here}/mysolver.py", "{scene}", "--out", "{out}", "--dt", "{dt}"]
///   check = ["/usr/bin/python3", "-c", "import numpy"]
///   accepts = { dt = true, friction = false }
///   slow = false
/// @endcode
///
/// Found by `--methods FILE` (every subcommand), the environment variable BEAMIMPACT_METHODS
/// (files separated by ':') and the default file verification/methods.toml (next to the program's
/// source tree, or share/beamimpact/verification/ when installed).

#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include <api/registry.hpp>

namespace beamimpact {

/// @brief The run placeholders of a command: {scene} {out} {dt} {mesh} {end}.
const std::vector<std::string>& run_placeholders();

/// @brief Replaces every {name} of `arg` by values.at(name). Returns false, leaving `arg` as
/// it was, when a placeholder has no value or an empty one.
bool expand_placeholders(std::string& arg, const std::map<std::string, std::string>& values);

/// @brief Reads and checks a methods file (unknown key, missing or empty command, a command
/// that does not exist, an unknown placeholder, two methods of one name, accepts that the
/// command cannot honour). Throws InputError naming the file and the key.
/// @param file the methods file; @param program expands {beamimpact}
std::vector<Method> read_methods_file(const std::filesystem::path& file,
                                      const std::filesystem::path& program);

/// @brief Reads a methods file and adds its methods to the registry (a file already read, by
/// canonical path, is not read again). Throws InputError as read_methods_file and add_method.
void load_methods_file(const std::filesystem::path& file);

/// @brief Every methods file read so far, in order (for the runs a command starts: each gets
/// `--methods FILE` for each of them).
const std::vector<std::filesystem::path>& loaded_methods_files();

/// @brief The files read before any --methods: those of BEAMIMPACT_METHODS, then the default
/// file when it exists.
std::vector<std::filesystem::path> default_methods_files();

/// @brief A program given without a folder, looked up in PATH as the shell does (an executable
/// file); "" when not found.
/// @param name the program's name, e.g. "python3"
std::string on_path(const std::string& name);

/// @brief The folder holding verification/methods.toml, verification/matrix.toml and the
/// shipped scenes: the repository or the installed share/beamimpact ("" when none is found).
std::filesystem::path data_root();

/// @brief The beamimpact program: the running one (/proc/self/exe) when it is named beamimpact,
/// else (the Python module, a test program) the one found from the file holding this code
/// upwards (bin/beamimpact, or beamimpact of a build tree). {beamimpact}, the runs' program, and
/// where the default methods file is looked for.
std::filesystem::path program_path();

}  // namespace beamimpact
