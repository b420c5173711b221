#include <verification/matrix/cards.hpp>

#include <algorithm>
#include <cmath>

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

/// One { metric, value, uncertainty, why } of a card's `settled`, for a metric the card gates.
SettledValue read_settled(const toml::node& n, const BenchmarkCard& c, const std::string& file,
                          const std::string& key) {
  const toml::table* t = n.as_table();
  if (!t) throw InputError(file, key, "expected { metric = ..., value = ..., uncertainty = ..., why = ... }");
  TableReader r(*t, file, key, nullptr);
  SettledValue v;
  v.metric =
      r.string("metric", "a quantity of the card with a scalar value (impulse, peak_R, contact_start)");
  const bool gated = std::any_of(c.quantities.begin(), c.quantities.end(),
                                 [&](const Gate& g) { return g.metric == v.metric; });
  if (!gated || !settled_metric(v.metric))
    r.fail("metric",
           "expected a quantity of the card with a scalar value (impulse, impulse_2, ..., peak_R, "
           "contact_start, contact_end), got '" +
               v.metric + "'");
  v.value = r.number("value", "the settled value in the quantity's unit (N s, N or s)");
  if (!(std::isfinite(v.value) && v.value != 0.0)) r.fail("value", "expected a finite, non-zero value");
  v.uncertainty = r.number("uncertainty", "the settled value's uncertainty >= 0, same unit");
  if (!(std::isfinite(v.uncertainty) && v.uncertainty >= 0.0))
    r.fail("uncertainty", "expected a finite uncertainty >= 0 in the value's unit");
  v.why = r.string("why", "where the settled value and its uncertainty come from");
  if (v.why.size() < 10) r.fail("why", "expected where the settled value and its uncertainty come from");
  r.finish();
  return v;
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
  c.reference = jobs::JobSpec{c.scene, rr.string("method", "a reference method (" + reference_names() + ")"),
                              std::nullopt, "", rr.strings("set")};
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
  if (const toml::node* sn = r.raw("settled")) {
    const toml::array* sa = sn->as_array();
    if (!sa) r.fail("settled", "expected an array of { metric, value, uncertainty, why }");
    for (std::size_t i = 0; i < sa->size(); ++i) {
      const std::string k = fmt::format("{}.settled[{}]", key, i);
      c.settled.push_back(read_settled((*sa)[i], c, r.file(), k));
      for (std::size_t j = 0; j < i; ++j)
        if (c.settled[j].metric == c.settled[i].metric)
          throw InputError(r.file(), k + ".metric",
                           "expected one settled value per quantity, '" + c.settled[i].metric + "' has two");
    }
  }
  return c;
}

}  // namespace

bool settled_metric(const std::string& metric) {
  if (metric == "peak_R" || metric == "contact_start" || metric == "contact_end" || metric == "impulse")
    return true;
  return metric.rfind("impulse_", 0) == 0 && known_norm(metric);
}

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
