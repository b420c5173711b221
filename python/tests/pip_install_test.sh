#!/usr/bin/env bash
# @brief ctest python_pip_install: `pip install --no-build-isolation .` into a fresh virtual
# environment made with --system-site-packages (numpy, matplotlib from Debian), both outside the
# clone, then, from an empty folder outside the clone, everything a user does with the install:
# the program (methods, scenes, run by name and by path, verify, examples/ci's gate), the module (data_root, methods,
# run by name, verify with no environment variable), pip show's licence. Checked against theory.
# Usage: python/tests/pip_install_test.sh BUILD_DIR [--whole-tier]
#   The module's verify(tier="quick") runs the S1 items of the quick tier; --whole-tier runs all of
#   it, as `python -c "import beamimpact; beamimpact.verify(tier='quick')"` does (ctest
#   python_pip_install_quick_tier, label full: 4 min 53 s at load 11-14 with a built BUILD_DIR).
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
build=$(cd "${1:?usage: pip_install_test.sh BUILD_DIR [--whole-tier]}" && pwd)
only=s1_central
[[ ${2:-} == --whole-tier ]] && only=""
# Outside the clone: a data root found by walking up from the clone would hide a missing install.
tmp=$(mktemp -d "${TMPDIR:-/tmp}/beamimpact-pip-test.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
venv=$tmp/venv work=$tmp/work
mkdir "$work"
/usr/bin/python3 -m venv --system-site-packages "$venv"
cd "$root"
BEAMIMPACT_BUILD_DIR=$build BEAMIMPACT_JOBS=1 "$venv/bin/pip" install --no-build-isolation --no-index -q . \
  > "$build/pip-install.log" 2>&1 || { cat "$build/pip-install.log"; echo "pip install: failed"; exit 1; }
cd "$work"
fail() { echo "pip install: $*"; exit 1; }
exe=$venv/bin/beamimpact
[[ -x $exe ]] || fail "no program $exe"
head -c 4 "$exe" | grep -q ELF || fail "$exe is not the compiled program"
# Every method of the shipped methods file is listed, declared by the installed file.
methods=$("$exe" methods)
for m in paper exact ida fenicsx siconos example getfem; do
  grep -q "^$m " <<<"$methods" || fail "beamimpact methods does not list $m:"$'\n'"$methods"
done
grep -q "from: $venv/share/beamimpact/verification/methods.toml" <<<"$methods" ||
  fail "the methods file is not the installed one:"$'\n'"$methods"
scenes=$("$exe" scenes)
grep -q "^s1_central .*$venv/share/beamimpact/verification/scenes/paper/s1_central.toml" <<<"$scenes" ||
  fail "beamimpact scenes does not list the installed S1:"$'\n'"$scenes"
# A shipped scene by name and by its repository path, from a folder that has neither.
"$exe" run s1_central --method exact --out by-name --quiet
"$exe" run verification/scenes/paper/s1_central.toml --out by-path --quiet
impulse() { /usr/bin/python3 -c "import json,sys; print(json.load(open(sys.argv[1]))['contacts'][0]['impulse_normal'])" "$1"; }
# S1, two equal free rods (references.md 1): the exact impulse is m v0 / 2 = 4 N s; the paper's
# 10-element mesh loses 3.6 % of it (the matrix's S1 mesh ladder: 3.6, 2.1, 1.2, 0.59 %).
[[ $(impulse by-name/summary.json) == 4.0 ]] || fail "run s1_central --method exact: impulse $(impulse by-name/summary.json), expected 4 N s"
/usr/bin/python3 -c "import sys; v = float(sys.argv[1]); sys.exit(not 0.95 * 4 < v < 4)" "$(impulse by-path/summary.json)" ||
  fail "run by path: paper impulse $(impulse by-path/summary.json), expected 3.8-4 N s"
"$exe" verify --tier quick --only s1_central --out verify-s1 --jobs 2 --baseline "$root/verification/baselines/quick.json" \
  > verify-s1.log || { cat verify-s1.log; fail "verify --only s1_central failed"; }
# The CI recipe of an outside solver's repository against the installed program: its gate passes
# for the honest solver and fails for one with 2 % more contact force (examples/ci/gate_test.sh).
bash "$root/examples/ci/gate_test.sh" "$root/examples/ci" "$venv/bin" > gate.log 2>&1 ||
  { cat gate.log; fail "examples/ci's gate against the installed program"; }
# The module, with no environment variable: data, methods, a run by name, the whole quick tier.
env -u BEAMIMPACT_EXE -u BEAMIMPACT_METHODS -u PYTHONPATH "$venv/bin/python" - "$venv" "$only" <<'PY'
import sys
import beamimpact
venv, only = sys.argv[1], sys.argv[2]
assert beamimpact.__file__.startswith(venv), f"imported {beamimpact.__file__}, not the installed package"
assert str(beamimpact.data_root()) == f"{venv}/share/beamimpact", beamimpact.data_root()
missing = {"paper", "exact", "ida", "fenicsx", "siconos", "example", "getfem"} - set(beamimpact.methods())
assert not missing, f"methods() lacks {missing}: {beamimpact.methods()}"
assert beamimpact.scenes()["s1_central"].is_file(), beamimpact.scenes()
exact = beamimpact.run("s1_central", method="exact", progress=False).summary["contacts"][0]["impulse_normal"]
paper = beamimpact.run("verification/scenes/paper/s1_central.toml", progress=False).summary["contacts"][0]["impulse_normal"]
assert abs(exact - 4.0) < 1e-9, exact  # m v0 / 2, as above
assert 0.95 * 4.0 < paper < 4.0, paper
result = beamimpact.verify(tier="quick", only=only, jobs=2)
assert result["verdict"] == "PASS", [g for i in result["items"] for g in i["gates"] if not g["passed"]][:3]
print(f"pip install: beamimpact {beamimpact.__version__} from {beamimpact.__file__}: S1 impulse {paper:.4f} N s "
      f"(exact {exact:g}); quick tier{' (' + only + ')' if only else ''}: {result['passed']} of {result['gates']} gates passed")
PY
shown=$("$venv/bin/pip" show beamimpact)  # whole output first: grep -q closing the pipe early breaks pip
grep -q "^Version: " <<<"$shown" || fail "pip does not list beamimpact"
grep -q "^License: BSD-3-Clause" <<<"$shown" || fail "pip show prints no BSD-3-Clause licence:"$'\n'"$shown"
echo "pip install: passed (program, scenes, methods, run, verify from $work)"
