"""Reads and validates a beamimpact scene file (docs/scene-format.md) with Python's tomllib.

Independent of the C++ loader on purpose: the FEniCSx reference shares nothing with the
paper's code but the scene file. Unknown keys are errors, as in the C++ loader; every default
used is recorded in `assumed` so that summary.json can list it. SI units throughout.
"""

import difflib
import hashlib
import math
import tomllib
from dataclasses import dataclass, field


class InputError(Exception):
    """Bad input: names the file, the dotted key and what was expected (exit code 2). The suite's
    one name for bad input, as in the C++ code and the Python module, defined here on its own: the
    reference shares nothing with them but the scene file."""

    def __init__(self, file, key, message):
        self.file, self.key = str(file), key
        super().__init__(f"{file}" + (f": key '{key}'" if key else "") + f": {message}")


FIX_ENTRIES = ("x", "y", "theta", "axial", "normal")


@dataclass
class Support:
    """A support on the body's axis: `s` (m) along the axis from the start; fixed components: global
    x, y, and the body's own axial (start -> end) and normal (axial turned +90 deg) directions."""
    s: float
    fix_x: bool
    fix_y: bool
    key: str
    fix_axial: bool = False
    fix_normal: bool = False


@dataclass
class Body:
    """One straight beam of the scene, as given (the continuum geometry is derived in geometry.py)."""
    name: str
    start: tuple
    end: tuple
    elements: int
    E: float          # N/m^2
    rho: float        # kg/m^3
    area: float       # m^2
    inertia: float    # m^4
    velocity: tuple   # m/s
    supports: list = field(default_factory=list)
    index: int = 0
    rigid: bool = False  # an immovable rigid body: every continuum node held (no free rigid body)

    @property
    def length(self):
        """Axis length (m)."""
        return math.dist(self.start, self.end)


@dataclass
class Contact:
    """A contact pair: striker end ("start"/"end") against the target body; Coulomb mu."""
    striker: int
    end: str
    target: int
    friction: float
    key: str


@dataclass
class Scene:
    """A validated scene. dt is None for "auto"; method_tables holds [paper]/[ida]/... untouched."""
    file: str
    sha256: str
    name: str
    description: str
    dt: float
    fraction: float
    end: float
    output_every: int
    model: dict
    bodies: list
    contacts: list
    effects: dict
    fenicsx: dict
    assumed: dict
    fields: bool = False  # [output] fields: VTK fields (fields.py)
    loads: object = None  # loads.Loads: the [loads] table (gravity, point forces)


_TOP = {"name", "description", "time", "model", "bodies", "contacts", "effects", "output",
        "fenicsx", "paper", "ida", "exact", "loads"}


