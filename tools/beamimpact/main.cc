/// @file main.cc
/// @brief The `beamimpact` command: dispatches to its subcommands.
/// Exit codes: 0 success; 1 a verification gate failed; 2 bad input (scene, options); 3 a run failed.

#include <cstdio>
#include <filesystem>
#include <new>

#include <CLI/CLI.hpp>

#include <api/registry.hpp>
#include <beamimpact/version.hpp>
#include <solver/util/InputError.hpp>
#include <verification/jobs/task_farm.hpp>

#include "CommandExit.hpp"
#include "command_methods.hpp"
#include "command_model.hpp"
#include "command_protocol.hpp"
#include "command_run.hpp"
#include "command_scenes.hpp"
#include "command_study.hpp"
#include "command_verification.hpp"

namespace {

/// An error on one rank of an MPI job ends every rank (the others would wait for it forever).
int fail(int code) {
  if (beamimpact::jobs::World::size() > 1) beamimpact::jobs::World::abort(code);
  return code;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace beamimpact;
  const jobs::World world(argc, argv);  // MPI, when started by mpirun
  CLI::App app{"beamimpact: dynamic beam-to-beam collision (Pu & Chi 2011) with independent references"};
  app.set_version_flag("--version", kVersion);
  app.require_subcommand(1);
  // A bad option is one line, as every other bad input: what was expected, no second line.
  app.failure_message(
      [](const CLI::App*, const CLI::Error& e) { return std::string("error: ") + e.what() + "\n"; });
  try {
    (void)methods();  // the built-in ones and the default methods files, for the help texts
    add_command_run(app);
    add_command_methods(app);  // methods, schema
    add_command_scenes(app);
    add_verification_commands(app);  // compare, verify, sweep
    add_command_study(app);
    add_protocol_commands(app);  // conform, score
    add_command_model(app);
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = jobs::World::rank() == 0 ? app.exit(e) : e.get_exit_code();
    return code == 0 ? 0 : fail(2);
  } catch (const CommandExit& e) {
    return e.code;
  } catch (const InputError& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return fail(2);
  } catch (const std::filesystem::filesystem_error& e) {
    // A path the file system refuses (too long, not writable, not a directory): the user's --out
    // or an input path, so bad input, named without the library's wording.
    std::fprintf(stderr, "error: %s: %s (check --out and the paths given)\n",
                 InputError::clip(e.path1().string(), 160).c_str(), e.code().message().c_str());
    return fail(2);
  } catch (const std::bad_alloc&) {
    std::fprintf(stderr, "error: out of memory: the run needs more memory than this machine has\n");
    return fail(3);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return fail(3);
  }
  return 0;
}
