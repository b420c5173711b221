"""history.csv and summary.json of a Siconos run, in the protocol's layout (`beamimpact schema`):
the contact columns of each contact (suffix _k from the second), then the model's columns; the
contact statistics by the suite's rule (solver/record/ContactIntervals.hpp): a step is in
contact when R > 0, each run of contact steps is a phase, and a phase that begins less than the
merge gap after the last interval's end joins it (references/common/contact_intervals.py: fewer
than 3 open steps); a re-closure is a closure."""

import json
import math
import os
import sys

import numpy as np

# The suite's contact-interval rule, shared by the Python references (references/common).
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
from contact_intervals import ContactIntervals, merge_gap, merge_rule  # noqa: E402,F401

CONTACT_COLUMNS = ["R", "tau", "gap", "ua_x", "ua_y", "va_x", "va_y", "ub_x", "ub_y", "vb_x", "vb_y", "state"]
MODEL_COLUMNS = ["kinetic", "strain", "dissipated", "load_work", "px", "py"]  # load_work: F . (u - u0), J
OPEN, STICK, SLIP, CLOSED = 0, 1, 2, 3  # column `state`


def history_columns(n_contacts):
    cols = ["t"]
    for k in range(n_contacts):
        cols += [c + ("" if k == 0 else f"_{k + 1}") for c in CONTACT_COLUMNS]
    return cols + MODEL_COLUMNS


class ContactStats:
    """One contact's intervals, impulses, peaks and stick/slip counts."""

    def __init__(self, dt):
        self.rule = merge_rule(dt)
        self.phases = ContactIntervals(merge_gap(dt))
        self.intervals = self.phases.intervals  # [start, end, peak after the closure step, closure R]
        self.on = False
        self.impulse_n = self.impulse_t = self.peak = 0.0
        self.stick = self.slip = 0
        self.gap_min, self.gap_min_time, self.slide_max = math.inf, 0.0, 0.0

    def add(self, t, R, tau, dt, state):
        if not R > 0:
            self.on = False
            return
        self.impulse_n += R * dt
        self.impulse_t += tau * dt
        self.peak = max(self.peak, R)
        self.stick += state == STICK
        self.slip += state == SLIP
        if not self.on:  # a (re-)closure begins a phase; its force is not a peak after closure
            self.phases.begin(t, 0.0, R)
            self.on = True
        else:
            self.intervals[-1][2] = max(self.intervals[-1][2], R)
            self.phases.extend(t)

    def track(self, t, gap, slide):
        if gap < self.gap_min:
            self.gap_min, self.gap_min_time = gap, t
        self.slide_max = max(self.slide_max, abs(slide))

    def summary(self, contact):
        return {"striker": contact["striker"], "target": contact["target"], "kind": contact["kind"],
                "friction": contact["friction"], "intervals": [iv[:2] for iv in self.intervals],
                "impacts": len(self.intervals), "merge_rule": self.rule,
                "impulse_normal": self.impulse_n, "impulse_tangential": self.impulse_t,
                "peak_R": self.peak,
                "peak_R_excluding_closure": max([iv[2] for iv in self.intervals], default=0.0),
                "first_step_R": self.intervals[0][3] if self.intervals else 0.0,
                "stick_steps": self.stick, "slip_steps": self.slip,
                "real_gap_min": self.gap_min, "real_gap_min_time": self.gap_min_time,
                "real_gap": "from the exported linear rows (no deformed geometry)",
                "struck_point_slide_max": self.slide_max}


def contact_state(R, tau, mu, friction):
    if R <= 0:
        return OPEN
    if not friction:
        return CLOSED
    return STICK if abs(tau) < mu * R * (1.0 - 1e-6) else SLIP


class Recorder:
    """Turns the stepping's samples into history rows and statistics."""

    def __init__(self, model, dt, every):
        self.model, self.dt, self.every = model, dt, every
        self.friction = "friction" in model.doc["effects"]
        self.stats = [ContactStats(dt) for _ in model.contacts]
        self.rows = []
        self.p0 = None
        self.drift = 0.0
        self.k = 0

    def add(self, t, u, v, R, tau, last):
        m = self.model
        kinetic, strain = 0.5 * v @ (m.M @ v), 0.5 * u @ (m.K @ u)
        work = m.F @ (u - m.u0)
        p = np.array(m.total_momentum(v))
        if self.p0 is None:
            self.p0, self.e0 = p, kinetic + strain
        self.drift = max(self.drift, float(np.abs(p - self.p0).max()))
        line = [t]
        for c, (contact, rows) in enumerate(zip(m.contacts, m.rows)):
            Rc, tc = (R[c], tau[c]) if R is not None else (0.0, 0.0)
            state = contact_state(Rc, tc, contact["friction"], self.friction)
            gap = contact["g0"] + rows["normal"] @ u
            self.stats[c].track(t, gap, rows["tangent"] @ u)
            if R is not None:
                self.stats[c].add(t, Rc, tc, self.dt, state)
            line += [Rc, tc, gap] + [rows[k] @ x for x, k in
                                     ((u, "striker_x"), (u, "striker_y"), (v, "striker_x"), (v, "striker_y"),
                                      (u, "target_x"), (u, "target_y"), (v, "target_x"), (v, "target_y"))]
            line.append(state)
        dissipated = self.e0 + work - kinetic - strain
        if self.k % self.every == 0 or last:
            self.rows.append(line + [kinetic, strain, dissipated, work, p[0], p[1]])
        self.k += 1


def _check_finite(obj, where):
    if isinstance(obj, float) and not math.isfinite(obj):
        raise RuntimeError(f"non-finite number in {where}; no result written")
    if isinstance(obj, dict):
        for k, v in obj.items():
            _check_finite(v, f"{where}.{k}")
    if isinstance(obj, (list, tuple)):
        for v in obj:
            _check_finite(v, where)


def remove_stale(out_dir):
    """Removes an earlier run's summary.json and history.csv: a failed run leaves neither."""
    os.makedirs(out_dir, exist_ok=True)
    for name in ("summary.json", "history.csv"):
        try:
            os.remove(os.path.join(out_dir, name))
        except FileNotFoundError:
            pass


def write_run(out_dir, n_contacts, rows, summary):
    """Writes history.csv, then summary.json last and atomically (rename of a temporary file)."""
    for r in rows:
        if not all(math.isfinite(float(x)) for x in r):
            raise RuntimeError(f"non-finite value in the history row at t = {r[0]}; no result written")
    _check_finite(summary, "summary")
    with open(os.path.join(out_dir, "history.csv"), "w") as f:
        f.write(",".join(history_columns(n_contacts)) + "\n")
        for r in rows:
            f.write(",".join(str(x) if isinstance(x, int) else repr(float(x)) for x in r) + "\n")
    tmp = os.path.join(out_dir, ".summary.json.tmp")
    with open(tmp, "w") as f:
        json.dump(summary, f, indent=2)
        f.write("\n")
    os.replace(tmp, os.path.join(out_dir, "summary.json"))
