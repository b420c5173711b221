// Every built-in method runs what its registry entry says it accepts: for each capability it
// declares true, a small scene that needs that capability is not refused for it (the run passes,
// or is refused by the method for another reason, naming another key); a capability declared
// false is refused, naming the key. The declared facts are what `beamimpact methods` prints and
// what api::run checks, so a declared `true` the method's own code refuses is caught here.
#include <api/accepts.hpp>

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <api/registry.hpp>
#include <api/run.hpp>
#include <solver/util/InputError.hpp>
#include <solver/util/Progress.hpp>

namespace beamimpact {
namespace {

namespace fs = std::filesystem;

const fs::path kScenes = fs::path(BEAMIMPACT_SOURCE) / "verification" / "scenes";

/// A run that needs one capability: the scene, its overrides, a step or mesh asked for, and the
/// key a refusal for that capability names (api/accepts.cc, or the method's own recogniser).
struct Needs {
  std::string scene;
  std::vector<std::string> set;
  std::string reason_key;
  std::optional<double> dt = std::nullopt;
  std::string mesh = {};
};

/// One run per capability of Method::Accepts (every key of accepts_keys()), short ones: the
/// scene's end cut where the contact has happened by then.
const std::map<std::string, Needs>& needs() {
  static const std::map<std::string, Needs> n = {
      {"dt", {"paper/s1_central.toml", {"time.end=1.0"}, "time.dt", 0.005}},
      {"mesh_factor", {"paper/s1_central.toml", {"time.end=1.0"}, "mesh", std::nullopt, "2"}},
      {"friction",
       {"paper/s2_transverse.toml", {"contacts[0].friction=0.3", "time.end=1.0"}, "contacts[0].friction"}},
      {"rigid_friction", {"extra/rigid_rod_oblique.toml", {}, "contacts[0].friction"}},
      {"rotation",
       {"paper/s1_central.toml", {"model.kinematics=\"corotational\"", "time.end=1.0"}, "model.kinematics"}},
      {"rigid", {"extra/rigid_rod_oblique.toml", {"contacts[0].friction=0"}, "bodies[0].rigid"}},
      {"search", {"paper/s1_central.toml", {"contacts[0].node=\"all\"", "time.end=1.0"}, "contacts[0].node"}},
      {"several_contacts", {"hard/two_contacts_pushed.toml", {"time.end=1.0"}, "contacts"}},
      {"timoshenko", {"extra/s2_stocky_timoshenko.toml", {"time.end=0.3"}, "bodies[0].theory"}},
      {"hertz", {"extra/ball_on_beam.toml", {}, "contacts[0].law"}},
      {"bending", {"paper/s2_transverse.toml", {"time.end=1.0"}, "bodies"}},
      {"node_to_surface", {"paper/s3_surface_10.toml", {"time.end=1.0"}, "contacts[0]"}},
      {"loads", {"benchmarks/bouncing_bar.toml", {"time.end=2.0"}, "loads"}},
  };
  return n;
}

/// "" when the run passed, else the InputError's key (a run that fails otherwise fails the test).
std::string refused_key(const Method& m, const Needs& n) {
  RunOptions o;
  o.set = n.set;
  o.dt = n.dt;
  o.mesh = n.mesh;
  try {
    (void)run(kScenes / n.scene, m.name, o);
    return "";
  } catch (const InputError& e) {
    return e.key();
  }
}

TEST(Accepts, EveryCapabilityHasARunThatNeedsIt) {
  Progress::set_enabled(false);
  for (const AcceptsKey& k : accepts_keys()) EXPECT_EQ(needs().count(k.key), 1u) << k.key;
}

TEST(Accepts, EveryBuiltInMethodRunsWhatItDeclares) {
  for (const Method& m : methods()) {
    if (m.origin != "built-in") continue;
    for (const AcceptsKey& k : accepts_keys()) {
      if (!(m.accepts.*k.field)) continue;
      const Needs& n = needs().at(k.key);
      // A refusal naming another key is the method's own reason (its recogniser's); one naming
      // the capability's key contradicts the declaration.
      EXPECT_NE(refused_key(m, n), n.reason_key) << m.name << " declares accepts." << k.key << " = true";
    }
  }
}

TEST(Accepts, ACapabilityDeclaredFalseIsRefused) {
  // The exact solutions take friction between rigid bodies only: friction on deformable beams is
  // refused by api::run for its declaration, before the method runs.
  const Method& exact = method("exact", "test", "method");
  ASSERT_FALSE(exact.accepts.friction);
  EXPECT_EQ(refused_key(exact, needs().at("friction")), "contacts[0].friction");
  // IDA declares no contact search.
  const Method& ida = method("ida", "test", "method");
  ASSERT_FALSE(ida.accepts.search);
  EXPECT_EQ(refused_key(ida, needs().at("search")), "contacts[0].node");
}

}  // namespace
}  // namespace beamimpact
