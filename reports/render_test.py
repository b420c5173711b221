"""The page generator's pieces on fixtures worked by hand: the study's breakdown range, the cost
grid's cells and headline set, the ladders flagged as not converging, the report page rendered from
the fixture verify run (verdict first, failing gate first, figures as files, provenance counted),
bad input refused with exit 2, and the scorecard and conform pages (unknown fields listed)."""
import copy
import glob
import html.parser
import json
import os
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "reports"))
import breakdown  # noqa: E402
import cost_grid  # noqa: E402
import report_page  # noqa: E402

RENDER = os.path.join(ROOT, "reports", "render.py")
FIXTURE = os.path.join(ROOT, "reports", "testdata", "verify")


def render(*args):
    return subprocess.run(["/usr/bin/python3", RENDER, *args], cwd=ROOT, capture_output=True, text=True)


class Tags(html.parser.HTMLParser):
    """Section ids in order, img srcs, and the text of the table id=tightest's rows."""

    def __init__(self):
        super().__init__()
        self.sections, self.imgs, self.rows, self._in = [], [], [], False

    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        if tag == "section":
            self.sections.append(a.get("id"))
        elif tag == "img":
            self.imgs.append(a["src"])
        elif tag == "table":
            self._in = a.get("id") == "tightest"
        elif tag == "tr" and self._in:
            self.rows.append("")

    def handle_endtag(self, tag):
        if tag == "table":
            self._in = False

    def handle_data(self, data):
        if self._in and self.rows:
            self.rows[-1] += data


def test_excess_range_is_the_run_with_most_breakdowns_above_the_rate():
    # 10 of 50 cases broke: rate 0.2, so the excess per x is -2, +2, +3, -2, -1; the best run is x 10..20.
    assert breakdown.excess_range([0, 10, 20, 30, 40], [0, 4, 5, 0, 1], [10] * 5) == (10, 20, 9, 20)
    # No breakdown anywhere: no range.
    assert breakdown.excess_range([0, 10], [0, 0], [5, 5]) is None


def test_cost_cells_say_bound_ratio_not_reached_and_not_run():
    e = {"impulse_error": 0.01, "cpu_s": {"paper": 2.914e-4, "IDA": 0.0294, "Siconos": None},
         "upper_bound": {"paper": True, "IDA": False}, "ratio_to_paper": {"IDA": 101.0},
         "ratio_range": {"IDA": [37.9, 105.0]}}
    assert cost_grid.cell(e, "paper")["s"] == "≤ 0.291 ms" and cost_grid.cell(e, "paper")["ratio"] == "1×"
    ida = cost_grid.cell(e, "IDA")
    assert (ida["s"], ida["ratio"], ida["range"]) == ("29.4 ms", "101×", "37.9–105×")
    assert cost_grid.ratio_text(3521.5) == "3,520×" and cost_grid.ratio_text(0.0255) == "1/39.2×"
    assert cost_grid.cell(e, "Siconos")["state"] == "not_reached"
    assert cost_grid.cell(e, "FEniCSx")["state"] == "not_run"


def test_headline_is_the_set_where_most_methods_reach_one_percent():
    def grid(name, dofs, reached):
        cells = [{"state": "ok" if i < reached else "not_reached"} for i in range(4)]
        return {"name": name, "dofs": dofs, "rows": [{"impulse_error": 0.01, "cells": cells},
                                                     {"impulse_error": 0.03, "cells": cells}]}
    h = cost_grid.headline([grid("a", 10, 3), grid("b", 1000, 2), grid("c", 100, 3)])
    assert h["name"] == "c"  # three methods in a and c; c is the larger model
    assert [r["impulse_error"] for r in h["rows"]] == [0.01]  # the 3 % row is not a verdict level


