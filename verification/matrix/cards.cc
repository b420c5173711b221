#include <verification/matrix/cards.hpp>

#include <algorithm>

#include <fmt/format.h>
#include <toml++/toml.h>

#include <api/registry.hpp>
#include <solver/scene/TableReader.hpp>
#include <solver/util/InputError.hpp>
#include <verification/compare/compare_runs.hpp>

namespace beamimpact::verification {
namespace {

namespace fs = std::filesystem;

/// The registry's reference methods, best first ("exact, ida").
std::string reference_names() {
  std::string names;
  for (const ReferenceRank r : {ReferenceRank::kExact, ReferenceRank::kConverged})
    for (const Method& m : methods())
      if (m.as_reference.rank == r) names += (names.empty() ? "" : ", ") + m.name;
  return names;
}

/// One { metric, tol, why } of a card.
Gate read_quantity(const toml::node& n, const std::string& file, const std::string& key) {
  const toml::table* t = n.as_table();
  if (!t) throw InputError(file, key, "expected { metric = ..., tol = ..., why = ... }");
  TableReader r(*t, file, key, nullptr);
  Gate g;
  g.metric = r.string("metric", "a norm name of `beamimpact compare` (e.g. \"impulse\")");
  if (!known_norm(g.metric)) r.fail("metric", "unknown norm '" + g.metric + "' (see `beamimpact compare`)");
  g.tol = r.number("tol", "a non-negative tolerance in the norm's unit");
  if (!(*g.tol >= 0.0)) r.fail("tol", "expected a non-negative tolerance in the norm's unit");
  g.why = r.string("why", "where the tolerance's number comes from");
  if (g.why.size() < 10) r.fail("why", "expected where the tolerance's number comes from");
  r.finish();
  return g;
}

/// One [[card]].
BenchmarkCard read_card(TableReader& r, const std::string& key, const fs::path& root) {
  BenchmarkCard c;
  const std::string scene = r.string("scene", "a scene file relative to the repository root");
  c.scene = fs::absolute(root / scene).lexically_normal();
  std::error_code ec;
  if (!fs::exists(c.scene, ec))
    r.fail("scene", "expected an existing scene file, " + c.scene.string() + " is not");
  c.set = r.string("set", "paper, hard or exact");
  if (std::find(card_sets().begin(), card_sets().end(), c.set) == card_sets().end())
    r.fail("set", "expected paper, hard or exact, got '" + c.set + "'");
  const toml::node* ref = r.raw("reference");
  if (!ref || !ref->as_table())
    r.fail("reference", "expected { method = NAME } of a reference method (" + reference_names() + ")");
  TableReader rr(*ref->as_table(), r.file(), key + ".reference", nullptr);
  c.reference =
      JobSpec{c.scene,           rr.string("method", "a reference method (" + reference_names() + ")"),
              std::nullopt,      "",
              rr.strings("set"), {}};
  const Method* m = find_method(c.reference.method);
  if (!m || m->as_reference.rank == ReferenceRank::kNone)
    rr.fail("method", "expected a reference method (ranked in the registry: " + reference_names() +
                          "), got '" + c.reference.method + "'");
  rr.finish();
  c.source = r.string("source", "the matrix row the tolerances come from, \"\" when derived");
  if (r.has("note")) c.note = r.string("note", "why a quantity of the scene is not on the card");
  const toml::node* q = r.raw("quantities");
  const toml::array* a = q ? q->as_array() : nullptr;
  if (!a || a->empty()) r.fail("quantities", "expected a non-empty array of { metric, tol, why }");
  for (std::size_t i = 0; i < a->size(); ++i) {
    c.quantities.push_back(read_quantity((*a)[i], r.file(), fmt::format("{}.quantities[{}]", key, i)));
    for (std::size_t j = 0; j < i; ++j)
      if (c.quantities[j].metric == c.quantities[i].metric)
        throw InputError(
            r.file(), fmt::format("{}.quantities[{}]", key, i),
            "expected one tolerance per quantity, '" + c.quantities[i].metric + "' is named twice");
  }
  return c;
}

}  // namespace

const std::vector<std::string>& card_sets() {
  static const std::vector<std::string> s = {"paper", "hard", "exact"};
  return s;
}

std::vector<BenchmarkCard> load_cards(const fs::path& file, const fs::path& root) {
  const std::string f = file.string();
  toml::table doc;
  try {
    doc = toml::parse_file(f);
  } catch (const toml::parse_error& e) {
    throw InputError(f, "", std::string("expected valid TOML: ") + std::string(e.description()));
  }
  TableReader top(doc, f, "", nullptr);
  const toml::node* n = top.raw("card");
  const toml::array* a = n ? n->as_array() : nullptr;
  if (!a || a->empty()) top.fail("card", "expected one or more [[card]] tables");
  std::vector<BenchmarkCard> cards;
  for (std::size_t i = 0; i < a->size(); ++i) {
    const std::string key = fmt::format("card[{}]", i);
    const toml::table* t = (*a)[i].as_table();
    if (!t) throw InputError(f, key, "expected a table");
    TableReader r(*t, f, key, nullptr);
    cards.push_back(read_card(r, key, root));
    r.finish();
    for (std::size_t j = 0; j < i; ++j)
      if (cards[j].scene == cards[i].scene)
        throw InputError(f, key + ".scene",
                         "expected one card per scene, " + cards[i].scene.string() + " has two");
  }
  top.finish();
  return cards;
}

}  // namespace beamimpact::verification
