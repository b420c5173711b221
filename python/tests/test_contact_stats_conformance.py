"""The Python references' contact-interval rule (references/common/contact_intervals.py: FEniCSx's,
Siconos's and GetFEM's statistics are built on it; GetFEM uses FEniCSx's output module) and
FEniCSx's contact statistics (references/fenicsx/output.py, pure Python: the references share no
code with the C++ methods) against the C++ rule every other method's summary uses
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
import contact_intervals  # noqa: E402  (on the path FEniCSx's output module puts it)

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


# The outside solvers' statistics run in a child process: importing the example (scipy) here
# would raise this process's memory, which a child started later inherits as its peak RSS
# (test_module's memory test measures one).
OUTSIDE = r"""
import importlib.util, json, sys
def load(name, path):
    spec = importlib.util.spec_from_file_location(name, path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module
siconos, example = load("siconos_output", sys.argv[1]), load("example_solver", sys.argv[2])
codes = {"open": 0, "stick": 1, "slip": 2, "frictionless": 3}
contact = {"striker": "A", "target": "B", "kind": "end_to_end", "friction": 0.3}
out = []
for samples, merge_gap in json.load(sys.stdin):
    s = siconos.ContactStats(1.0)
    s.phases.merge_gap = merge_gap
    e = example.Stats(merge_gap)
    for t, R, tau, dt, state in samples:
        s.add(t, R, tau, dt, codes[state])
        e.add(t, R, dt)
    out.append([s.summary(contact), e.summary(contact, 0.0)])
json.dump(out, sys.stdout)
"""


def test_outside_solvers_statistics_follow_the_rule():
    # The Siconos adapter's statistics (integer states) and the minimal example's (frictionless:
    # no tangential force or stick/slip counts) against the C++ rule on the same random chatter.
    import json
    import subprocess
    rng = random.Random(20261126)
    cases = []
    for _ in range(200):
        cases.append((chattering_samples(rng, rng.randint(0, 60)), rng.choice([0.0, 1.5e-6, 3.5e-6, 1e-5])))
    src = Path(os.environ["BEAMIMPACT_SOURCE"])
    p = subprocess.run([sys.executable, "-c", OUTSIDE, str(src / "references/siconos/output.py"),
                        str(src / "examples/external_solver/penalty_central.py")],
                       input=json.dumps(cases), capture_output=True, text=True)
    assert p.returncode == 0, p.stderr
    for case, ((samples, merge_gap), (siconos, example)) in enumerate(zip(cases, json.loads(p.stdout))):
        assert {k: siconos[k] for k in KEYS} == cpp_stats(samples, merge_gap), f"siconos, case {case}"
        frictionless = [(t, R, 0.0, dt, "frictionless" if R > 0 else "open") for t, R, _, dt, _ in samples]
        assert {k: example[k] for k in KEYS} == cpp_stats(frictionless, merge_gap), f"example, case {case}"


def test_the_shared_default_merge_gap_is_the_cpp_one():
    # Fewer than 3 open samples merge, whatever the step: (3 + 0.5) steps in both languages.
    assert contact_intervals.MERGE_STEPS == _core.merge_steps == 3
    for step in (1e-6, 0.01, 0.37, 2.0):
        assert contact_intervals.merge_gap(step) == _core.default_merge_gap(step) == 3.5 * step


def test_two_and_three_open_samples_at_the_default_gap():
    # Steps of 0.01 s (round-off in the times): two open samples between contacts merge, three do
    # not, for the shared module's default gap as for the C++ one.
    for open_steps, intervals in ((2, 1), (3, 2)):
        R = [0.0, 1.0, 1.0] + [0.0] * open_steps + [1.0, 0.0]
        samples = [(0.01 * i, r, 0.0, 0.01, "frictionless" if r else "open") for i, r in enumerate(R)]
        assert len(python_stats(samples, contact_intervals.merge_gap(0.01))["intervals"]) == intervals
        assert len(cpp_stats(samples, _core.default_merge_gap(0.01))["intervals"]) == intervals


SHARED = r"""
import importlib.util, sys
def load(name, path):
    spec = importlib.util.spec_from_file_location(name, path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module
siconos = load("siconos_output", sys.argv[1])
s = siconos.ContactStats(0.01)
print(type(s.phases).__module__, s.phases.merge_gap)
"""


def test_every_python_reference_builds_on_the_shared_module():
    # FEniCSx's statistics (and GetFEM's, which are FEniCSx's) and Siconos's hold the shared rule's
    # intervals; Siconos's default gap is the suite's (its run.py passes the step).
    import subprocess
    assert type(ContactStats(1.0, "").phases) is contact_intervals.ContactIntervals
    src = Path(os.environ["BEAMIMPACT_SOURCE"])
    p = subprocess.run([sys.executable, "-c", SHARED, str(src / "references/siconos/output.py")],
                       capture_output=True, text=True)
    assert p.returncode == 0, p.stderr
    module, gap = p.stdout.split()
    assert module == "contact_intervals"
    assert float(gap) == _core.default_merge_gap(0.01)