def test_flat_ladders_flag_a_time_ladder_whose_error_grows_and_not_a_converging_mesh_ladder():
    def pts(method, errs):
        return [{"method": method, "status": "ok", "error": {"impulse": e}} for e in errs]
    res = {"points": pts("paper (dt ladder)", [0.010, 0.011, 0.012]) + pts("paper (mesh ladder)", [0.02, 0.01])
           + pts("FEniCSx (meshes)", [0.010, 0.0085])}  # 15 % gain: under the 20 % a falling ladder needs
    flat = {f["method"]: f for f in cost_grid.flat_ladders(res)}
    assert set(flat) == {"paper (dt ladder)", "FEniCSx (meshes)"}
    assert "mesh (spatial) error dominates" in flat["paper (dt ladder)"]["why"]
    assert "another error dominates" in flat["FEniCSx (meshes)"]["why"]


def test_a_ladder_row_says_what_it_is_judged_against():
    # Items as verify writes them (Convergence::name(): scene, method, rungs, " vs REFERENCE" when it
    # has one): a ladder against the exact answer is not labelled self-convergence, one without is.
    gate = {"metric": "impulse", "margin": 0.5, "passed": True, "status": "pass"}
    exact = {"kind": "convergence", "scene": "s1_central", "name": "s1_central paper dt=0.01/0.005 vs exact",
             "settings": "paper dt=0.01", "reference": "exact", "gates": [gate]}
    own = dict(exact, name="s1_central paper dt=0.01/0.005", reference="")
    case = {"kind": "case", "scene": "s1_central", "name": "s1_central/paper", "settings": "paper dt=0.01",
            "reference": "exact", "gates": [gate]}
    rows = report_page.gate_rows({"items": [exact, own, case]})
    assert [(r["run"], r["against"]) for r in rows] == [
        ("paper dt=0.01/0.005 (ladder: each rung against exact)", "exact"),
        ("paper dt=0.01/0.005 (self-convergence: each rung against the next finer)", "-"),
        ("paper dt=0.01", "exact")]
    assert [r["reference"] for r in rows] == ["exact", "", "exact"]  # the raw field, for the promise's count


def test_report_opens_with_the_verdict_and_the_failing_gate(tmp_path):
    out = tmp_path / "report.html"
    r = render("report", "--verify", FIXTURE, "--committed", "--out", str(out))
    assert r.returncode == 0, r.stderr
    text = out.read_text()
    t = Tags()
    t.feed(text)
    assert t.sections[:3] == ["verdict", "where", "cost"]
    assert "FAIL 1/2" in text  # the fixture: two gates, one failing
    assert t.rows[1].startswith("s2_transverse") and "fail" in t.rows[1]  # the failing gate leads (after the header)
    assert "data:image" not in text and t.imgs
    for src in t.imgs:
        assert os.path.isfile(tmp_path / src), src
    # Figures of the committed sets, counted from their manifests; none has the fixture's version.
    n = sum(len(json.load(open(m))["figures"]) for m in glob.glob(os.path.join(ROOT, "reports", "*", "figures.json")))
    assert f"0 of {n} figures made by this run" in text


def test_norms_without_margins_are_refused(tmp_path):
    with open(os.path.join(FIXTURE, "norms.json")) as f:
        norms = json.load(f)
    old = copy.deepcopy(norms)
    del old["items"][0]["gates"][0]["margin"]
    (tmp_path / "v").mkdir()
    (tmp_path / "v" / "norms.json").write_text(json.dumps(old))
    r = render("report", "--verify", str(tmp_path / "v"), "--out", str(tmp_path / "r.html"))
    assert r.returncode == 2 and "margin" in r.stderr


class Tables(html.parser.HTMLParser):
    """Every table's rows as lists of cell texts, in order and by the table's id or class (the first of
    that name); section ids in order."""

    def __init__(self):
        super().__init__()
        self.tables, self.all, self.sections, self._t, self._cell = {}, [], [], None, False

    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        if tag == "section":
            self.sections.append(a.get("id"))
        elif tag == "table":
            self._t = []
            self.all.append(self._t)
            self.tables.setdefault(a.get("id") or a.get("class"), self._t)
        elif tag == "tr" and self._t is not None:
            self._t.append([])
        elif tag in ("td", "th") and self._t is not None and self._t:
            self._t[-1].append("")
            self._cell = True

    def handle_endtag(self, tag):
        if tag == "table":
            self._t = None
        elif tag in ("td", "th") and self._t and self._t[-1]:
            self._t[-1][-1] = self._t[-1][-1].strip()
            self._cell = False

    def handle_data(self, data):
        if self._cell and self._t and self._t[-1]:
            self._t[-1][-1] += data


