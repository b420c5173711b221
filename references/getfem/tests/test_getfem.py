"""The GetFEM reference against theory: the exact central rod collision (S1), the rod on a rigid
wall, the Euler-Bernoulli beam it assembles, and its refusals.

Run by ctest (references/getfem/CMakeLists.txt); ctest reports it skipped (exit 77) when
/usr/bin/python3 cannot import getfem."""

import csv
import json
import math
import os
import subprocess
import sys

import numpy as np
import pytest

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(os.path.dirname(HERE)))
ADAPTER = os.path.join(ROOT, "references", "getfem", "run.py")
SCENES = os.path.join(ROOT, "verification", "scenes")
sys.path.insert(0, os.path.dirname(HERE))


def getfem(tmp_path, scene, *args, name="run"):
    out = tmp_path / name
    r = subprocess.run(["/usr/bin/python3", ADAPTER, scene, "--out", str(out), "--quiet", *args],
                       capture_output=True, text=True)
    return r, out


def finished(tmp_path, scene, *args, name="run"):
    r, out = getfem(tmp_path, scene, *args, name=name)
    assert r.returncode == 0, r.stderr
    with open(out / "summary.json") as f:
        s = json.load(f)
    with open(out / "history.csv") as f:
        rows = list(csv.DictReader(f))
    return s, rows


def s1_run(tmp_path, factor, *args):
    """S1 with every body in `factor` times its elements and the step scaled with them."""
    return finished(tmp_path, os.path.join(SCENES, "paper", "s1_central.toml"), "--mesh", str(factor),
                    "--dt", str(0.01 / factor), *args, name=f"s1_{factor}_{'_'.join(args)}")


def test_s1_matches_the_exact_rod_collision(tmp_path):
    # Exact (d'Alembert, equal rods, c = 10 m/s, L = 10 m, Z = rho A c = 4 N s/m): touch at
    # gap / v0 = 0.5 s, contact for 2 L / c = 2 s at P = Z v0 / 2 = 2 N, impulse 4 N s, then A at
    # rest and B at 1 m/s. The P1 mesh carries the wave front over about one element, so the
    # release and the momentum exchanged are off by about one element's transit le / c: the
    # tolerances are one transit at the mean force (2 N x le / c) for the impulse, two transits for
    # the release; the closure is sampled at the first step end with R > 0 (within one step).
    for factor in (1, 4):
        le_c = 0.1 / factor  # s
        s, rows = s1_run(tmp_path, factor)
        c = s["contacts"][0]
        assert c["impacts"] == 1, c["intervals"]
        assert abs(c["intervals"][0][0] - 0.5) <= 0.01 / factor + 1e-12
        assert abs(c["intervals"][0][1] - 2.5) <= 2 * le_c
        assert abs(c["impulse_normal"] - 4.0) <= 2.0 * le_c, c["impulse_normal"]
        # A's momentum goes to B (m = rho A L = 4 kg each): B ends at J / m, A at v0 - J / m.
        assert s["bodies"]["B"]["final_velocity"][0] == pytest.approx(c["impulse_normal"] / 4.0, abs=1e-6)
        assert s["bodies"]["A"]["final_velocity"][0] == pytest.approx(1.0 - c["impulse_normal"] / 4.0, abs=1e-6)
        # Free bodies: the total momentum rho A L v0 = 4 N s holds at every step (Newmark keeps it
        # for equal and opposite contact forces).
        assert max(abs(float(r["px"]) - 4.0) for r in rows) < 1e-9
        # The trapezoidal rule keeps the quadratic energy while the active set is fixed; only the
        # penalty's switching steps change it, by less than 0.1 % of the 2 J.
        assert abs(s["energy_final"] - 2.0) < 2e-3


def test_s1_lumped_error_falls_with_the_mesh(tmp_path):
    # With the lumped axial mass the mesh error is larger (the lumped bar's dispersion lags the
    # front) and falls with the element size (10 -> 40 elements, the step scaled with it); slowly,
    # as a discontinuous front dispersed by a second-order scheme does (measured about le^0.45),
    # so the check is that a quarter of the element size takes off at least a quarter of the error.
    errors = [abs(s1_run(tmp_path, f, "--mass", "lumped")[0]["contacts"][0]["impulse_normal"] - 4.0)
              for f in (1, 4)]
    assert errors[0] <= 0.2 and errors[1] < 0.75 * errors[0], errors


