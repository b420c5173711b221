"""One run: the GetFEM model, its contact pairs and the Newmark stepping, sampled into history rows
(the protocol's columns, SI units) and the summary's entries."""

import numpy as np
import scipy.linalg
import scipy.sparse.linalg as spla

from assembly import GlobalModel
from contact import build_pairs
from newmark import Stepper

CLOSED, OPEN = 3, 0  # column `state`: 3 closed without friction, 0 open


class _Sampler:
    """Energies, momentum and contact columns of a state (u, v on every DOF)."""

    def __init__(self, model, pairs):
        self.model, self.pairs = model, pairs
        self.e0 = None

    def row(self, t, u, v, lam):
        """One history row (history_columns' order) at time t (s) with contact forces lam (N)."""
        m = self.model
        kinetic, strain = 0.5 * v @ (m.M @ v), 0.5 * u @ (m.K @ u)
        penalty = sum(0.5 * l * l / p.kn for p, l in zip(self.pairs, lam))
        if self.e0 is None:
            self.e0 = kinetic + strain + penalty
        line = [t]
        for p, l in zip(self.pairs, lam):
            ua, ub, va, vb = p.Pa @ u, p.Pb @ u, p.Pa @ v, p.Pb @ v
            gap = p.g0 + p.G @ u
            line += [l, 0.0, gap, ua[0], ua[1], va[0], va[1], ub[0], ub[1], vb[0], vb[1], CLOSED if l > 0 else OPEN]
        momentum, _ = m.momentum(v)
        # dissipated: what the account misses (Rayleigh damping, the penalty's switching); the
        # penalty spring's energy is stored, not dissipated.
        dissipated = self.e0 - kinetic - strain - penalty
        return line + [kinetic, strain, dissipated, 0.0, momentum[0], momentum[1]]


def critical_dt(model):
    """s, 2 / omega_max of the free DOFs' K q = omega^2 M q (GetFEM's M and K, before any mass
    redistribution): the explicit step that `dt = "auto"` takes a fraction of."""
    f = model.free
    K, M = model.K[f][:, f].tocsc(), model.M[f][:, f].tocsc()
    if K.shape[0] < 3:
        w2 = np.max(np.real(scipy.linalg.eigvals(K.toarray(), M.toarray())))
    else:
        w2 = spla.eigsh(K, k=1, M=M, which='LM', return_eigenvectors=False)[0]
    return 2.0 / np.sqrt(w2)


def time_grid(scene, model):
    """(dt, steps, critical dt): the scene's step, or for "auto" the fraction of the critical step
    shortened to a whole number of steps to time.end."""
    crit = critical_dt(model)
    if scene.dt is not None:
        return scene.dt, int(round(scene.end / scene.dt)), crit
    steps = int(np.ceil(scene.end / (scene.fraction * crit) - 1e-9))
    return scene.end / steps, steps, crit


def simulate(scene, opts, make_stats):
    """Runs the scene; returns (history rows, summary without the timing keys). make_stats(dt)
    gives one contact-statistics object per contact."""
    model = GlobalModel(scene, opts.mass)
    dt, steps, crit = time_grid(scene, model)
    stats = [make_stats(dt) for _ in scene.contacts]
    pairs = build_pairs(scene, model, opts.penalty, opts.redistribute)
    f = model.free
    stepper = Stepper(model, pairs, dt, opts, scene.rayleigh)
    u, v = np.zeros(model.n), model.initial_velocity()
    uf, vf = u[f].copy(), v[f].copy()
    af = stepper.initial_acceleration(uf, vf)
    sampler = _Sampler(model, pairs)
    lam = np.zeros(len(pairs))
    first = sampler.row(0.0, u, v, lam)
    rows, peak_pen = [first], 0.0
    for k in range(1, steps + 1):
        uf, vf, af, lam = stepper.step(uf, vf, af)
        u[f], v[f] = uf, vf
        t = k * dt
        for s, l in zip(stats, lam):
            s.add(t, float(l), 0.0, dt, "frictionless" if l > 0 else "open")
        peak_pen = max([peak_pen] + [-(p.g0 + p.G @ u) for p in pairs])
        if k % scene.output_every == 0 or k == steps:
            rows.append(sampler.row(t, u, v, lam))
    _, vcm = model.momentum(v)
    summary = _summary(scene, opts, model, pairs, stats, steps, first, rows[-1], vcm, peak_pen)
    summary.update({"dt": dt, "end_time": steps * dt, "critical_dt": crit})
    return rows, summary


def _version():
    """The installed GetFEM (python-getfem carries no version string: Debian's package version)."""
    try:
        from importlib.metadata import version
        return f"getfem {version('getfem')}"
    except Exception:  # noqa: BLE001 -- Debian installs no distribution metadata
        return "getfem 5.4 (Debian python3-getfem)"


def _summary(scene, opts, model, pairs, stats, steps, first, last, vcm, peak_pen):
    contacts = []
    for p, s in zip(pairs, stats):
        entry = {"striker": p.striker, "target": p.target, "kind": p.kind, "friction": 0.0,
                 "penalty_kn": p.kn, "struck_point_s": p.s_struck, **s.summary()}
        entry["impacts"] = len(entry["intervals"])
        contacts.append(entry)
    effects = ["axial"] + (["bending"] if scene.bending else []) + (
        ["damping"] if any(scene.rayleigh) else []) + (["rigid"] if any(b.rigid for b in scene.bodies) else [])
    return {
        "scene": scene.name, "scene_file": scene.file, "scene_sha256": scene.sha256,
        "description": scene.description, "method": "getfem", "version": _version(),
        "steps": steps,
        "effects": effects,
        "assumed": {
            "getfem.elements": "FEM_PK(1,1) axial" + (", FEM_HERMITE(1) transverse (Euler-Bernoulli)" if scene.bending
                                                      else "; no transverse field (rods on one line)"),
            "getfem.mass": ("axial: Gauss-Lobatto lumped" if opts.mass == "lumped" else
                            f"axial: consistent (GetFEM's; the scene's model.mass = {scene.mass!r} is not followed, "
                            "option mass)") + (
                "; transverse: consistent Hermite (GetFEM lumps no Hermite field)" if scene.bending else ""),
            "getfem.newmark": f"beta {opts.beta}, gamma {opts.gamma}",
            "getfem.contact": f"linear penalty at the striker node, kn = {opts.penalty} E A / h; "
                              "contact point and normal fixed at t = 0",
        },
        "energy_initial": first[-6] + first[-5], "energy_final": last[-6] + last[-5],
        "max_penetration": peak_pen,
        "massless_dofs": len(model.massless),
        "bodies": {name: {"final_velocity": vel} for name, vel in vcm.items()},
        "contacts": contacts,
        "units": {"t": "s", "R": "N", "tau": "N", "gap": "m", "u": "m", "v": "m/s", "energy": "J",
                  "momentum": "N s", "impulse": "N s"},
        "getfem": {"mass": opts.mass, "beta": opts.beta, "gamma": opts.gamma, "penalty": opts.penalty,
                   "integrator": "Newmark on the GWFL-assembled M, K (implicit)",
                   "contact_sampling": "every step: the penalty force at the step's end"},
        "complete": True,
    }
