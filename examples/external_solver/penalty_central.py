#!/usr/bin/python3
"""A minimal outside solver for beamimpact: copy it to plug your own code into the suite.

Gets the scene's semi-discrete model from `beamimpact model` (M, K, C, F, initial state, contact
rows), steps it by central differences with penalty contact (R = k_p (-gap) - c_p gap_rate >= 0
while gap < 0; k_p = PENALTY x the stiffest EA/le at the contact, c_p critical for the contact
points' reduced mass; no friction) and writes history.csv and summary.json (docs/protocol.md).
Usage: penalty_central.py SCENE --out DIR --beamimpact PROGRAM [--dt S] [--mesh M] [--quiet]
Exit: 0 done, 2 refused or bad input (one line on stderr), 3 failed. Needs numpy and scipy."""
import argparse, json, os, subprocess, sys, tempfile, time
import numpy as np, scipy.io, scipy.sparse.linalg

PENALTY = 10.0  # k_p over EA/le: the penalty's gap error is R / k_p


def refuse(why): print(f"error: {why}", file=sys.stderr), sys.exit(2)  # the protocol's "refused"


def load_model(args, folder):
    cmd = [args.beamimpact, "model", args.scene, "--out", folder, "--quiet"]
    cmd += ["--set", f"time.dt={args.dt}"] if args.dt else []
    cmd += ["--mesh-factor", args.mesh] if args.mesh else []
    r = subprocess.run(cmd, capture_output=True, text=True)
    if r.returncode == 2: refuse((r.stderr.strip().splitlines() or ["bad scene"])[-1].removeprefix("error: "))
    if r.returncode != 0: raise RuntimeError(f"beamimpact model failed: {r.stderr.strip()}")
    m = json.load(open(os.path.join(folder, "model.json")))
    f = lambda k: os.path.join(folder, m["files"][k]["path"])  # model.json names every file
    mat, col = lambda k: scipy.io.mmread(f(k)).tocsr(), lambda k: np.loadtxt(f(k), delimiter=",", skiprows=1, ndmin=2)
    return m, mat("M"), mat("K"), mat("C"), col("initial_state"), col("load")[:, 1], col("momentum")


class Stats:  # intervals, impulse and peaks of one contact by the suite's rule (R > 0: in contact)
    def __init__(self, merge_gap): self.merge, self.iv, self.on, self.imp, self.peak = merge_gap, [], False, 0.0, 0.0

    def add(self, t, R, dt):  # a phase beginning within the merge gap of the last interval joins it
        self.imp, self.peak = self.imp + R * dt, max(self.peak, R)
        if R > 0 and not self.on and not (self.iv and t - self.iv[-1][1] < self.merge): self.iv.append([t, t, 0.0, R])
        elif R > 0 and self.on: self.iv[-1][2] = max(self.iv[-1][2], R)  # a (re-)closure is no peak after it
        if R > 0: self.iv[-1][1] = t
        self.on = R > 0

    def summary(self, c, k):
        return {"striker": c["striker"], "target": c["target"], "kind": c["kind"], "friction": 0.0,
                "intervals": [i[:2] for i in self.iv], "impacts": len(self.iv), "merge_rule":
                "contact phases separated by fewer than 3 open steps are merged; R > 0 is contact",
                "impulse_normal": self.imp, "impulse_tangential": 0.0, "peak_R": self.peak,
                "peak_R_excluding_closure": max([i[2] for i in self.iv], default=0.0),
                "first_step_R": self.iv[0][3] if self.iv else 0.0, "stick_steps": 0, "slip_steps": 0, "k_p": k}


def solve(m, M, K, C, state, F, P):
    n, contacts = M.shape[0], m["contacts"]
    Minv = scipy.sparse.linalg.factorized(M.tocsc())
    dense = lambda terms: np.bincount(np.array([e for e, _ in terms], dtype=int), [w for _, w in terms], n)
    rows = [{key: dense(terms) for key, terms in c["rows"].items()} for c in contacts]
    kp = [PENALTY * max([b["E"] * b["area"] * b["elements"] / b["length"] for b in m["bodies"]
                         if b["name"] in (c["striker"], c["target"]) and not b["rigid"]] or [1.0]) for c in contacts]
    # The stable step with the penalty springs added (Weyl: their omega^2 adds to the model's).
    w2 = (2.0 / m["time"]["critical_dt"]) ** 2 if m["time"]["critical_dt"] else 0.0
    w2 += sum(k * r["normal"] @ Minv(r["normal"]) for k, r in zip(kp, rows))
    dt, every = m["time"]["dt"], m["time"]["output_every"]
    sub = max(1, int(np.ceil(dt * np.sqrt(w2) / 0.5)))  # h c_p / m_red <= 1: the damper never reverses
    h, steps = dt / sub, int(round(m["time"]["end"] / dt))
    u, v = state[:, 1].copy(), state[:, 2].copy()
    cp = [2.0 * np.sqrt(k / (r["normal"] @ Minv(r["normal"]))) for k, r in zip(kp, rows)]  # critical damping
    def force(u, v):
        gaps = [c["g0"] + r["normal"] @ u for c, r in zip(contacts, rows)]
        return np.array([max(0.0, -k * g - c * (r["normal"] @ v)) if g < -1e-12 else 0.0  # roundoff: open
                         for g, k, c, r in zip(gaps, kp, cp, rows)])
    accel = lambda u, v, R: Minv(F - K @ u - C @ v + sum(Ri * r["normal"] for Ri, r in zip(R, rows)))
    Px, Py, F0 = P[:, 1::2].sum(axis=1), P[:, 2::2].sum(axis=1), F @ u
    stats, out, a = [Stats(3.5 * dt) for _ in contacts], [], accel(u, v, force(u, v))
    for p in range(steps + 1):
        u0, v0, R = u.copy(), v.copy(), np.zeros(len(contacts))
        for _ in range(sub if p < steps else 0):  # central differences: half kick, drift, force, half kick
            v_half = v + 0.5 * h * a
            u = u + h * v_half
            f = force(u, v_half)
            a = accel(u, v_half, f)
            v = v_half + 0.5 * h * a
            R += f / sub  # the step's mean force, reported at the step's start
        for st, Rc in zip(stats, R if p < steps else []): st.add(p * dt, Rc, dt)
        if p % every and p != steps: continue  # history rows every output_every steps and the last
        line, strain = [p * dt], 0.5 * u0 @ (K @ u0)
        for c, r, Rc, k in zip(contacts, rows, R, kp):
            g = lambda key, x: r[key] @ x
            gap = c["g0"] + g("normal", u0)
            strain += 0.5 * k * min(gap, 0.0) ** 2  # the penalty springs' energy
            line += [Rc, 0.0, gap, g("striker_x", u0), g("striker_y", u0), g("striker_x", v0), g("striker_y", v0),
                     g("target_x", u0), g("target_y", u0), g("target_x", v0), g("target_y", v0), 3 if Rc > 0 else 0]
        kinetic = 0.5 * v0 @ (M @ v0)
        e0 = out[0][-6] + out[0][-5] if out else kinetic + strain
        out.append(line + [kinetic, strain, e0 + F @ u0 - F0 - kinetic - strain, F @ u0 - F0, Px @ v0, Py @ v0])
    final = {b["name"]: {"final_velocity": [P[:, 1 + 2 * i] @ v / b["mass"], P[:, 2 + 2 * i] @ v / b["mass"]]}
             for i, b in enumerate(m["bodies"])}
    return np.array(out), [s.summary(c, k) for s, c, k in zip(stats, contacts, kp)], final, sub, steps