SCORECARD = os.path.join(ROOT, "reports", "testdata", "scorecard")


def render_fixture(tmp_path, page, doc):
    (tmp_path / f"{page}.json").write_text(json.dumps(doc))
    r = render(page, str(tmp_path))
    assert r.returncode == 0, r.stderr
    text = (tmp_path / f"{page}.html").read_text()
    t = Tables()
    t.feed(text)
    return text, t


def test_scorecard_page_opens_with_the_verdict_then_the_failing_quantity(tmp_path):
    with open(os.path.join(SCORECARD, "scorecard.json")) as f:
        card = json.load(f)
    text, t = render_fixture(tmp_path, "scorecard", card)
    assert t.sections[:2] == ["verdict", "tightest"]
    assert "score demo: FAILED: 1 of 3 quantities failed (fixture)" in text.split('<section id="tightest">')[0]
    # The fixture's one failing quantity leads: S2's peak_R, error 0.062 against 0.05, 0.062 / 0.05 = 1.24 over.
    first = t.tables["first"][1]
    assert first[:3] == ["s2_transverse", "peak_R", "fail"] and first[4:6] == ["0.062", "0.05"]
    assert "1.24 × the tolerance: over" in first[3]
    # Then the passing ones, tightest first: S2 impulse 0.01 / 0.04 = 25 %; the S1 limit's error
    # 1e-4 against its allowance 1.25 x 2e-4 + 0.04 / 10 = 4.25e-3 uses 2.4 %.
    assert [r[:2] for r in t.tables["first"][2:]] == [["s2_transverse", "impulse"], ["s1_central", "impulse"]]
    assert "uses 25 % of the tolerance" in t.tables["first"][2][3]
    assert "uses 2.4 % of the limit's allowance" in t.tables["first"][3][3]
    # The whole table: one row a quantity, how each was judged.
    rows = t.tables["scorecard"][1:]
    assert [(r[0], r[2], r[3]) for r in rows] == [("s1_central", "impulse", "limit of a ladder"),
                                                  ("s2_transverse", "peak_R", "single run"),
                                                  ("s2_transverse", "impulse", "single run")]
    assert "fixture rule for the limit" in text and "s, fixture unit text" in text
    assert "IDA converged beyond its defaults (fixture text)" in text


def test_scorecard_page_shows_a_ladders_rungs_order_and_limit(tmp_path):
    with open(os.path.join(SCORECARD, "scorecard.json")) as f:
        card = json.load(f)
    _, t = render_fixture(tmp_path, "scorecard", card)
    # The fixture's S1 ladder: rungs 3.9204, 3.9804, 3.9954 differ by 0.06 then 0.015 (ratio 4:
    # order 2), limit 3.9954 + 0.015 / (2^2 - 1) = 4.0004.
    rungs = t.tables["rungs"][1:]
    assert [(r[1], r[2], r[3], r[7]) for r in rungs] == [("demo n=10", "0.004", "500", "3.9204"),
                                                         ("demo n=20", "0.002", "1000", "3.9804"),
                                                         ("demo n=40", "0.001", "2000", "3.9954")]
    order = t.tables["orders"][1]
    assert order[:5] == ["impulse", "2", "4.0004", "0.0002", "4"]