class _Table:
    """Typed access to one table; remembers keys read so finish() can reject unknown ones."""

    def __init__(self, table, file, prefix, assumed):
        if not isinstance(table, dict):
            raise InputError(file, prefix, "expected a table")
        self.t, self.file, self.prefix, self.assumed, self.seen = table, file, prefix, assumed, set()

    def path(self, key):
        return f"{self.prefix}.{key}" if self.prefix else key

    def fail(self, key, message):
        raise InputError(self.file, self.path(key), message)

    def _get(self, key, default, shown):
        self.seen.add(key)
        if key in self.t:
            return self.t[key], True
        if default is _REQUIRED:
            typo = difflib.get_close_matches(key, [k for k in self.t if isinstance(k, str)], 1, 0.6)
            hint = f" (found '{typo[0]}': a typo?)" if typo else ""
            self.fail(key, "missing; expected " + shown + hint)
        self.assumed[self.path(key)] = str(default)
        return default, False

    def number(self, key, what, default=None, positive=False, nonneg=False):
        v, _ = self._get(key, _REQUIRED if default is None else default, what)
        if isinstance(v, bool) or not isinstance(v, (int, float)) or not math.isfinite(v):
            self.fail(key, f"expected {what}, found {v!r}")
        if positive and v <= 0:
            self.fail(key, f"expected {what} > 0, found {v!r}")
        if nonneg and v < 0:
            self.fail(key, f"expected {what} >= 0, found {v!r}")
        return float(v)

    def integer(self, key, what, default=None, minimum=None):
        v, _ = self._get(key, _REQUIRED if default is None else default, what)
        if isinstance(v, bool) or not isinstance(v, int):
            self.fail(key, f"expected {what} (an integer), found {v!r}")
        if minimum is not None and v < minimum:
            self.fail(key, f"expected {what} >= {minimum}, found {v!r}")
        return v

    def string(self, key, what, default=None, allowed=None):
        v, _ = self._get(key, _REQUIRED if default is None else default, what)
        if not isinstance(v, str):
            self.fail(key, f"expected {what} (a string), found {v!r}")
        if allowed and v not in allowed:
            self.fail(key, f"expected one of {', '.join(allowed)}, found {v!r}")
        return v

    def boolean(self, key, default):
        v, _ = self._get(key, default, "true or false")
        if v is not None and not isinstance(v, bool):
            self.fail(key, f"expected true or false, found {v!r}")
        return v

    def vec2(self, key, what):
        v, _ = self._get(key, _REQUIRED, what)
        if (not isinstance(v, list) or len(v) != 2
                or any(isinstance(x, bool) or not isinstance(x, (int, float)) or not math.isfinite(x)
                       for x in v)):
            self.fail(key, f"expected {what} (an array of two numbers), found {v!r}")
        return (float(v[0]), float(v[1]))

    def raw(self, key, default=None):
        self.seen.add(key)
        return self.t.get(key, default)

    def finish(self):
        for k in self.t:
            if k not in self.seen:
                self.fail(k, "unknown key (a typo must not fall back to a default)")


_REQUIRED = object()


