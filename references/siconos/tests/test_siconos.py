"""Siconos on the exported model, checked against theory and the exact S1 solution.

Run by ctest (references/siconos/CMakeLists.txt) with BEAMIMPACT_EXE set; ctest reports it
skipped (exit 77) when /usr/bin/python3 cannot import siconos."""

import json
import os
import subprocess

import pytest

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(os.path.dirname(HERE)))
EXE = os.environ.get("BEAMIMPACT_EXE", os.path.join(ROOT, "build", "beamimpact"))
ADAPTER = os.path.join(ROOT, "references", "siconos", "run.py")
PAPER = os.path.join(ROOT, "verification", "scenes", "paper")


def siconos(tmp_path, scene, *args, name="run"):
    out = tmp_path / name
    r = subprocess.run(["/usr/bin/python3", ADAPTER, os.path.join(PAPER, scene), "--out", str(out),
                        "--beamimpact", EXE, "--quiet", *args], capture_output=True, text=True)
    return r, out


def summary(out):
    with open(out / "summary.json") as f:
        return json.load(f)


def s1(tmp_path, n):
    # dt = 0.1 le / c: the paper's 0.01 s at 10 elements, scaled with the mesh.
    sets = ["--set", f"bodies.A.elements={n}", "--set", f"bodies.B.elements={n}", "--set", f"time.dt={0.1 / n}"]
    r, out = siconos(tmp_path, "s1_central.toml", *sets, name=f"s1_{n}")
    assert r.returncode == 0, r.stderr
    return summary(out)


def test_s1_converges_to_the_exact_impulse_and_velocities(tmp_path):
    # Exact (d'Alembert): impulse rho c A v0 / 2 x 2 L / c = 4 N s over [0.5, 2.5] s; then A at rest,
    # B at 1 m/s. The lumped rod's mesh error: the plastic closure of two end nodes (mass
    # rho A le / 2 each) and the dispersed release shift the impulse by O(rho A le v0) = 4 le / L N s,
    # the tolerance; the error falls about tenfold from 10 to 100 elements (first order in le).
    errors = []
    for n in (10, 100):
        s = s1(tmp_path, n)
        c = s["contacts"][0]
        errors.append(abs(c["impulse_normal"] - 4.0))
        le_over_c = 10.0 / n / 10.0  # s, one element's transit time
        assert errors[-1] < 4.0 * le_over_c, (n, c["impulse_normal"])  # 4 le / L N s, L / c = 1 s
        assert c["impacts"] == 1
        assert abs(c["intervals"][0][0] - 0.5) <= 0.1 / n + 1e-12  # closure within one step
        assert abs(c["intervals"][0][1] - 2.5) <= 2.0 * le_over_c  # release within two transits
        # Momentum passes from A to B: J = m v_B with m = rho A L = 4 kg; free bodies keep the total.
        assert s["bodies"]["B"]["final_velocity"][0] == pytest.approx(c["impulse_normal"] / 4.0, abs=1e-9)
        assert s["momentum_drift_max"] < 1e-10
    assert errors[1] < errors[0] / 5.0


def test_s1_agrees_with_the_paper_integrator_on_the_same_model(tmp_path):
    # Same model, same plastic closure: the two schemes differ only in where in a step the contact
    # events fall, at most one step of the mean force 2 N: 2 N x 0.01 s.
    s = s1(tmp_path, 10)
    paper = tmp_path / "paper"
    subprocess.run([EXE, "run", os.path.join(PAPER, "s1_central.toml"), "--out", str(paper), "--quiet"], check=True)
    p = summary(paper)
    assert s["contacts"][0]["impulse_normal"] == pytest.approx(p["contacts"][0]["impulse_normal"], abs=0.02)


def test_oblique_linear_slips_within_the_coulomb_cone(tmp_path):
    # S4 at 45 deg (linear kinematics): the first step's stick ratio cot(45) = 1 exceeds mu = 0.3, so
    # the striker slips from the closure; every step's force lies in the cone |tau| <= mu R.
    r, out = siconos(tmp_path, "s4_oblique_45.toml", "--set", 'model.kinematics="linear"', "--set", "time.end=0.03")
    assert r.returncode == 0, r.stderr
    c = summary(out)["contacts"][0]
    assert c["slip_steps"] > 0 and c["impulse_normal"] > 0
    assert abs(c["impulse_tangential"]) <= 0.3 * c["impulse_normal"] * (1 + 1e-6)
    with open(out / "history.csv") as f:
        head = f.readline().strip().split(",")
        rows = [list(map(float, line.split(","))) for line in f]
    R, tau = head.index("R"), head.index("tau")
    assert all(abs(row[tau]) <= 0.3 * row[R] * (1 + 1e-6) + 1e-9 for row in rows)


