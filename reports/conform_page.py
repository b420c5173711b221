"""@brief The data of a conformance page (templates/conform.html.j2) from conform.json of `beamimpact
conform` (verification/matrix/conform.cc write_conform_reports, beside its junit.xml):
  {"method": NAME, "origin": methods.toml, "command": CLI, "version": kVersion, "made": UTC,
   "timeout_seconds": s, "verdict": "passed" | "failed",
   "rules": [{"rule": NAME, "definition": text}]                                    (protocol_rules()),
   "results": [{"rule", "scene", "file", "passed": bool, "not_applicable": bool, "message"}] (RuleResult),
   "counts": {"checks": n, "broken": n, "not_applicable": n}}
Fields this page does not know are listed as they are, never fatal."""
import json

from figure_sets import InputProblem

TOP = ("method", "origin", "command", "version", "made", "timeout_seconds", "verdict", "rules", "results", "counts")
RESULT = ("rule", "scene", "file", "passed", "not_applicable", "message")


def context(doc):
    """@brief Everything the conform template reads: results grouped by rule (broken rules first),
    with the rule's definition. @param doc the parsed conform.json."""
    for k in ("method", "results"):
        if k not in doc:
            raise InputProblem(f"conform.json: key '{k}' missing (expected a `beamimpact conform` result)")
    defs = {r["rule"]: r.get("definition", "") for r in doc.get("rules", [])}
    groups = {}
    for r in doc["results"]:
        if "rule" not in r or "passed" not in r:
            raise InputProblem("conform.json: a result lacks 'rule' or 'passed'")
        groups.setdefault(r["rule"], []).append(
            {**r, "extra": [(k, json.dumps(v)) for k, v in r.items() if k not in RESULT]})
    for rule in defs:
        groups.setdefault(rule, [])
    rules = sorted(groups.items(), key=lambda kv: (all(x["passed"] for x in kv[1]), list(defs).index(kv[0])
                                                   if kv[0] in defs else len(defs)))
    checked = [r for r in doc["results"] if not r.get("not_applicable")]
    counts = doc.get("counts") or {}
    broken = counts.get("broken", sum(not r["passed"] for r in checked))
    checks = counts.get("checks", len(checked))
    not_applicable = counts.get("not_applicable", len(doc["results"]) - len(checked))
    passed = doc.get("verdict", "failed" if broken else "passed") == "passed"
    line = (f"conform {doc['method']}: {'passed' if passed else 'FAILED'}: {checks} check(s), {broken} broken"
            + (f", {not_applicable} scene(s) not applicable" if not_applicable else ""))
    return {"doc": doc, "rules": [(rule, defs.get(rule, ""), rs) for rule, rs in rules], "broken": broken,
            "checks": checks, "passed": passed, "verdict_line": line,
            "extra": [(k, v if isinstance(v, str) else json.dumps(v)) for k, v in doc.items() if k not in TOP]}
