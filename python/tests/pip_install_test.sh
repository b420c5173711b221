#!/usr/bin/env bash
# @brief ctest python_pip_install: `pip install --no-build-isolation .` into a fresh virtual
# environment made with --system-site-packages (numpy, matplotlib from Debian), then, from another
# directory, imports beamimpact from that environment and runs S1 against theory.
# Usage: python/tests/pip_install_test.sh BUILD_DIR
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
build=$(cd "${1:?usage: pip_install_test.sh BUILD_DIR}" && pwd)
venv=$build/pip-test-venv
rm -rf "$venv" && /usr/bin/python3 -m venv --system-site-packages "$venv"
cd "$root"
BEAMIMPACT_BUILD_DIR=$build BEAMIMPACT_JOBS=1 "$venv/bin/pip" install --no-build-isolation --no-index -q . \
  > "$build/pip-install.log" 2>&1 || { cat "$build/pip-install.log"; echo "pip install: failed"; exit 1; }
cd "$venv"
"$venv/bin/python" - "$root/verification/scenes/paper/s1_central.toml" "$venv" <<'PY'
import sys
import beamimpact
scene, venv = sys.argv[1], sys.argv[2]
assert beamimpact.__file__.startswith(venv), f"imported {beamimpact.__file__}, not the installed package"
exact = beamimpact.run(scene, method="exact", progress=False).summary["contacts"][0]["impulse_normal"]
paper = beamimpact.run(scene, progress=False).summary["contacts"][0]["impulse_normal"]
# S1, two equal free rods (references.md 1): the exact impulse is m v0 / 2 = 4 N s; the paper's
# 10-element mesh loses 3.6 % of it (the matrix's S1 mesh ladder: 3.6, 2.1, 1.2, 0.59 %).
assert abs(exact - 4.0) < 1e-9, exact
assert 0.95 * 4.0 < paper < 4.0, paper
print(f"pip install: beamimpact {beamimpact.__version__} from {beamimpact.__file__}: S1 impulse {paper:.4f} N s (exact {exact:g})")
PY
shown=$("$venv/bin/pip" show beamimpact)  # whole output first: grep -q closing the pipe early breaks pip
grep -q "^Version: " <<<"$shown" || { echo "pip install: pip does not list beamimpact"; exit 1; }
