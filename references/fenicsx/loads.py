"""The scene's external loads for the FEniCSx reference: reading [loads] (docs/scene-format.md) and
turning it into nodal forces of the Q2 continuum.

  [loads]
  gravity = [gx, gy]             # m/s^2, on every body's mass
  [[loads.point]]
  body = "A"                     # a body name
  node = 3                       # "start", "end" or a beam node index 0..elements
  force = [fx, fy]               # N, global axes, constant

Gravity is the body force rho g per unit volume in the weak form: int rho b g . v dx over every
body (b the thickness). A point force P on beam node k acts in the continuum as a traction
uniformly distributed over the cross-section at that node's axis position s = L k / elements:
on an end node the end face, on an interior node the section line through the body there (a
line load P / h per unit depth). Its consistent nodal forces are int (P / h) N_i dr along that
line; on a line of Q2 nodes (an element edge or the line through mid-edge nodes) the Q2 shape
functions reduce to 1D quadratics, so each stretch of three nodes of length l gets
l/6, 2l/3, l/6 times P / h. The resultant is P on the axis with no moment (the distribution is
symmetric about the axis), which is all a beam's point load is; the continuum differs from it only
within about one depth h of the section (Saint-Venant).
"""

import math
from dataclasses import dataclass, field

import numpy as np

from scene import InputError, _Table


@dataclass
class PointLoad:
    """A constant force (N, global axes) on beam node `node` of body `body` (index), at `s` (m)."""
    body: int
    node: int
    s: float
    force: tuple
    key: str


@dataclass
class Loads:
    """The scene's [loads]: gravity (m/s^2) and point forces."""
    gravity: tuple = (0.0, 0.0)
    point: list = field(default_factory=list)

    def any(self):
        """True when some load is not zero (the scene then pays for a load vector)."""
        return self.gravity != (0.0, 0.0) or bool(self.point)

    def summary(self, bodies, work_final):
        """summary.json's "loads" object, as the paper integrator writes it."""
        return {"gravity": list(self.gravity),
                "point": [{"body": bodies[p.body].name, "node": p.node, "force": list(p.force)}
                          for p in self.point],
                "work_final": work_final,
                "energy_account": "kinetic + strain + dissipated - load_work = energy_initial (history.csv "
                                  "columns; load_work: the work of the constant loads since t = 0)"}


def read_loads(doc, file, bodies):
    """Reads the optional [loads] table of a parsed scene; raises InputError naming the key."""
    if "loads" not in doc:
        return Loads()
    t = _Table(doc["loads"], file, "loads", {})
    loads = Loads()
    if "gravity" in doc["loads"]:
        loads.gravity = _bounded(t, "gravity", "[gx, gy] (m/s^2)")
    pts = t.raw("point", [])
    if not isinstance(pts, list):
        t.fail("point", "expected [[loads.point]] tables { body, node, force = [fx, fy] }")
    names = {b.name: b for b in bodies}
    for i, praw in enumerate(pts):
        p = _Table(praw, file, f"loads.point[{i}]", {})
        name = p.string("body", "the name of a body")
        if name not in names:
            p.fail("body", f"expected one of the bodies ({', '.join(names)}), found {name!r}")
        body = names[name]
        if body.rigid:
            p.fail("body", f"body {name!r} is immovable (a rigid body with a support): a load on it "
                   "does nothing; expected a deformable body")
        node = p.raw("node")
        expected = f'"start", "end" or a node index 0..{body.elements} of body {name!r}'
        if node == "start":
            k = 0
        elif node == "end":
            k = body.elements
        elif isinstance(node, int) and not isinstance(node, bool) and 0 <= node <= body.elements:
            k = node
        else:
            p.fail("node", f"expected {expected}, found {node!r}")
        force = _bounded(p, "force", "[fx, fy] (N)")
        p.finish()
        loads.point.append(PointLoad(body.index, k, body.length * k / body.elements, force, p.prefix))
    t.finish()
    return loads


def _bounded(t, key, what):
    v = t.vec2(key, what)
    if any(abs(x) > 1e30 for x in v):
        t.fail(key, f"expected {what} of magnitude at most 1e30, found {list(v)!r}")
    return v


def section_weights(q, h, file, key, where):
    """Consistent weights (summing to 1) of a uniform line load over a section line whose nodes
    sit at depth coordinates q (sorted, m) spanning [-h/2, h/2] in equal steps, two per Q2
    element (an odd count): l/6, 2l/3, l/6 per element stretch of length l, divided by h."""
    n = len(q)
    if n < 3 or n % 2 == 0 or abs(q[0] + h / 2) > 1e-9 * h or abs(q[-1] - h / 2) > 1e-9 * h:
        raise InputError(file, key, f"the point force's section at {where} is not a line of Q2 nodes "
                         "through the whole depth; expected the node at a multiple of half a Q2 element "
                         "(change fenicsx.elements_length)")
    w = np.zeros(n)
    for e in range(0, n - 1, 2):
        length = q[e + 2] - q[e]
        w[e:e + 3] += np.array([1.0, 4.0, 1.0]) * length / 6.0
    return w / h


def load_vector(scene, cont, loads):
    """Nodal forces (N) on the owned DOFs (2 per node), or None without loads."""
    if not loads.any():
        return None
    F = np.zeros(2 * cont.n_own)
    if loads.gravity != (0.0, 0.0):
        F += cont.body_force(loads.gravity)
    tol = cont.tol
    for p in loads.point:
        r = cont.rects[p.body]
        nodes, x = cont.find_nodes(p.body, lambda s, q, s0=p.s: abs(s - s0) < tol, lambda s, q: q)
        q = r.local(x)[1] if len(x) else np.zeros(0)
        w = section_weights(q, r.h, scene.file, p.key + ".node",
                            f"{p.s:.6g} m along {r.name}")
        mask, loc = cont.owned_local(nodes)
        F[2 * loc] += w[mask] * p.force[0]
        F[2 * loc + 1] += w[mask] * p.force[1]
    if not all(math.isfinite(f) for f in F):
        raise InputError(scene.file, "loads", "the load vector is not finite; expected smaller loads")
    return F