def load_scene(path, overrides=None):
    """Reads `path` and validates it; `overrides` maps dotted keys ("time.end") to values."""
    file = str(path)
    try:
        with open(path, "rb") as f:
            data = f.read()
    except OSError as e:
        raise InputError(file, "", f"cannot read the scene file ({e.strerror})")
    try:
        doc = tomllib.loads(data.decode("utf-8"))
    except (tomllib.TOMLDecodeError, UnicodeDecodeError) as e:
        raise InputError(file, "", f"not valid TOML ({e})")
    for k, v in (overrides or {}).items():
        table, _, key = k.partition(".")
        doc.setdefault(table, {})[key] = v
    assumed = {}
    for k in doc:
        if k not in _TOP:
            raise InputError(file, k, "unknown key (a typo must not fall back to a default)")
    name = doc.get("name")
    if not isinstance(name, str) or not name:
        raise InputError(file, "name", "missing; expected the scene's name (a string)")
    description = doc.get("description", "")
    if not isinstance(description, str):
        raise InputError(file, "description", "expected a string")

    if "time" not in doc:
        raise InputError(file, "time", "missing; expected a [time] table")
    t = _Table(doc["time"], file, "time", assumed)
    dt_raw = t.raw("dt")
    if dt_raw is None:
        t.fail("dt", 'missing; expected a time step in s or "auto"')
    if dt_raw == "auto":
        dt = None
    elif isinstance(dt_raw, (int, float)) and not isinstance(dt_raw, bool) and dt_raw > 0:
        dt = float(dt_raw)
    else:
        t.fail("dt", f'expected a positive number (s) or "auto", found {dt_raw!r}')
    fraction = t.number("fraction", "a fraction of the critical step", 0.5, positive=True)
    end = t.number("end", "the end time (s)", positive=True)
    output_every = t.integer("output_every", "write every n-th step", 1, minimum=1)
    t.boolean("allow_above_critical", False)   # the continuum always picks its own stable step
    t.boolean("allow_long_run", False)         # the cost guard is the C++ CLI's (solver/scene/run_cost.hpp)
    t.finish()

    m = _Table(doc.get("model", {}), file, "model", assumed)
    model = {
        "mass": m.string("mass", "the mass kind", "lumped", ["lumped", "consistent"]),
        "rotary_inertia": m.string("rotary_inertia", "the rotary inertia", "hrz", ["hrz", "section"]),
        "kinematics": m.string("kinematics", "the kinematics", "linear", ["linear", "corotational"]),
        "rayleigh_mass": m.number("rayleigh_mass", "a damping coefficient (1/s)", 0.0, nonneg=True),
        "rayleigh_stiffness": m.number("rayleigh_stiffness", "a damping coefficient (s)", 0.0, nonneg=True),
    }
    m.finish()
    if model["rayleigh_mass"] or model["rayleigh_stiffness"]:
        raise InputError(file, "model.rayleigh_mass", "Rayleigh damping cannot be modelled by the "
                         "FEniCSx reference; expected 0 (an undamped scene)")

    bodies_raw = doc.get("bodies")
    if not isinstance(bodies_raw, list) or len(bodies_raw) < 2:
        raise InputError(file, "bodies", "expected an array of at least two [[bodies]] tables")
    bodies = []
    for i, braw in enumerate(bodies_raw):
        b = _Table(braw, file, f"bodies[{i}]", assumed)
        body = Body(
            name=b.string("name", "the body's name"),
            start=b.vec2("start", "the first node (m)"), end=b.vec2("end", "the last node (m)"),
            elements=b.integer("elements", "the beam element count", minimum=1),
            E=b.number("E", "Young's modulus (N/m^2)", positive=True),
            rho=b.number("rho", "the density (kg/m^3)", positive=True),
            area=b.number("area", "the cross-section area (m^2)", positive=True),
            inertia=b.number("inertia", "the second moment of area (m^4)", 0.0, nonneg=True),
            velocity=(b.vec2("velocity", "the initial velocity (m/s)") if "velocity" in braw
                      else _default_vec(b, "velocity")),
            index=i)
        if body.length <= 0:
            b.fail("end", "expected a point different from start (a body of positive length)")
        body.rigid = _rigid(b)
        if b.raw("theory", "euler-bernoulli") != "euler-bernoulli":
            b.fail("theory", "the plane-stress continuum is compared with Euler-Bernoulli beams only "
                   "(theory = \"timoshenko\" is run by the paper method and ida); expected "
                   "\"euler-bernoulli\" or no theory")
        sup_raw = b.raw("supports", [])
        if not isinstance(sup_raw, list):
            b.fail("supports", "expected an array of { at = ..., fix = [...] } tables")
        if body.rigid:
            _immovable(b, sup_raw, assumed)
            sup_raw = []   # held as a whole: no support nodes of its own
        for j, sraw in enumerate(sup_raw):
            s = _Table(sraw, file, f"bodies[{i}].supports[{j}]", assumed)
            at = s.raw("at")
            if at == "start":
                pos = 0.0
            elif at == "end":
                pos = body.length
            elif isinstance(at, int) and not isinstance(at, bool) and 0 <= at <= body.elements:
                pos = body.length * at / body.elements
            else:
                s.fail("at", f'expected "start", "end" or a node index 0..{body.elements}, found {at!r}')
            fix = s.raw("fix")
            if not isinstance(fix, list) or not fix or any(f not in FIX_ENTRIES for f in fix):
                s.fail("fix", f'expected a non-empty array of "x", "y", "theta", "axial", "normal", found {fix!r}')
            if "theta" in fix:
                s.fail("fix", "a rotation support cannot be modelled by the plane-stress continuum "
                       "(supports act on the axis node); expected only \"x\", \"y\", \"axial\", \"normal\"")
            s.finish()
            body.supports.append(Support(pos, "x" in fix, "y" in fix, s.prefix, "axial" in fix, "normal" in fix))
        b.finish()
        if any(o.name == body.name for o in bodies):
            b.fail("name", f"expected a unique body name, {body.name!r} is used twice")
        bodies.append(body)

    from loads import read_loads   # here: loads.py builds on this module's table reader
    loads = read_loads(doc, file, bodies)

    contacts_raw = doc.get("contacts")
    if not isinstance(contacts_raw, list) or not contacts_raw:
        raise InputError(file, "contacts", "expected an array of at least one [[contacts]] table")
    names = {bd.name: bd.index for bd in bodies}
    contacts = []
    for i, craw in enumerate(contacts_raw):
        c = _Table(craw, file, f"contacts[{i}]", assumed)
        striker = c.string("striker", "the striker body's name")
        target = c.string("target", "the target body's name")
        for key, nm in (("striker", striker), ("target", target)):
            if nm not in names:
                c.fail(key, f"expected one of the bodies ({', '.join(names)}), found {nm!r}")
        if striker == target:
            c.fail("target", "expected a body other than the striker")
        node = c.raw("node")
        if node == "all":
            c.fail("node", 'node = "all" (contact search) is run by the paper method only; the continuum '
                   'models the striker\'s end face: expected "start" or "end"')
        nel = bodies[names[striker]].elements
        if node in ("start", 0):
            end_name = "start"
        elif node == "end" or (isinstance(node, int) and not isinstance(node, bool) and node == nel):
            end_name = "end"
        elif isinstance(node, int) and not isinstance(node, bool) and 0 < node < nel:
            c.fail("node", "an interior striker node cannot be modelled by the continuum (its "
                   "contact face is an end face); expected \"start\" or \"end\"")
        else:
            c.fail("node", f'expected "start", "end" or a node index 0..{nel}, found {node!r}')
        mu = c.number("friction", "the Coulomb coefficient", 0.0, nonneg=True)
        if c.raw("law", "hard") != "hard":
            c.fail("law", "the continuum's contact is its own (hard, between the faces); law = \"hertz\" "
                   "is run by the paper method and ida: expected \"hard\" or no law")
        c.finish()
        contacts.append(Contact(names[striker], end_name, names[target], mu, c.prefix))
    strikers = [c.striker for c in contacts]
    for c in contacts:
        if strikers.count(c.striker) > 1 or c.striker in [d.target for d in contacts]:
            raise InputError(file, c.key + ".striker", "the FEniCSx reference models one contact per "
                             "striker and a striker that is nobody's target; expected that")

    e = _Table(doc.get("effects", {}), file, "effects", {})
    effects = {k: e.boolean(k, None) for k in ("bending", "friction", "damping")}
    e.finish()
    _check_rods(file, bodies, effects, assumed)
    _check_rod_loads(file, bodies, loads)
    for c in contacts:
        if bodies[c.striker].rigid:
            raise InputError(file, c.key + ".striker", "the striker is an immovable rigid body and "
                             "cannot strike; expected a deformable striker (the rigid body as the target)")
    if effects["damping"]:
        raise InputError(file, "effects.damping", "damping cannot be modelled by the FEniCSx reference")
    if effects["friction"] is False:
        for c in contacts:
            c.friction = 0.0
    for tbl in ("paper", "ida", "exact"):
        if tbl in doc and not isinstance(doc[tbl], dict):
            raise InputError(file, tbl, "expected a table")
    o = _Table(doc.get("output", {}), file, "output", assumed)
    fields = o.boolean("fields", False)
    # The beam methods' encoding and precision choices; dolfinx's VTKFile writes the continuum's
    # files in its own encoding and precision whichever is asked (ParaView reads both).
    o.string("field_format", "binary or ascii", default="binary", allowed=("binary", "ascii"))
    o.string("field_precision", "single or double", default="single", allowed=("single", "double"))
    if not o.boolean("history", True):
        o.fail("history", "the FEniCSx reference keeps its history rows (its summary is made from "
                          "them); expected true")
    o.finish()
    fen = doc.get("fenicsx", {})
    if not isinstance(fen, dict):
        raise InputError(file, "fenicsx", "expected a table")

    return Scene(file=file, sha256=hashlib.sha256(data).hexdigest(), name=name,
                 description=description, dt=dt, fraction=fraction, end=end,
                 output_every=output_every, model=model, bodies=bodies, contacts=contacts,
                 effects=effects, fenicsx=fen, assumed=assumed, fields=fields, loads=loads)


