"""The minimal example solver against the exact S1 solution and the paper integrator.

Run by ctest (examples/external_solver/CMakeLists.txt) with BEAMIMPACT_EXE set."""

import json
import os
import subprocess

import pytest

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
EXE = os.environ.get("BEAMIMPACT_EXE", os.path.join(ROOT, "build", "beamimpact"))
SCENES = os.path.join(ROOT, "verification", "scenes", "paper")


def example(tmp_path, scene, *args, name="run"):
    out = tmp_path / name
    r = subprocess.run(["/usr/bin/python3", os.path.join(HERE, "penalty_central.py"), os.path.join(SCENES, scene),
                        "--out", str(out), "--beamimpact", EXE, "--quiet", *args], capture_output=True, text=True)
    return r, out


def summary(out):
    with open(out / "summary.json") as f:
        return json.load(f)


def test_s1_impulse_converges_to_exact_and_meets_the_paper(tmp_path):
    # Exact: 4 N s over [0.5, 2.5] s. Mesh error of the lumped rod O(rho A le v0) = 4 le / L N s
    # (see references/siconos/tests); the penalty adds a penetration R / k_p = 2 N / (10 EA / le),
    # le / 200 m, which shifts closure and release by under a step. dt = 0.1 le / c.
    errors = []
    for mesh in (1, 10):
        n = 10 * mesh
        r, out = example(tmp_path, "s1_central.toml", "--mesh", str(mesh), "--dt", str(0.1 / n), name=f"s1_{n}")
        assert r.returncode == 0, r.stderr
        s = summary(out)
        c = s["contacts"][0]
        errors.append(abs(c["impulse_normal"] - 4.0))
        assert errors[-1] < 4.0 / n
        assert c["impacts"] == 1 and abs(c["intervals"][0][0] - 0.5) <= 0.1 / n + 1e-12
        assert s["momentum_drift_max"] < 1e-10  # free bodies, equal and opposite contact forces
        assert s["energy_final"] <= s["energy_initial"] * (1 + 1e-9)  # a stable step creates no energy
    assert errors[1] < errors[0] / 5.0  # first order in le
    paper = tmp_path / "paper"
    subprocess.run([EXE, "run", os.path.join(SCENES, "s1_central.toml"), "--out", str(paper), "--quiet"], check=True)
    # Same model: closure and release within a step of the paper's, 2 N x 2 steps of 0.01 s.
    r, out = example(tmp_path, "s1_central.toml", name="s1_paper_dt")
    assert summary(out)["contacts"][0]["impulse_normal"] == pytest.approx(
        summary(paper)["contacts"][0]["impulse_normal"], abs=0.04)


def test_refuses_scenes_it_cannot_run_with_exit_2(tmp_path):
    r, out = example(tmp_path, "s2_transverse.toml", "--dt", "0.01", name="ok")
    assert r.returncode == 0, r.stderr
    r, out = example(tmp_path, "s4_oblique_45.toml", name="corotational")
    assert r.returncode == 2 and len(r.stderr.strip().splitlines()) == 1
    assert not (out / "summary.json").exists()
    r, out = example(tmp_path, "missing.toml", name="missing")
    assert r.returncode == 2 and "missing.toml" in r.stderr


def conform(tmp_path, name, methods=None):
    args = [EXE, "conform", name, "--out", str(tmp_path / f"conform_{name}")]
    return subprocess.run(args + (["--methods", str(methods)] if methods else []), capture_output=True, text=True)


def test_conform_passes_every_rule_of_the_protocol(tmp_path):
    r = conform(tmp_path, "example")  # declared in verification/methods.toml
    assert r.returncode == 0, r.stdout + r.stderr
    assert "conform passed" in r.stdout and "[FAIL]" not in r.stdout


# Broken copies of the example, each breaking one rule of docs/protocol.md: conform must fail
# (exit 1) and name that rule. (old, new) is a single edit of the source.
BROKEN = [
    ("column", ('"R tau gap ua_x', '"F tau gap ua_x'), "columns"),
    ("exit_code", ('sys.exit(2)  # the protocol', 'sys.exit(1)  # the protocol'), "exit code"),
    ("summary_on_failure",
     ('for c in m["contacts"]): refuse(',
      'for c in m["contacts"]): open(os.path.join(args.out, "summary.json"), "w").write("{}"), refuse('),
     "no summary after failure"),
]


@pytest.mark.parametrize("broken,edit,rule", BROKEN, ids=[b[0] for b in BROKEN])
def test_conform_names_the_rule_a_broken_copy_breaks(tmp_path, broken, edit, rule):
    with open(os.path.join(HERE, "penalty_central.py")) as f:
        source = f.read()
    assert source.count(edit[0]) == 1, f"the edit for '{broken}' no longer matches penalty_central.py"
    copy = tmp_path / f"broken_{broken}.py"
    copy.write_text(source.replace(edit[0], edit[1]))
    name = f"broken_{broken}"
    methods = tmp_path / "methods.toml"
    methods.write_text(f'''[[method]]
name = "{name}"
summary = "the example with one broken rule: {broken}"
command = ["/usr/bin/python3", "{copy}", "{{scene}}", "--out", "{{out}}", "--quiet", "--beamimpact",
           "{{beamimpact}}", "--dt", "{{dt}}", "--mesh", "{{mesh}}", "--method", "{name}"]
[method.accepts]
dt = true
mesh_factor = true
several_contacts = true
bending = true
node_to_surface = true
loads = true
''')
    r = conform(tmp_path, name, methods)
    assert r.returncode == 1, r.stdout + r.stderr
    assert f"[FAIL] {rule}" in r.stdout, r.stdout


def test_gravity_work_is_the_free_fall_of_the_bouncing_bar(tmp_path):
    # Free fall before the first touch (at 1 s): the loads' work is m g^2 t^2 / 2 (m = 10 kg,
    # g = 10 m/s^2). Central differences are exact for a constant acceleration: roundoff only.
    scene = os.path.join(ROOT, "verification", "scenes", "benchmarks", "bouncing_bar.toml")
    out = tmp_path / "bar"
    r = subprocess.run(["/usr/bin/python3", os.path.join(HERE, "penalty_central.py"), scene, "--out", str(out),
                        "--beamimpact", EXE, "--quiet"], capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    with open(out / "history.csv") as f:
        head = f.readline().strip().split(",")
        rows = [dict(zip(head, map(float, line.split(",")))) for line in f]
    before = [row for row in rows if row["t"] <= 0.9]
    assert len(before) > 10
    for row in before:
        assert row["load_work"] == pytest.approx(10.0 * 100.0 * row["t"] ** 2 / 2, rel=1e-9, abs=1e-9)