def test_refusals_exit_2_with_one_line_and_no_summary(tmp_path):
    r, out = siconos(tmp_path, "s4_oblique_45.toml", name="corotational")  # matrices change every step
    assert r.returncode == 2
    assert len(r.stderr.strip().splitlines()) == 1 and "model.kinematics" in r.stderr
    assert not (out / "summary.json").exists()
    r, out = siconos(tmp_path, "s1_central.toml", "--theta", "0.2", name="theta")
    assert r.returncode == 2 and "--theta" in r.stderr
    r, out = siconos(tmp_path, "s1_central.toml", "--set", "bodies.A.elements=0", name="bad")
    assert r.returncode == 2 and "elements" in r.stderr
    assert not (out / "summary.json").exists()


def test_conform_passes_every_rule_of_the_protocol(tmp_path):
    # Declared in verification/methods.toml: the conformance set of docs/protocol.md (valid scenes
    # of each kind, a refused one, a malformed one, the same scene twice).
    r = subprocess.run([EXE, "conform", "siconos", "--out", str(tmp_path / "conform")], capture_output=True, text=True)
    assert r.returncode == 0, r.stdout + r.stderr
    assert "conform passed" in r.stdout and "[FAIL]" not in r.stdout


def test_gravity_work_is_the_free_fall_of_the_bouncing_bar(tmp_path):
    # Free fall before the first touch (at 1 s): the bar (m = 10 kg, g = 10 m/s^2) has fallen
    # g t^2 / 2, so the loads' work is m g^2 t^2 / 2 (125 J at 0.5 s). Moreau-Jean with theta 0.5 is
    # the trapezoidal rule, exact for a constant acceleration: roundoff only.
    scene = os.path.join(ROOT, "verification", "scenes", "benchmarks", "bouncing_bar.toml")
    out = tmp_path / "bar"
    r = subprocess.run(["/usr/bin/python3", ADAPTER, scene, "--out", str(out), "--beamimpact", EXE, "--quiet",
                        "--set", "time.end=0.5"], capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    with open(out / "history.csv") as f:
        head = f.readline().strip().split(",")
        rows = [dict(zip(head, map(float, line.split(",")))) for line in f]
    for row in rows:
        assert row["load_work"] == pytest.approx(10.0 * 100.0 * row["t"] ** 2 / 2, rel=1e-9, abs=1e-9)
        assert row["kinetic"] == pytest.approx(row["load_work"], rel=1e-9, abs=1e-9)  # no strain in free fall


def test_rotated_copy_with_a_roller_across_the_target_is_s2(tmp_path):
    # S2 rotated by 37 deg with the target's roller across it (fix = ["normal"]): the export puts
    # that node's translations in the target's axes (dofs.csv axis_x, axis_y) and its matrices are
    # T^T K T, a rotation of S2's model. One problem, one answer: Siconos's fixed steps give S2's
    # intervals and impulse to the roundoff of the rotated coordinates (1e-12 relative allows the
    # LCP's few products per step over 300 steps; measured 1e-15).
    r, out = siconos(tmp_path, "s2_transverse.toml", name="s2")
    assert r.returncode == 0, r.stderr
    rotated = os.path.join(ROOT, "verification", "scenes", "extra", "s2_rotated_37.toml")
    r37, out37 = siconos(tmp_path, rotated, name="s2_37")
    assert r37.returncode == 0, r37.stderr
    a, b = summary(out)["contacts"][0], summary(out37)["contacts"][0]
    assert len(a["intervals"]) == 2 and len(b["intervals"]) == 2
    assert sum(b["intervals"], []) == pytest.approx(sum(a["intervals"], []), abs=1e-12)
    assert b["impulse_normal"] == pytest.approx(a["impulse_normal"], rel=1e-12)
    assert b["peak_R"] == pytest.approx(a["peak_R"], rel=1e-12)