def _rigid(b):
    """The body's `rigid` flag (false when absent; not listed in assumed, as the C++ reader)."""
    rigid = b.raw("rigid", False)
    if not isinstance(rigid, bool):
        b.fail("rigid", f"expected true or false, found {rigid!r}")
    return rigid


def _immovable(b, sup_raw, assumed):
    """A rigid body must be immovable: one support fixing x, y and theta (the continuum holds
    every node of it); a free rigid body is refused."""
    fix = None
    if len(sup_raw) == 1 and isinstance(sup_raw[0], dict):
        s = _Table(sup_raw[0], b.file, b.path("supports[0]"), assumed)
        s.raw("at")
        fix = s.raw("fix")
        s.finish()
    if not isinstance(fix, list) or sorted(fix) != ["theta", "x", "y"]:
        b.fail("supports", "the continuum models an immovable rigid body only (every node held); "
               "a free rigid body is run by the beam methods: expected one support fixing "
               "\"x\", \"y\" and \"theta\"")


def _check_rods(file, bodies, effects, assumed):
    """A deformable body without `inertia` is a rod: accepted when the scene is one of rods (all
    bodies on one line, bending not forced on), with the continuum depth sqrt(A) (a square
    section; with Poisson 0 the axial response does not depend on it). Rigid bodies need no I."""
    rods = [bd for bd in bodies if bd.inertia <= 0]
    if not rods:
        return
    p0 = bodies[0].start
    e = ((bodies[0].end[0] - p0[0]) / bodies[0].length, (bodies[0].end[1] - p0[1]) / bodies[0].length)
    scale = max(bd.length for bd in bodies)
    on_line = all(abs((q[0] - p0[0]) * e[1] - (q[1] - p0[1]) * e[0]) <= 1e-9 * scale
                  for bd in bodies for q in (bd.start, bd.end))
    for bd in rods:
        if bd.rigid:
            continue
        if not on_line or effects["bending"]:
            raise InputError(file, f"bodies[{bd.index}].inertia", "missing; expected a positive second "
                             "moment of area (m^4): this scene bends, and the continuum's depth is "
                             "sqrt(12 I / A)")
    for bd in rods:
        assumed[f"fenicsx.depth.{bd.name}"] = (
            "sqrt(area) (no inertia: a square section; " +
            ("an immovable rigid body, held at every node)" if bd.rigid else
             "rods on one line, so the axial response does not depend on it)"))


def _check_rod_loads(file, bodies, loads):
    """In a scene of rods (a deformable body without I) a load across the axis would bend the
    continuum's square section, a stiffness the scene does not give: refused, as the beam
    methods' rod model refuses it."""
    if not any(bd.inertia <= 0 and not bd.rigid for bd in bodies):
        return
    b0 = bodies[0]
    e = ((b0.end[0] - b0.start[0]) / b0.length, (b0.end[1] - b0.start[1]) / b0.length)
    for key, a in [("loads.gravity", loads.gravity)] + [(p.key + ".force", p.force) for p in loads.point]:
        if abs(a[0] * e[1] - a[1] * e[0]) > 1e-12 * math.hypot(*a):
            raise InputError(file, key, f"this scene is of rods along ({e[0]:.6g}, {e[1]:.6g}) (a body "
                             f"without inertia), and the load ({a[0]:.6g}, {a[1]:.6g}) has a component "
                             "across that axis; expected a load along the axis, or give every body "
                             "its inertia")


def _default_vec(b, key):
    b.seen.add(key)
    b.assumed[b.path(key)] = "[0, 0]"
    return (0.0, 0.0)

