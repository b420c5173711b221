"""@brief The data of a method's scorecard page (templates/scorecard.html.j2) from scorecard.json of
`beamimpact score` (verification/matrix/scorecard.cc). Fields this page does not know (a newer
scorecard.json) are listed as they are, at the level they appear, never dropped and never fatal."""
import json

from figure_sets import InputProblem

TOP = ("method", "origin", "command", "version", "made", "sets", "references", "wall_seconds", "counts",
       "scenes", "units", "ida_reference")
SCENE = ("scene", "file", "run", "reference", "reference_kind", "reference_check", "tolerances_from", "status",
         "message", "solver_seconds", "process_seconds", "steps", "dt", "quantities")
QUANTITY = ("metric", "error", "tol", "reference_spread", "status", "note")
IDA_REFERENCE = {  # ida_reference() of scorecard.cc, for a scorecard.json that does not carry the text
    "converged": "IDA converged beyond its defaults (rtol 1e-10, atol 1e-13, kn_factor 1e4, friction_velocity "
                 "1e-5 m/s), checked against itself at the case's penalty",
    "matrix": "IDA at the matrix case's own settings",
}
STATUS_CLASS = {"pass": "pass", "fail": "fail", "failed": "fail", "reference uncertain": "unc"}


def extra(obj, known):
    """@brief The fields of `obj` outside `known`, as (key, compact JSON text)."""
    return [(k, v if isinstance(v, str) else json.dumps(v)) for k, v in obj.items() if k not in known]


def context(card):
    """@brief Everything the scorecard template reads. @param card the parsed scorecard.json."""
    for k in ("method", "command", "version", "scenes"):
        if k not in card:
            raise InputProblem(f"scorecard.json: key '{k}' missing (expected a `beamimpact score` result)")
    rows = []
    for s in card["scenes"]:
        for q in s.get("quantities", []) or [{}]:
            rows.append({"scene": s, "q": q, "cls": STATUS_CLASS.get(q.get("status"), "na"),
                         "extra": extra(s, SCENE) + extra(q, QUANTITY)})
    counts = card.get("counts") or {}
    return {"card": card, "rows": rows, "tally": ", ".join(f"{n} {k}" for k, n in counts.items()),
            "ida": card.get("ida_reference") or IDA_REFERENCE.get(card.get("references"), "IDA"),
            "extra": extra(card, TOP)}
