"""@brief The data of a method's scorecard page (templates/scorecard.html.j2) from scorecard.json of
`beamimpact score` (verification/matrix/scorecard_output.cc) and, when present, the diagrams'
manifest figures.json of reports/scorecard_figures.py. Fields this page does not know (a newer
scorecard.json) are listed as they are, at the level they appear, never dropped and never fatal."""
import base64
import json
import os

from figure_sets import InputProblem

TOP = ("method", "origin", "command", "version", "made", "sets", "references", "ladder", "rungs", "reference_cache",
       "wall_seconds", "verdict", "verdict_line", "exit_code", "counts", "statuses", "scenes", "rules", "units",
       "ida_reference")
SCENE = ("scene", "file", "set", "run", "reference", "reference_kind", "reference_check", "tolerances_from", "ladder",
         "status", "message", "solver_seconds", "process_seconds", "steps", "dt", "quantities")
QUANTITY = ("metric", "error", "tol", "uncertainty", "reference_spread", "status", "judged", "exact", "allowed", "note",
            "ladder")
SCENE_LADDER = ("kind", "why", "rungs")
RUNG = ("run", "status", "dt", "steps", "solver_seconds", "process_seconds")
QUANTITY_LADDER = ("values", "order", "limit", "limit_uncertainty", "why_not")
FIGURE = ("png", "title", "command", "scene", "version")
IDA_REFERENCE = {  # ida_reference() of scorecard.cc, for a scorecard.json that does not carry the text
    "converged": "IDA converged beyond its defaults (rtol 1e-10, atol 1e-13, kn_factor 1e4, friction_velocity "
                 "1e-5 m/s), checked against itself at the case's penalty",
    "matrix": "IDA at the matrix case's own settings",
}
STATUS_CLASS = {"pass": "pass", "fail": "fail", "failed": "fail", "not converged": "fail",
                "reference uncertain": "unc", "skipped": "unc"}
TIGHTEST = 5  # passing quantities shown after the failing ones, closest to their tolerance first


def extra(obj, known):
    """@brief The fields of `obj` outside `known`, as (key, compact JSON text); none for a non-object."""
    if not isinstance(obj, dict):
        return []
    return [(k, v if isinstance(v, str) else json.dumps(v)) for k, v in obj.items() if k not in known]


def margin(q):
    """@brief How much of its allowance a quantity's error uses, in words and as a bar: against the
    tolerance, or for a ladder's limit against what the limit may miss by (`allowed`: 1.25 x its
    uncertainty + tol / 10). @return {"ratio", "words", "width" (0-100, % of the bar), "over"} or
    None when the quantity has no error or no allowance."""
    error = q.get("error")
    limit = q.get("judged") == "limit" and q.get("allowed") is not None
    basis = q.get("allowed") if limit else q.get("tol")
    if error is None or basis is None:
        return None
    what = "the limit's allowance" if limit else "the tolerance"
    if basis <= 0:
        if error <= 0:
            return {"ratio": 0.0, "words": "exact (tolerance 0)", "width": 0, "over": False}
        return {"ratio": float("inf"), "words": "over a tolerance of 0", "width": 100, "over": True}
    ratio = error / basis
    if ratio <= 1:
        words = f"uses {100 * ratio:.2g} % of {what}"
    else:
        words = f"{ratio:.3g} \u00d7 {what}: over"
    return {"ratio": ratio, "words": words, "width": round(100 * min(ratio, 1.0)), "over": ratio > 1}


def is_failing(q):
    """@brief A quantity whose status is neither a pass nor not applicable (it sets exit code 1)."""
    return q.get("status") not in ("pass", "not applicable")


def tightest(rows):
    """@brief The rows a reader looks at first: every failing or undecided quantity, then the
    TIGHTEST passing ones closest to their allowance."""
    def key(r):
        return -(r["margin"]["ratio"] if r["margin"] else float("-inf"))
    bad = sorted((r for r in rows if r["q"] and is_failing(r["q"])), key=key)
    good = sorted((r for r in rows if r["q"] and not is_failing(r["q"]) and r["margin"]), key=key)
    return bad + good[:TIGHTEST]


