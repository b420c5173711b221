#!/usr/bin/env bash
# @brief The CI recipe as an outside team runs it: examples/ci copied to an empty folder outside
# the clone, gate.sh with the beamimpact program on PATH. The honest solver passes its gate (exit
# 0); a copy whose contact force is 2 % too large (consistently in history.csv and summary.json,
# so that it breaks no protocol rule) fails it with exit 1, naming the quantity.
# Usage: gate_test.sh EXAMPLE_DIR PROGRAM_DIR
set -uo pipefail
src=$(cd "$1" && pwd)
export PATH="$(cd "$2" && pwd):$PATH"
d=$(mktemp -d)
trap 'rm -rf "$d"' EXIT
cp -r "$src/." "$d/honest"
cp -r "$src/." "$d/wrong"
if ! (cd "$d/honest" && bash gate.sh out) > "$d/honest.log" 2>&1; then
  cat "$d/honest.log"
  echo "gate_test: the honest solver failed its gate (expected exit 0)"
  exit 1
fi
# The pages the workflow keeps (github-workflow.yml): made by the program's page generator.
for page in score/scorecard.html conform/conform.html; do
  grep -q "passed\|PASSED" "$d/honest/out/$page" 2>/dev/null ||
    { cat "$d/honest.log"; echo "gate_test: no page out/$page with the gate's verdict"; exit 1; }
done
# The wrong copy: the same solver, its contact force scaled by 1.02 in every output.
cat > "$d/wrong/wrong_solver.py" <<'PY'
import csv, json, os, subprocess, sys
here = os.path.dirname(os.path.abspath(__file__))
code = subprocess.run([sys.executable, os.path.join(here, "solver.py")] + sys.argv[1:]).returncode
if code != 0:
    sys.exit(code)
out = sys.argv[sys.argv.index("--out") + 1]
with open(os.path.join(out, "history.csv")) as f:
    rows = list(csv.reader(f))
scaled = [i for i, n in enumerate(rows[0]) if n.split("_")[0] in ("R", "impulse") and n != "R_variation"]
with open(os.path.join(out, "history.csv"), "w") as f:
    f.write(",".join(rows[0]) + "\n")
    for r in rows[1:]:
        f.write(",".join(repr(float(x) * 1.02) if i in scaled else x for i, x in enumerate(r)) + "\n")
with open(os.path.join(out, "summary.json")) as f:
    s = json.load(f)
for c in s["contacts"]:
    for k in ("impulse_normal", "peak_R", "peak_R_excluding_closure"):
        if k in c:
            c[k] *= 1.02
    if "interval_impulses" in c:
        c["interval_impulses"] = [j * 1.02 for j in c["interval_impulses"]]
with open(os.path.join(out, "summary.json"), "w") as f:
    json.dump(s, f, indent=1)
PY
sed -i 's#{here}/solver.py#{here}/wrong_solver.py#' "$d/wrong/methods.toml"
(cd "$d/wrong" && bash gate.sh out) > "$d/wrong.log" 2>&1
code=$?
if [[ $code != 1 ]] || ! grep -qE "impulse.*(fail|grew)" "$d/wrong.log"; then
  cat "$d/wrong.log"
  echo "gate_test: the solver with a 2 % force error gave exit $code (expected 1 naming the impulse)"
  exit 1
fi
grep -E "^score mysolver|impulse.*(fail|grew)" "$d/wrong.log" | head -5
echo "gate_test: the honest solver passes its gate; 2 % more force fails it (exit 1)"