def test_rod_on_a_rigid_wall_matches_dalembert(tmp_path):
    # Exact (references/exact/RodOnWall.hpp): touch at 0.5 s, contact for 2 L / c = 2 s at
    # R = rho A c v0 = 4 N (impulse 8 N s), the rod leaves at -v0. Tolerances as in S1: one element
    # transit le / c = 0.1 s at 4 N for the impulse, two transits for the release, one step (0.05 s)
    # for the closure.
    s, rows = finished(tmp_path, os.path.join(SCENES, "benchmarks", "rod_on_wall.toml"))
    c = s["contacts"][0]
    assert c["impacts"] == 1, c["intervals"]
    assert abs(c["intervals"][0][0] - 0.5) <= 0.05 + 1e-12
    assert abs(c["intervals"][0][1] - 2.5) <= 0.2
    assert abs(c["impulse_normal"] - 8.0) <= 0.4
    # The wall takes the impulse: the rod (4 kg) ends at v0 - J / m.
    assert s["bodies"]["rod"]["final_velocity"][0] == pytest.approx(1.0 - c["impulse_normal"] / 4.0, abs=1e-6)
    # Mid-contact the force is the wave solution's plateau Z v0 = 4 N, on average within 5 %.
    mid = [float(r["R"]) for r in rows if 1.0 <= float(r["t"]) <= 2.0]
    assert abs(np.mean(mid) - 4.0) < 0.2


def test_hermite_beam_has_the_euler_bernoulli_frequencies():
    # Simply supported beam (S2's B: L = 10 m, E I = 0.5333 N m^2, rho A = 0.4 kg/m):
    # Omega_n = (n pi / L)^2 sqrt(E I / (rho A)). Cubic Hermite elements with their consistent mass
    # converge as h^4: with 10 elements the first three modes are within 0.1 %.
    import scene_input
    from assembly import GlobalModel
    import scipy.linalg

    scene = scene_input.load(os.path.join(SCENES, "paper", "s2_transverse.toml"))
    model = GlobalModel(scene)
    p, o = model.parts[1], model.offset[1]
    block = [d for d in model.free if o + p.nu <= d < o + p.ndof]  # B's transverse (Hermite) DOFs
    K = model.K[block][:, block].toarray()
    M = model.M[block][:, block].toarray()
    w = np.sqrt(np.sort(np.abs(scipy.linalg.eigvalsh(K, M))))
    for n, x in enumerate(w[:3], start=1):
        exact = (n * math.pi / 10.0) ** 2 * math.sqrt(100.0 * 0.0053333333333333 / 0.4)
        assert x == pytest.approx(exact, rel=1e-3), (n, x, exact)


def test_transverse_impulse_is_the_strikers_momentum_change(tmp_path):
    # S2: the striker A (2 kg, free, falling at 1 m/s) feels only the contact force, so the
    # impulse the history reports equals A's momentum change (trapezoidal rule, force zero at
    # both ends of the contact).
    s, _ = finished(tmp_path, os.path.join(SCENES, "paper", "s2_transverse.toml"))
    J = sum(c["impulse_normal"] for c in s["contacts"])
    assert J > 0.5
    assert 2.0 * (s["bodies"]["A"]["final_velocity"][1] + 1.0) == pytest.approx(J, rel=1e-9)


@pytest.mark.parametrize("old, new, why", [
    ("friction = 0.0", "friction = 0.3", "friction"),
    ('kinematics = "linear"', 'kinematics = "corotational"', "corotational"),
    ('node = "end"', 'node = "all"', "search"),
    ("[time]", "[time\n", "TOML"),
])
def test_unsupported_or_bad_scene_is_refused_with_one_line(tmp_path, old, new, why):
    # The protocol (docs/protocol.md): exit 2, one line on stderr saying why, no summary.json.
    with open(os.path.join(SCENES, "paper", "s1_central.toml")) as f:
        text = f.read()
    assert old in text
    scene = tmp_path / "scene.toml"
    scene.write_text(text.replace(old, new, 1))
    r, out = getfem(tmp_path, str(scene))
    assert r.returncode == 2, (r.returncode, r.stderr)
    lines = r.stderr.strip().splitlines()
    assert len(lines) == 1 and why in lines[0], r.stderr
    assert not (out / "summary.json").exists()