def test_scorecard_page_says_the_statuses_in_the_words_the_scorecard_gives(tmp_path):
    # scorecard.json's "statuses" (verification/matrix/quantity_status.cc describe()): a quantity
    # outside its tolerance reads "fail (outside tolerance)", a run that did not finish "run failed",
    # never "fail" beside "failed"; the JSON words themselves stay as they are.
    with open(os.path.join(SCORECARD, "scorecard.json")) as f:
        card = json.load(f)
    card["statuses"] = {"pass": "pass", "fail": "fail (outside tolerance)", "failed": "run failed"}
    card["scenes"][0]["quantities"][0]["status"] = "failed"
    text, t = render_fixture(tmp_path, "scorecard", card)
    rows = t.tables["scorecard"][1:]
    shown = {(r[0], r[2]): r[8] for r in rows}
    assert shown[("s2_transverse", "peak_R")] == "fail (outside tolerance)"
    assert shown[("s1_central", "impulse")] == "run failed"
    assert t.tables["first"][1][2] in ("fail (outside tolerance)", "run failed")
    legend = text.split('<p class="legend">')[1].split("</p>")[0]
    assert "fail (outside tolerance), run failed, not converged" in legend
    assert '<section id="other">' not in text  # "statuses" is a field the page knows


def test_scorecard_page_lists_fields_it_does_not_know(tmp_path):
    with open(os.path.join(SCORECARD, "scorecard.json")) as f:
        card = json.load(f)
    card["ladders_v2"] = {"s1_central": [0.1, 0.05]}
    card["scenes"][0]["ladder_orders"] = [1.0, 1.1]
    card["scenes"][0]["quantities"][0]["ladder"]["richardson_ratio"] = 4.0
    card["scenes"][0]["ladder"]["rungs"][0]["memory_mb"] = 12
    text, t = render_fixture(tmp_path, "scorecard", card)
    for k in ("ladders_v2", "ladder_orders", "richardson_ratio", "memory_mb"):
        assert k in text, k
    assert len(t.tables["scorecard"]) - 1 == sum(len(s["quantities"]) for s in card["scenes"])


def test_scorecard_page_embeds_the_diagrams_of_its_manifest(tmp_path):
    import base64
    with open(os.path.join(SCORECARD, "scorecard.json")) as f:
        card = json.load(f)
    png = base64.b64decode("iVBORw0KGgoAAAANSUhEUgAAAAEAAAABCAYAAAAfFcSJAAAADUlEQVR42mNk+M9QDwADhgGAWjR9awAAAABJRU5ErkJggg==")
    (tmp_path / "s1.png").write_bytes(png)
    (tmp_path / "figures.json").write_text(json.dumps({"title": "Diagrams", "figures": [
        {"png": "s1.png", "scene": "s1_central", "title": "S1 diagram", "command": "fixture-command --x",
         "version": "0.0.0+fixture", "made": "2026-01-01T00:00:00Z", "caption": "fixture caption"}]}))
    text, _ = render_fixture(tmp_path, "scorecard", card)
    assert text.count('<img alt="S1 diagram" src="data:image/png;base64,') == 1
    assert "fixture-command --x" in text and "fixture caption" in text  # how it was made: the caption's
    (tmp_path / "s1.png").unlink()
    r = render("scorecard", str(tmp_path))
    assert r.returncode == 2 and "s1.png" in r.stderr


def test_conform_page_opens_with_the_verdict_and_puts_the_broken_rule_first(tmp_path):
    doc = {"method": "demo", "command": "beamimpact conform demo", "version": "test", "verdict": "failed",
           "rules": [{"rule": "exit code", "definition": "0 done; 2 refused; 3 failed"},
                     {"rule": "columns", "definition": "t and R first"}],
           "results": [{"rule": "exit code", "scene": "a", "file": "run.log", "passed": True, "not_applicable": False,
                        "message": ""},
                       {"rule": "exit code", "scene": "b", "file": "", "passed": True, "not_applicable": True,
                        "message": "refused (exit 2)"},
                       {"rule": "columns", "scene": "a", "file": "history.csv", "passed": False,
                        "not_applicable": False, "message": "no column R"}],
           "counts": {"checks": 2, "broken": 1, "not_applicable": 1}}
    text, t = render_fixture(tmp_path, "conform", doc)
    assert t.sections[0] == "verdict"
    assert "conform demo: FAILED: 2 check(s), 1 broken, 1 scene(s) not applicable" in text
    assert text.index("columns:") < text.index("exit code:")
    assert "t and R first" in text and "no column R" in text
    verdicts = [r[2] for rows in t.all for r in rows[1:]]
    assert verdicts == ["broken", "holds", "not applicable"]
