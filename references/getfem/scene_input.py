"""Reads a beamimpact scene file (docs/scene-format.md) for the GetFEM reference, with Python's
tomllib: its own reader, sharing nothing with the C++ loader but the file format. It takes what
this reference models (straight Euler-Bernoulli beams or rods, linear kinematics, frictionless
node-to-point penalty contact, supports on the body's own axes, immovable rigid obstacles,
Rayleigh damping) and raises Refused (exit 2, one line) for anything else, naming the key.
SI units throughout."""

import hashlib
import math
import tomllib
from dataclasses import dataclass, field

# Tables of other methods' options ([paper], [ida], [siconos], ...): read by those methods only.
_SCENE_KEYS = {"name", "description", "time", "model", "bodies", "contacts", "effects", "output", "loads"}


class Refused(Exception):
    """A scene this reference cannot run or a bad scene: one line naming file, key and why."""

    def __init__(self, file, key, why):
        super().__init__(f"getfem: {file}" + (f": {key}" if key else "") + f": {why}")


@dataclass
class Support:
    node: int     # node index along the body, 0 .. elements
    axial: bool   # the body's own axial displacement held
    normal: bool  # the body's own normal displacement held
    theta: bool   # the rotation held


@dataclass
class Body:
    name: str
    start: tuple   # m
    end: tuple     # m
    elements: int
    E: float       # N/m^2
    rho: float     # kg/m^3
    area: float    # m^2
    inertia: float  # m^4, 0 for a rod
    velocity: tuple  # m/s
    rigid: bool = False  # an immovable rigid obstacle (no degrees of freedom)
    supports: list = field(default_factory=list)

    @property
    def length(self):
        return math.dist(self.start, self.end)

    @property
    def axis(self):
        """Unit vector from start to end."""
        return ((self.end[0] - self.start[0]) / self.length, (self.end[1] - self.start[1]) / self.length)


@dataclass
class Contact:
    striker: int
    node: int      # striker node index
    target: int
    key: str


@dataclass
class Scene:
    file: str
    sha256: str
    name: str
    description: str
    dt: float      # s; None for "auto" (fraction x the model's critical step, simulate.py)
    fraction: float
    end: float     # s
    output_every: int
    mass: str      # "lumped" | "consistent"
    rotary_inertia: str  # "hrz" | "section"
    rayleigh: tuple  # (1/s, s)
    bodies: list
    contacts: list
    bending: bool
    options: dict  # the [getfem] table
    assumed: dict


class _Table:
    """One TOML table: typed reads; finish() refuses keys never read."""

    def __init__(self, t, file, prefix):
        if not isinstance(t, dict):
            raise Refused(file, prefix, "expected a table")
        self.t, self.file, self.prefix, self.seen = t, file, prefix, set()

    def key(self, k):
        return f"{self.prefix}.{k}" if self.prefix else k

    def fail(self, k, why):
        raise Refused(self.file, self.key(k), why)

    def get(self, k, default=None):
        self.seen.add(k)
        if k not in self.t and default is None:
            self.fail(k, "missing")
        return self.t.get(k, default)

    def number(self, k, default=None, positive=False):
        v = self.get(k, default)
        if isinstance(v, bool) or not isinstance(v, (int, float)) or not math.isfinite(v):
            self.fail(k, f"expected a number, found {v!r}")
        if (positive and v <= 0) or v < 0:
            self.fail(k, f"expected a number {'>' if positive else '>='} 0, found {v!r}")
        return float(v)

    def vec2(self, k, default=None):
        v = self.get(k, default)
        if not (isinstance(v, list) and len(v) == 2 and all(
                isinstance(x, (int, float)) and not isinstance(x, bool) and math.isfinite(x) for x in v)):
            self.fail(k, f"expected [x, y], found {v!r}")
        return (float(v[0]), float(v[1]))

    def choice(self, k, default, allowed, why_not=""):
        v = self.get(k, default)
        if v not in allowed:
            self.fail(k, f"{v!r}: " + (why_not or f"expected one of {', '.join(map(repr, allowed))}"))
        return v

    def finish(self):
        for k in self.t:
            if k not in self.seen:
                self.fail(k, "unknown key or one this reference does not model")


def _node(tb, k, body, default=None):
    v = tb.get(k, default)
    if v == "start":
        return 0
    if v == "end":
        return body.elements
    if isinstance(v, int) and not isinstance(v, bool) and 0 <= v <= body.elements:
        return v
    tb.fail(k, f'expected "start", "end" or a node index 0..{body.elements}, found {v!r}')


