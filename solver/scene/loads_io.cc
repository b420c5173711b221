#include <solver/scene/loads_io.hpp>

#include <cmath>
#include <string>

namespace beamimpact {
namespace {

/// Loads of magnitude above this are refused (as the scene's other magnitudes: products with
/// masses and displacements must stay finite).
constexpr double kLargest = 1e30;

Vec2 bounded_vec2(TableReader& r, const std::string& key, const std::string& what) {
  const Vec2 v = r.vec2(key, what);
  for (double x : v)
    if (!(std::abs(x) <= kLargest)) r.fail(key, "expected " + what + " of magnitude at most 1e30");
  return v;
}

int load_node(TableReader& r, const Body& body) {
  const std::string expected = "\"start\", \"end\" or a node index 0.." + std::to_string(body.elements) +
                               " of body '" + body.name + "'";
  const toml::node* n = r.raw("node");
  if (!n) r.fail("node", "missing; expected " + expected);
  if (auto s = n->as_string()) {
    if (s->get() == "start") return 0;
    if (s->get() == "end") return body.elements;
  } else if (auto i = n->as_integer(); i && i->get() >= 0 && i->get() <= body.elements) {
    return static_cast<int>(i->get());
  }
  r.fail("node", "expected " + expected);
}

PointLoad read_point(TableReader& r, const Scene& sc) {
  PointLoad p;
  const std::string name = r.string("body", "the name of a body");
  p.body = sc.body_index(name);
  if (p.body < 0) r.fail("body", "expected the name of a body, got '" + name + "'");
  p.node = load_node(r, sc.bodies[p.body]);
  p.force = bounded_vec2(r, "force", "[fx, fy] (N)");
  if (sc.bodies[p.body].rigid && sc.bodies[p.body].supports.size() == 1)
    r.fail("body",
           "body '" + name + "' is immovable (a rigid body with a support): a load on it does nothing");
  r.finish();
  return p;
}

}  // namespace

void read_loads(TableReader& top, Scene& sc) {
  const toml::node* n = top.raw("loads");
  if (!n) return;
  if (!n->as_table()) top.fail("loads", "expected a table [loads]");
  TableReader r(*n->as_table(), top.file(), "loads", nullptr);
  if (r.has("gravity")) sc.loads.gravity = bounded_vec2(r, "gravity", "[gx, gy] (m/s^2)");
  if (const toml::node* pn = r.raw("point")) {
    const toml::array* arr = pn->as_array();
    if (!arr) r.fail("point", "expected [[loads.point]] tables { body, node, force = [fx, fy] }");
    for (std::size_t i = 0; i < arr->size(); ++i) {
      const std::string key = "point[" + std::to_string(i) + "]";
      if (!arr->get(i)->as_table()) r.fail(key, "expected a table { body, node, force = [fx, fy] }");
      TableReader pr(*arr->get(i)->as_table(), top.file(), r.path(key), nullptr);
      sc.loads.point.push_back(read_point(pr, sc));
    }
  }
  r.finish();
}

}  // namespace beamimpact
