/// @file main.cc
/// @brief The `beamimpact` command: dispatches to its subcommands.
/// Exit codes: 0 success; 1 a verification gate failed; 2 bad input (scene, options); 3 a run failed.

#include <cstdio>
#include <filesystem>
#include <new>

#include <CLI/CLI.hpp>

#include <beamimpact/scene/SceneError.hpp>
#include <beamimpact/version.hpp>

#include "CommandExit.hpp"
#include "command_run.hpp"
#include "command_verification.hpp"

int main(int argc, char** argv) {
  using namespace beamimpact;
  CLI::App app{"beamimpact: dynamic beam-to-beam collision (Pu & Chi 2011) with independent references"};
  app.set_version_flag("--version", kVersion);
  app.require_subcommand(1);
  add_command_run(app);
  add_command_methods(app);        // methods, schema
  add_verification_commands(app);  // compare, verify, sweep
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : 2;
  } catch (const CommandExit& e) {
    return e.code;
  } catch (const SceneError& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 2;
  } catch (const std::filesystem::filesystem_error& e) {
    // A path the file system refuses (too long, not writable, not a directory): the user's --out
    // or an input path, so bad input, named without the library's wording.
    std::fprintf(stderr, "error: %s: %s (check --out and the paths given)\n",
                 SceneError::clip(e.path1().string(), 160).c_str(), e.code().message().c_str());
    return 2;
  } catch (const std::bad_alloc&) {
    std::fprintf(stderr, "error: out of memory: the run needs more memory than this machine has\n");
    return 3;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 3;
  }
  return 0;
}
