"""history.csv and summary.json in the layout of docs/scene-format.md, and the contact statistics
(intervals, impulses, peaks) computed the way solver/record/ContactStats.hpp describes them:
a sample is "in contact" when R > 0, each run of contact samples is a phase, and a phase that
begins less than the merge gap after the last interval's end joins it (the rule of
solver/record/ContactIntervals.hpp, in Python references/common/contact_intervals.py;
python/tests/test_contact_stats_conformance.py checks that both give the same statistics)."""

import glob
import json
import math
import os
import sys

# The suite's contact-interval rule, shared by the Python references (references/common).
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
from contact_intervals import ContactIntervals, merge_gap, merge_rule  # noqa: E402,F401

CONTACT_COLUMNS = ["R", "tau", "gap", "ua_x", "ua_y", "va_x", "va_y",
                   "ub_x", "ub_y", "vb_x", "vb_y", "state"]
# The integer of column `state` (docs/scene-format.md): 0 open, 1 stick, 2 slip, 3 closed without friction.
STATE_CODES = {"open": 0, "stick": 1, "slip": 2, "frictionless": 3}
# load_work: F . u (J), the constant loads' work since t = 0 (0 without [loads]).
TOTAL_COLUMNS = ["kinetic", "strain", "dissipated", "load_work", "px", "py"]


def history_columns(n_contacts):
    """Column names for a scene with n contacts (contact columns repeat with _2, _3, ...)."""
    cols = ["t"]
    for k in range(n_contacts):
        cols += [c + ("" if k == 0 else f"_{k + 1}") for c in CONTACT_COLUMNS]
    return cols + TOTAL_COLUMNS


class ContactStats:
    """Accumulates one contact's per-step samples into the summary's contact entry."""

    def __init__(self, merge_gap, rule):
        self.rule = rule
        self.phases = ContactIntervals(merge_gap)
        self.intervals = self.phases.intervals  # [start, end, peak_after_closure, closure_R]
        self.in_contact = False
        self.impulse_n = self.impulse_t = self.peak = 0.0
        self.stick = self.slip = 0

    def add(self, t, R, tau, dt, state):
        if not R > 0:
            self.in_contact = False
            return
        self.impulse_n += R * dt
        self.impulse_t += tau * dt
        self.peak = max(self.peak, R)
        self.stick += state == "stick"
        self.slip += state == "slip"
        if not self.in_contact:
            # A (re-)closure begins a phase (a new interval, or the last one's chatter). Its force
            # is not a peak after closure.
            self.phases.begin(t, 0.0, R)
            self.in_contact = True
        else:
            self.intervals[-1][2] = max(self.intervals[-1][2], R)
            self.phases.extend(t)

    def summary(self):
        return {
            "intervals": [[a, b] for a, b, _, _ in self.intervals],
            "merge_rule": self.rule,
            "impulse_normal": self.impulse_n, "impulse_tangential": self.impulse_t,
            "peak_R": self.peak,
            "peak_R_excluding_closure": max([iv[2] for iv in self.intervals], default=0.0),
            "first_step_R": self.intervals[0][3] if self.intervals else 0.0,
            "stick_steps": self.stick, "slip_steps": self.slip,
        }


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
    """Removes what an earlier run left in out_dir first: summary.json, so that a crash cannot
    leave an old one looking valid, and its fields (fields.pvd and its pieces), so that a run
    without fields leaves no collection describing another run."""
    os.makedirs(out_dir, exist_ok=True)
    stale = [os.path.join(out_dir, "summary.json")]
    for pattern in ("fields*.pvd", "fields*.pvtu", "fields_p*.vtu"):
        stale += glob.glob(os.path.join(out_dir, pattern))
    for p in stale:
        try:
            os.remove(p)
        except FileNotFoundError:
            pass


def write_run(out_dir, columns, rows, summary):
    """Writes history.csv, then summary.json last and atomically (rename of a temporary file)."""
    for r in rows:
        if not all(math.isfinite(v) for v in r):
            raise RuntimeError(f"non-finite value in history row at t = {r[0]}; no result written")
    _check_finite(summary, "summary")
    with open(os.path.join(out_dir, "history.csv"), "w") as f:
        f.write(",".join(columns) + "\n")
        for r in rows:
            f.write(",".join(str(v) if isinstance(v, int) else repr(float(v)) for v in r) + "\n")
    tmp = os.path.join(out_dir, ".summary.json.tmp")
    with open(tmp, "w") as f:
        json.dump(summary, f, indent=2)
        f.write("\n")
    os.replace(tmp, os.path.join(out_dir, "summary.json"))
