"""@brief The data of a conformance page (templates/conform.html.j2) from conform.json of `beamimpact
conform` (verification/matrix/conform.cc). conform.json, as proposed for conform.cc to write beside
its junit.xml:
  {"method": NAME, "origin": methods.toml, "command": CLI, "version": kVersion, "made": UTC,
   "timeout_seconds": s, "rules": [{"rule": NAME, "definition": text}]   (protocol_rules()),
   "results": [{"rule", "scene", "file", "passed": bool, "message"}]     (RuleResult),
   "counts": {"checks": n, "broken": n}}
Fields this page does not know are listed as they are, never fatal."""
import json

from figure_sets import InputProblem

TOP = ("method", "origin", "command", "version", "made", "timeout_seconds", "rules", "results", "counts")
RESULT = ("rule", "scene", "file", "passed", "message")


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
    broken = sum(not r["passed"] for r in doc["results"])
    return {"doc": doc, "rules": [(rule, defs.get(rule, ""), rs) for rule, rs in rules], "broken": broken,
            "checks": len(doc["results"]),
            "extra": [(k, v if isinstance(v, str) else json.dumps(v)) for k, v in doc.items() if k not in TOP]}
