"""The FEniCSx reference's own options: the scene's optional [fenicsx] table, then CLI overrides.

Keys (all optional; unknown keys are errors):
  mesh            "coarse" | "default" | "fine": elements through the depth 1 | 2 | 4, square elements
  elements_depth  Q2 elements through each body's depth (overrides the preset)
  elements_length Q2 elements along each body: an integer for all bodies or a table {NAME = n}
                  (default: square elements, round(L / (h / elements_depth)))
  poisson         Poisson's ratio of the plane-stress continuum (default 0: beam theory has no
                  lateral contraction, and nu = 0 keeps the axial wave speed sqrt(E/rho) exact)
  fraction        time step as a fraction of the continuum's critical step (default 0.9)
  output_interval s between history rows (default: the scene's dt x output_every; with
                  dt = "auto", every output_every-th continuum step)
"""

from dataclasses import dataclass, field

from scene import InputError

PRESETS = {"coarse": 1, "default": 2, "fine": 4}


@dataclass
class Options:
    """Resolved options; `assumed` lists defaults used ("fenicsx.poisson" -> "0")."""
    mesh: str = "default"
    elements_depth: int = 2
    elements_length: dict = field(default_factory=dict)   # body name -> count (missing: square)
    poisson: float = 0.0
    fraction: float = 0.9
    output_interval: float = None
    end: float = None
    assumed: dict = field(default_factory=dict)


def _int(file, key, v, minimum=1):
    if isinstance(v, bool) or not isinstance(v, int) or v < minimum:
        raise InputError(file, key, f"expected an integer >= {minimum}, found {v!r}")
    return v


def _num(file, key, v, lo, hi, what):
    if isinstance(v, bool) or not isinstance(v, (int, float)) or not lo(v) or not hi(v):
        raise InputError(file, key, f"expected {what}, found {v!r}")
    return float(v)


def resolve_options(scene, cli):
    """Merges scene.fenicsx with CLI overrides (dict of key -> value, None = not given)."""
    file, table = scene.file, dict(scene.fenicsx)
    known = {"mesh", "elements_depth", "elements_length", "poisson", "fraction", "output_interval"}
    for k in table:
        if k not in known:
            raise InputError(file, f"fenicsx.{k}", "unknown key; expected one of " + ", ".join(sorted(known)))
    src = {k: ("--" + k.replace("_", "-"), v) for k, v in cli.items() if v is not None}
    for k, v in table.items():
        src.setdefault(k, (f"fenicsx.{k}", v))
    o = Options()
    names = [b.name for b in scene.bodies]

    def get(k, default):
        if k in src:
            return src[k]
        o.assumed[f"fenicsx.{k}"] = str(default)
        return None

    if (g := get("mesh", "default")):
        key, v = g
        if v not in PRESETS:
            raise InputError(file, key, f"expected one of {', '.join(PRESETS)}, found {v!r}")
        o.mesh = v
    o.elements_depth = PRESETS[o.mesh]
    if (g := get("elements_depth", o.elements_depth)):
        o.elements_depth = _int(file, g[0], g[1])
    if (g := get("elements_length", "square elements")):
        key, v = g
        if isinstance(v, dict):
            for n, c in v.items():
                if n not in names:
                    raise InputError(file, f"{key}.{n}", f"expected a body name ({', '.join(names)})")
                o.elements_length[n] = _int(file, f"{key}.{n}", c)
        else:
            for n in names:
                o.elements_length[n] = _int(file, key, v)
    if (g := get("poisson", 0.0)):
        o.poisson = _num(file, g[0], g[1], lambda x: x >= 0, lambda x: x < 0.5, "a number in [0, 0.5)")
    if (g := get("fraction", 0.9)):
        o.fraction = _num(file, g[0], g[1], lambda x: x > 0, lambda x: x <= 1, "a number in (0, 1]")
    default_out = "dt x output_every" if scene.dt else "every output_every-th step"
    if (g := get("output_interval", default_out)):
        o.output_interval = _num(file, g[0], g[1], lambda x: x > 0, lambda x: True, "a positive time (s)")
    elif scene.dt:
        o.output_interval = scene.dt * scene.output_every
    if "end" in cli and cli["end"] is not None:
        o.end = _num(file, "--end", cli["end"], lambda x: x > 0, lambda x: True, "a positive time (s)")
    return o
