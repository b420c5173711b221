"""scorecard_figures.py on a real scorecard (`beamimpact score paper --sets paper`): one diagram per
scored scene with a committed work-precision set, each in the manifest figures.json with its scene
and how it was made, embedded in the page render.py makes (still self-contained), a second run
replacing the figures instead of adding to them, and bad input refused with exit 2."""
import json
import os
import re
import subprocess

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
EXE = os.environ.get("BEAMIMPACT_EXE", os.path.join(ROOT, "build", "beamimpact"))
SCRIPT = os.path.join(ROOT, "reports", "scorecard_figures.py")


def figures(path):
    with open(path) as f:
        html = f.read()
    return html, len(re.findall(r'<img [^>]*src="data:image/png;base64,', html))


def test_one_diagram_per_scene_with_a_set_and_idempotent(tmp_path):
    out = tmp_path / "score"
    # The paper's scenes only, against IDA as the matrix writes it (converged IDA on S4 costs minutes
    # of CPU): this test is about the figures, the references' choice has its own tests.
    # Exit 1 is a scorecard whose verdict failed: still a scorecard to draw.
    r = subprocess.run([EXE, "score", "paper", "--out", str(out), "--jobs", "2", "--sets", "paper", "--references",
                        "matrix", "--cache", str(tmp_path / "cache")], cwd=ROOT, capture_output=True, text=True)
    assert r.returncode in (0, 1), r.stderr
    paper = {f[:-5] for f in os.listdir(os.path.join(ROOT, "verification", "scenes", "paper")) if f.endswith(".toml")}
    sets = {d for d in os.listdir(os.path.join(ROOT, "reports", "work_precision"))
            if d in paper and os.path.isfile(os.path.join(ROOT, "reports", "work_precision", d, "work_precision.json"))}
    assert len(sets) == 7  # the paper's seven scenes (S1, S2, S3 x2, S4 x3)
    for _ in range(2):
        subprocess.run(["/usr/bin/python3", SCRIPT, str(out)], cwd=ROOT, check=True, capture_output=True)
        html, n = figures(out / "scorecard.html")
        assert n == len(sets)  # every paper scene is scored, each once (the second run replaces)
        with open(out / "figures.json") as f:
            manifest = json.load(f)
        assert sorted(f["scene"] for f in manifest["figures"]) == sorted(sets)
        with open(out / "scorecard.json") as f:
            version = json.load(f)["version"]
        for f in manifest["figures"]:
            assert (out / f["png"]).is_file() and f["version"] == version
            assert "scorecard_figures.py" in f["command"] and f["command"] in html  # the caption says it
    assert not re.search(r'src="(?!data:)', html)  # self-contained: no file the page would fetch
    assert html.rstrip().endswith("</html>")


def test_bad_input_exit_2_with_one_line(tmp_path):
    r = subprocess.run(["/usr/bin/python3", SCRIPT, str(tmp_path)], capture_output=True, text=True)
    assert r.returncode == 2 and "scorecard.json" in r.stderr and len(r.stderr.strip().splitlines()) == 1


def test_score_refuses_unknown_sets_matrix_references_for_ida_and_no_time(tmp_path):
    for args, key in ((["paper", "--sets", "paper,papers"], "--sets"), (["ida", "--references", "matrix"], "--references"),
                      (["paper", "--timeout=0"], "--timeout")):
        r = subprocess.run([EXE, "score"] + args + ["--out", str(tmp_path / "s")], cwd=ROOT, capture_output=True, text=True)
        assert r.returncode == 2, r.stderr
        assert key in r.stderr and len(r.stderr.strip().splitlines()) == 1, r.stderr
        assert not (tmp_path / "s" / "scorecard.json").exists()


def test_several_methods_share_their_references(tmp_path):
    out = tmp_path / "score"
    cache = tmp_path / "cache"
    r = subprocess.run([EXE, "score", "paper", "example", "--sets", "exact", "--references", "matrix", "--out", str(out),
                        "--jobs", "2", "--no-ladder", "--cache", str(cache)], cwd=ROOT, capture_output=True, text=True)
    assert r.returncode in (0, 1), r.stderr
    cards = {}
    for m in ("paper", "example"):
        with open(out / m / "scorecard.json") as f:
            cards[m] = json.load(f)
        assert cards[m]["method"] == m and "paper example" in cards[m]["command"]
    refs = {(s["scene"], s["reference"]) for c in cards.values() for s in c["scenes"]}
    assert all(s["reference_kind"] == "exact" for c in cards.values() for s in c["scenes"])
    # The eight exact-answer scenes' references, each run once for both scorecards, in the cache.
    assert len(refs) == len(cards["paper"]["scenes"]) == 8
    assert len([d for d in os.listdir(cache) if d.endswith(".exact")]) == 8
