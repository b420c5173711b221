"""FEniCSx's contact statistics (references/fenicsx/output.py, pure Python: the reference shares
no code with the C++ methods) against the C++ rule every other method's summary uses
(solver/record/ContactStats with ContactIntervals' merge rule, through beamimpact._core): the
same samples give the same intervals, impulses, peaks and stick/slip counts, bit for bit (both
sum the same IEEE products in the same order). Run from ctest (PYTHONPATH=build/python,
BEAMIMPACT_SOURCE)."""
import os
import random
import sys
from pathlib import Path

sys.path.insert(0, str(Path(os.environ["BEAMIMPACT_SOURCE"]) / "references" / "fenicsx"))
from output import ContactStats  # noqa: E402  (FEniCSx's module needs no dolfinx)

from beamimpact import _core  # noqa: E402

KEYS = ["intervals", "impulse_normal", "impulse_tangential", "peak_R", "peak_R_excluding_closure",
        "first_step_R", "stick_steps", "slip_steps"]


def python_stats(samples, merge_gap):
    s = ContactStats(merge_gap, "")
    for t, R, tau, dt, state in samples:
        s.add(t, R, tau, dt, state)
    out = s.summary()
    return {k: out[k] for k in KEYS}


def cpp_stats(samples, merge_gap):
    t, R, tau, dt, states = (list(c) for c in zip(*samples)) if samples else ([],) * 5
    out = _core.contact_stats(t, R, tau, dt, states, merge_gap)
    out["intervals"] = [list(iv) for iv in out["intervals"]]
    return {k: out[k] for k in KEYS}


def chattering_samples(rng, n):
    """n samples of a contact that closes, chatters (short openings) and reopens for long, at
    uneven steps (an adaptive method's) so that gaps fall on both sides of the merge gap."""
    samples, t, closed = [], 0.0, False
    for _ in range(n):
        dt = rng.choice([0.5, 1.0, 1.0, 2.0]) * 1e-6
        t += dt
        if rng.random() < 0.3:
            closed = not closed
        if closed:
            R = rng.uniform(0.0, 100.0)
            state = rng.choice(["stick", "slip", "frictionless"])
            samples.append((t, R, rng.uniform(-0.3, 0.3) * R, dt, state))
        else:
            samples.append((t, 0.0, 0.0, dt, "open"))
    return samples


def test_random_chatter_agrees_bit_for_bit():
    rng = random.Random(20261125)
    for case in range(200):
        samples = chattering_samples(rng, rng.randint(0, 60))
        merge_gap = rng.choice([0.0, 1.5e-6, 3.5e-6, 1e-5])
        assert python_stats(samples, merge_gap) == cpp_stats(samples, merge_gap), f"case {case}"


def test_reclosure_inside_merged_chatter_is_a_closure():
    # R over steps of 1 s with merge gap 2.5 s: [0, 5, 1, 0, 9, 2, 0] closes at t=1 and again at
    # t=4 (gap 3-2 = 1 s < 2.5 s: one interval [1, 5]). Both closures (5 and 9) are left out of the
    # peak excluding closures, which is the largest of the rest: 2.
    samples = [(float(i), R, 0.0, 1.0, "frictionless" if R else "open")
               for i, R in enumerate([0, 5, 1, 0, 9, 2, 0])]
    for stats in (python_stats(samples, 2.5), cpp_stats(samples, 2.5)):
        assert stats["intervals"] == [[1.0, 5.0]]
        assert stats["peak_R_excluding_closure"] == 2
        assert stats["first_step_R"] == 5
        assert stats["peak_R"] == 9


def _load(name, path):
    """A module by file path under its own name (the references' modules share names)."""
    import importlib.util
    spec = importlib.util.spec_from_file_location(name, Path(os.environ["BEAMIMPACT_SOURCE"]) / path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_outside_solvers_statistics_follow_the_rule():
    # The Siconos adapter's statistics (integer states) and the minimal example's (frictionless:
    # no tangential force or stick/slip counts) against the C++ rule on the same random chatter.
    siconos = _load("siconos_output", "references/siconos/output.py")
    example = _load("example_solver", "examples/external_solver/penalty_central.py")
    codes = {"open": 0, "stick": 1, "slip": 2, "frictionless": 3}
    contact = {"striker": "A", "target": "B", "kind": "end_to_end", "friction": 0.3}
    rng = random.Random(20261126)
    for case in range(200):
        samples = chattering_samples(rng, rng.randint(0, 60))
        merge_gap = rng.choice([0.0, 1.5e-6, 3.5e-6, 1e-5])
        expected = cpp_stats(samples, merge_gap)
        s = siconos.ContactStats(1.0)
        s.merge_gap = merge_gap
        for t, R, tau, dt, state in samples:
            s.add(t, R, tau, dt, codes[state])
        out = s.summary(contact)
        assert {k: out[k] for k in KEYS} == expected, f"siconos, case {case}"
        e = example.Stats(merge_gap)
        frictionless = cpp_stats([(t, R, 0.0, dt, "frictionless" if R > 0 else "open")
                                  for t, R, _, dt, _ in samples], merge_gap)
        for t, R, _, dt, _ in samples:
            e.add(t, R, dt)
        out = e.summary(contact, 0.0)
        assert {k: out[k] for k in KEYS} == frictionless, f"example, case {case}"