def write(args, m, out, contacts, final, sub, steps, wall):
    if not np.all(np.isfinite(out)): raise RuntimeError("the run diverged (non-finite values)")
    cols = ["t"] + [c + (f"_{k + 1}" if k else "") for k in range(len(contacts)) for c in
                   "R tau gap ua_x ua_y va_x va_y ub_x ub_y vb_x vb_y state".split()]
    with open(os.path.join(args.out, "history.csv"), "w") as f:
        f.write(",".join(cols + ["kinetic", "strain", "dissipated", "load_work", "px", "py"]) + "\n")
        f.writelines(",".join(repr(float(x)) for x in r) + "\n" for r in out)
    for k, c in enumerate(contacts):  # the least gap of the linear rows (no deformed geometry here)
        c["real_gap_min"], c["real_gap_min_time"] = out[:, 3 + 12 * k].min(), out[np.argmin(out[:, 3 + 12 * k]), 0]
    summary = {"scene": m["scene"], "scene_file": m["scene_file"], "scene_sha256": m["scene_sha256"],
               "description": m["description"], "method": args.method, "version": "example-1",
               "contact_sampling": f"every step: penalty force averaged over {sub} substep(s)",
               "dt": m["time"]["dt"], "steps": steps, "end_time": m["time"]["end"], "wall_seconds": wall,
               "critical_dt": m["time"]["critical_dt"] or 0.0, "effects": m["effects"],
               "assumed": {**m["assumed"], "penalty": f"{PENALTY} x EA/le"}, "overrides": m["overrides"],
               "energy_initial": out[0, -6] + out[0, -5], "energy_final": out[-1, -6] + out[-1, -5],
               "momentum_drift_max": np.abs(out[:, -2:] - out[0, -2:]).max(), "bodies": final,
               "contacts": contacts, "units": {"t": "s", "R": "N", "tau": "N", "gap": "m", "u": "m", "v": "m/s", "energy": "J",
                                               "momentum": "N s", "impulse": "N s"}, "complete": True}
    tmp = os.path.join(args.out, ".summary.json.tmp")  # summary.json last and atomically
    with open(tmp, "w") as f: json.dump(summary, f, indent=2, default=float)
    os.replace(tmp, os.path.join(args.out, "summary.json"))


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("scene")
    for a in ("--out", "--beamimpact"): ap.add_argument(a, required=True)
    for a in ("--dt", "--mesh"): ap.add_argument(a, default="")
    ap.add_argument("--method", default="example")
    ap.add_argument("--quiet", action="store_true")
    args = ap.parse_args()
    os.makedirs(args.out, exist_ok=True)
    for old in ("summary.json", "history.csv"):  # nothing of an earlier run may vouch for this one
        os.path.exists(os.path.join(args.out, old)) and os.remove(os.path.join(args.out, old))
    start = time.perf_counter()
    try:
        with tempfile.TemporaryDirectory() as folder:
            m, M, K, C, state, F, P = load_model(args, folder)
        if any(c["friction"] > 0 for c in m["contacts"]): refuse(f"{args.scene}: contacts[].friction: expected 0 (no friction here)")
        out, contacts, final, sub, steps = solve(m, M, K, C, state, F, P)
        write(args, m, out, contacts, final, sub, steps, time.perf_counter() - start)
    except (RuntimeError, ValueError, OSError, KeyError) as e:
        print(f"error: {e}", file=sys.stderr)
        sys.exit(3)
    if not args.quiet: print(f"example: {steps} steps x {sub} substep(s), wrote {args.out}/summary.json")


if __name__ == "__main__":
    main()