def _supports(tb, body):
    raw = tb.get("supports", [])
    if not isinstance(raw, list):
        tb.fail("supports", "expected an array of { at = ..., fix = [...] }")
    ex, ey = body.axis
    for j, sraw in enumerate(raw):
        s = _Table(sraw, tb.file, tb.key(f"supports[{j}]"))
        node = _node(s, "at", body)
        fix = s.get("fix")
        if not isinstance(fix, list) or not fix or any(f not in ("x", "y", "theta", "axial", "normal") for f in fix):
            s.fail("fix", f'expected a non-empty array of "x", "y", "theta", "axial", "normal", found {fix!r}')
        s.finish()
        axial, normal = "axial" in fix, "normal" in fix
        gx, gy = "x" in fix, "y" in fix
        if gx and gy:
            axial = normal = True
        elif gx or gy:  # one global direction: along the body's axis or its normal only
            along = abs(ex) if gx else abs(ey)
            if along > 1 - 1e-12:
                axial = True
            elif along < 1e-12:
                normal = True
            else:
                s.fail("fix", "a single global direction oblique to the body's axis is not modelled by the "
                              "GetFEM reference (its supports act on the body's axial and normal displacements)")
        body.supports.append(Support(node, axial, normal, "theta" in fix))


def _body(raw, file, i):
    tb = _Table(raw, file, f"bodies[{i}]")
    b = Body(name=tb.get("name"), start=tb.vec2("start"), end=tb.vec2("end"),
             elements=tb.get("elements"), E=tb.number("E", positive=True), rho=tb.number("rho", positive=True),
             area=tb.number("area", positive=True), inertia=tb.number("inertia", 0.0),
             velocity=tb.vec2("velocity", [0.0, 0.0]), rigid=tb.get("rigid", False))
    if not isinstance(b.elements, int) or isinstance(b.elements, bool) or b.elements < 1:
        tb.fail("elements", f"expected a whole number >= 1, found {b.elements!r}")
    if b.length <= 0:
        tb.fail("end", "expected a point different from start")
    tb.choice("theory", "euler-bernoulli", ("euler-bernoulli",),
              "this reference models Euler-Bernoulli beams and rods only (no Timoshenko shear)")
    _supports(tb, b)
    if b.rigid is not False:
        held = len(b.supports) == 1 and b.supports[0].axial and b.supports[0].normal and b.supports[0].theta
        if b.rigid is not True or not held:
            tb.fail("rigid", "this reference models an immovable rigid body only (one support fixing x, y "
                             "and theta): a free rigid body is not modelled")
    tb.finish()
    return b


def _contact(raw, file, i, bodies):
    tb = _Table(raw, file, f"contacts[{i}]")
    names = [b.name for b in bodies]
    striker, target = tb.get("striker"), tb.get("target")
    for k, v in (("striker", striker), ("target", target)):
        if v not in names:
            tb.fail(k, f"expected one of {', '.join(names)}, found {v!r}")
    if striker == target:
        tb.fail("target", "expected a body other than the striker")
    sb = bodies[names.index(striker)]
    if tb.t.get("node") == "all":
        tb.fail("node", '"all": a contact search is not modelled (one striker node against one point)')
    node = _node(tb, "node", sb)
    if tb.number("friction", 0.0) > 0:
        tb.fail("friction", "this reference models frictionless contact only")
    tb.choice("law", "hard", ("hard",), "the Hertz law is not modelled (a linear penalty stands for the hard law)")
    tb.finish()
    if sb.rigid:
        tb.fail("striker", "an immovable rigid body cannot strike")
    return Contact(names.index(striker), node, names.index(target), tb.prefix)


def _time(doc, file):
    tb = _Table(doc.get("time"), file, "time")
    fraction = tb.number("fraction", 0.5, positive=True)
    dt = None if tb.get("dt") == "auto" else tb.number("dt", positive=True)
    if dt is not None and "fraction" in tb.t:
        tb.fail("fraction", 'is used only with dt = "auto"')
    end = tb.number("end", positive=True)
    every = tb.get("output_every", 1)
    if not isinstance(every, int) or isinstance(every, bool) or every < 1:
        tb.fail("output_every", f"expected a whole number >= 1, found {every!r}")
    tb.get("allow_above_critical", False)  # an implicit scheme has no critical step
    tb.get("allow_long_run", False)
    tb.finish()
    if dt is not None and dt > end:
        tb.fail("dt", "expected a step no longer than time.end")
    return dt, fraction, end, every