def ladders(scenes):
    """@brief Each ladder scene's rungs and, per quantity judged on it, the rungs' values, the
    observed order and the limit. @param scenes scorecard.json's scenes."""
    out = []
    for s in scenes:
        lad = s.get("ladder") if isinstance(s.get("ladder"), dict) else {}
        rungs = lad.get("rungs") or []
        if not rungs:
            continue
        qs = [q for q in s.get("quantities", []) if isinstance(q.get("ladder"), dict)]
        out.append({"scene": s, "kind": lad.get("kind", ""), "why": lad.get("why", ""), "extra": extra(lad, SCENE_LADDER),
                    "rungs": [{**r, "extra": extra(r, RUNG)} for r in rungs],
                    "quantities": [{"q": q, "l": q["ladder"], "extra": extra(q["ladder"], QUANTITY_LADDER)} for q in qs]})
    return out


def figures(manifest, folder):
    """@brief The diagrams of the manifest, each PNG embedded (data: URI) so that the page stays one
    file. @param manifest figures.json of reports/scorecard_figures.py, or None @param folder its folder"""
    if manifest is None:
        return None
    figs = []
    for f in manifest.get("figures", []):
        for k in FIGURE:
            if k not in f:
                raise InputProblem(f"{folder}/figures.json: a figure lacks '{k}' (each needs {', '.join(FIGURE)})")
        path = os.path.join(folder, f["png"])
        try:
            with open(path, "rb") as fh:
                data = base64.b64encode(fh.read()).decode()
        except OSError:
            raise InputProblem(f"{folder}/figures.json: figure '{f['png']}' not found") from None
        figs.append({**f, "src": "data:image/png;base64," + data})
    return {**manifest, "figures": figs}


def shown(status, words):
    """@brief A status as the page says it: the reader's words scorecard.json gives for it
    ("statuses": "fail (outside tolerance)", "run failed", ...), else the word itself."""
    return words.get(status, status) if isinstance(words, dict) else status


def legend(words):
    """@brief The legend's statuses by colour class, in the reader's words."""
    groups = {"pass": [], "fail": [], "unc": [], "na": []}
    for status in ("pass", "fail", "failed", "not converged", "reference uncertain", "skipped", "not applicable"):
        groups[STATUS_CLASS.get(status, "na")].append(shown(status, words))
    groups["na"].append("not judged")
    return [(cls, ", ".join(names)) for cls, names in groups.items()]


def context(card, manifest=None, folder="."):
    """@brief Everything the scorecard template reads. @param card the parsed scorecard.json
    @param manifest the parsed figures.json beside it, or None @param folder the scorecard's folder"""
    for k in ("method", "command", "version", "scenes"):
        if k not in card:
            raise InputProblem(f"scorecard.json: key '{k}' missing (expected a `beamimpact score` result)")
    rows, words = [], card.get("statuses")
    for s in card["scenes"]:
        for q in s.get("quantities", []) or [{}]:
            status = q.get("status", s.get("status", ""))
            rows.append({"scene": s, "q": q, "cls": STATUS_CLASS.get(status, "na"), "status": shown(status, words),
                         "margin": margin(q) if q else None,
                         "extra": extra(s, SCENE) + extra(q, QUANTITY) + extra(q.get("ladder"), QUANTITY_LADDER)})
    counts = card.get("counts") or {}
    tally = ", ".join(f"{n} {k}" for k, n in counts.items())
    if "exit_code" in card:
        passed = card["exit_code"] == 0
    else:
        passed = card.get("verdict", "passed" if rows and not any(r["q"] and is_failing(r["q"]) for r in rows)
                          else "failed") == "passed"
    line = card.get("verdict_line") or f"score {card['method']}: {'PASSED' if passed else 'FAILED'} ({tally})"
    return {"card": card, "rows": rows, "tally": tally, "passed": passed, "verdict_line": line,
            "tightest": tightest(rows), "ladders": ladders(card["scenes"]),
            "rules": list((card.get("rules") or {}).items()), "units": list((card.get("units") or {}).items()),
            "ida": card.get("ida_reference") or IDA_REFERENCE.get(card.get("references"), "IDA"),
            "figures": figures(manifest, folder), "extra": extra(card, TOP), "legend": legend(words),
            "shown": lambda status: shown(status, words)}
