#include "command_methods.hpp"

#include <algorithm>

#include <fmt/format.h>

#include <api/registry.hpp>
#include <solver/schema/output_schema.hpp>

#include "methods_option.hpp"

namespace beamimpact {
namespace {

/// The accepted capabilities as short words ("dt mesh-factor friction ..."), "-" for none.
std::string accepted(const Method::Accepts& a) {
  std::string s;
  for (const AcceptsKey& k : accepts_keys())
    if (a.*k.field) {
      std::string word = k.key;
      std::replace(word.begin(), word.end(), '_', '-');
      s += (s.empty() ? "" : " ") + word;
    }
  return s.empty() ? "-" : s;
}

void print_methods() {
  for (const Method& m : methods()) {
    const std::string why = unavailable(m);
    fmt::print("{:<10} {:<10} {}\n", m.name, m.in_process() ? "in-process" : "program",
               why.empty() ? "runs here" : "cannot run here: " + why);
    fmt::print("{:<10} from: {}\n", "", m.origin);
    fmt::print("{:<10} accepts: {}{}\n", "", accepted(m.accepts), m.slow ? " (slow)" : "");
    fmt::print("{:<10} {}\n", "", m.summary);
  }
}

}  // namespace

void add_command_methods(CLI::App& app) {
  CLI::App* m = app.add_subcommand(
      "methods",
      "List every method: built-in or from which methods file, whether it can run here, what it accepts");
  add_methods_option(m);
  m->callback(print_methods);
  app.add_subcommand(
         "schema",
         "Print the output schema (history.csv columns, enums, units) as JSON; the scene format and "
         "the output files are described in docs/scene-format.md")
      ->callback([] { fmt::print("{}\n", schema_json().dump(2)); });
}

}  // namespace beamimpact