def _collinear(bodies):
    a, e = bodies[0].start, bodies[0].axis
    scale = max(b.length for b in bodies)
    return all(abs((q[0] - a[0]) * e[1] - (q[1] - a[1]) * e[0]) <= 1e-9 * scale
               for b in bodies for q in (b.start, b.end))


def refine(scene, factor):
    """Every body in `factor` times its elements (an element multiplier, 1 .. 64); node indices of
    supports and contacts follow their nodes."""
    for b in scene.bodies:
        if not b.rigid:
            b.elements *= factor
            for sup in b.supports:
                sup.node *= factor
    for c in scene.contacts:
        c.node *= factor
    return scene


def load(path, overrides=None):
    """Reads and checks `path`; `overrides` maps "table.key" to a value (tests and --set)."""
    file = str(path)
    try:
        data = open(path, "rb").read()
        doc = tomllib.loads(data.decode("utf-8"))
    except OSError as e:
        raise Refused(file, "", f"cannot read the scene file ({e.strerror})")
    except (tomllib.TOMLDecodeError, UnicodeDecodeError) as e:
        raise Refused(file, "", f"not valid TOML ({e})")
    for k, v in (overrides or {}).items():
        table, _, key = k.partition(".")
        doc.setdefault(table, {})[key] = v
    top = _Table(doc, file, "")
    top.seen |= set(k for k in doc if k not in _SCENE_KEYS)  # other methods' tables
    name, description = top.get("name"), top.get("description", "")
    dt, fraction, end, every = _time(doc, file)
    top.get("time")
    mt = _Table(top.get("model", {}), file, "model")
    mass = mt.choice("mass", "lumped", ("lumped", "consistent"))
    rotary = mt.choice("rotary_inertia", "hrz", ("hrz", "section"))
    mt.choice("kinematics", "linear", ("linear",),
              "large rotation (corotational) is not modelled: linear kinematics only")
    rayleigh = (mt.number("rayleigh_mass", 0.0), mt.number("rayleigh_stiffness", 0.0))
    mt.finish()
    braw, craw = top.get("bodies", []), top.get("contacts", [])
    if not isinstance(braw, list) or len(braw) < 2:
        top.fail("bodies", "expected at least two [[bodies]] tables")
    bodies = [_body(b, file, i) for i, b in enumerate(braw)]
    if len({b.name for b in bodies}) != len(bodies):
        top.fail("bodies", "expected unique body names")
    if not isinstance(craw, list) or not craw:
        top.fail("contacts", "expected at least one [[contacts]] table")
    contacts = [_contact(c, file, i, bodies) for i, c in enumerate(craw)]
    if top.get("loads", {}):
        top.fail("loads", "loads (gravity, point forces) are not modelled by this reference")
    et = _Table(top.get("effects", {}), file, "effects")
    forced = {k: et.get(k, "unset") for k in ("bending", "friction", "damping")}
    et.finish()
    if forced["damping"] is False:
        rayleigh = (0.0, 0.0)
    bending = forced["bending"] is True or (forced["bending"] != False and not _collinear(bodies))  # noqa: E712
    if not bending and not _collinear(bodies):
        top.fail("effects.bending", "false in a scene whose bodies are not on one line: a rod struck across "
                                    "its axis has no stiffness there")
    for i, b in enumerate(bodies):
        e = b.axis
        if not bending and abs(b.velocity[0] * e[1] - b.velocity[1] * e[0]) > 0:
            top.fail(f"bodies[{i}].velocity", "across the axis in a scene of rods on one line (no transverse field)")
        if bending and not b.rigid and b.inertia <= 0:
            top.fail(f"bodies[{bodies.index(b)}].inertia", "missing: this scene bends (expected I > 0, m^4)")
    ot = _Table(top.get("output", {}), file, "output")
    if ot.get("fields", False):
        ot.fail("fields", "VTK fields are not written by this reference")
    if not ot.get("history", True):
        ot.fail("history", "this reference always writes its history")
    ot.get("field_format", "binary")
    ot.get("field_precision", "single")
    ot.finish()
    options = doc.get("getfem", {})
    if not isinstance(options, dict):
        top.fail("getfem", "expected a table")
    top.get("getfem", {})
    top.finish()
    return Scene(file, hashlib.sha256(data).hexdigest(), name, description, dt, fraction, end, every, mass, rotary,
                 rayleigh, bodies, contacts, bending, options, {})
