#pragma once
/// @file registry.hpp
/// @brief The method registry: every method beamimpact can run, by name, in one table (in the
/// style of Ceres' LinearSolver::Create). The CLI, verify, sweep, study and the C++ API reach
/// methods only through it. In-process methods are compiled in (registry.cc); external programs
/// are declared in methods files (TOML, api/methods_file.hpp, docs/protocol.md) with no C++ edit.

#include <deque>
#include <string>
#include <string_view>

#include <solver/method/Method.hpp>

namespace beamimpact {

/// @brief Every method: the built-in ones (paper first), then those of the methods files in the
/// order read. The first call reads the default methods files (methods_file.hpp); a bad file
/// throws InputError naming it and the key.
const std::deque<Method>& methods();

/// @brief Adds a method declared in a methods file. Throws InputError(file, key) when its name is
/// already taken.
/// @param m the method; @param file the methods file, for messages; @param key its table's key
void add_method(Method m, const std::string& file, const std::string& key);

/// @brief The method with this name, or nullptr.
const Method* find_method(std::string_view name);

/// @brief The method with this name. Throws InputError naming `file` and `key` and listing the
/// known names when there is none.
const Method& method(std::string_view name, const std::string& file, const std::string& key);

/// @brief "paper, exact, ida, ...": the names, for messages and help texts.
std::string method_names();

/// @brief The most threads any method takes (the largest Method::max_threads, at least 1): the
/// bound of `--threads`, RunOptions::threads and the Python module's `threads`.
int thread_limit();

/// @brief The method run when none is named (`beamimpact run`, the Python module): the first of
/// the registry (the paper's).
const Method& default_method();

/// @brief Why the method cannot run on this machine ("" when it can): an external program's
/// check command failing or missing (run once per method and remembered).
std::string unavailable(const Method& m);

}  // namespace beamimpact
