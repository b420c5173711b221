#!/usr/bin/env bash
# @brief The install test: `cmake --install` the build into a fresh prefix, build the example
# consumer (examples/consumer) against it with find_package(beamimpact), run it on the shipped
# S1 scene with the exact method and check the impulse against theory (m v0 / 2 = 4 N s); the
# installed `beamimpact score` makes its page with the installed reports/render.py.
# Usage: tools/test-install.sh BUILD_DIR   (run by ctest as install_consumer)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=$(cd "$1" && pwd)
prefix=$build/install-test
rm -rf "$prefix" "$build/consumer"
cmake --install "$build" --prefix "$prefix" > "$build/install-test.log"
# The installed headers are the public API's closure: each one's project includes (a path that
# is a file of the repository, or the generated beamimpact/...) are installed beside it, and no
# internal header (a test helper, a *_impl or detail/ file) is.
inc=$prefix/include/beamimpact
mapfile -t installed < <(cd "$inc" && find . -name '*.hpp' -printf '%P\n' | sort)
((${#installed[@]})) || { echo "install test: no headers under $inc"; exit 1; }
missing=0
for h in "${installed[@]}"; do
  while read -r dep; do
    if [[ -f $root/$dep ]]; then  # one spelling for a consumer: <beamimpact/FOLDER/...>
      echo "install test: $h includes <$dep>; expected <beamimpact/$dep>"; missing=1
    fi
    if { [[ -f $root/$dep ]] && [[ ! -f $inc/$dep ]]; } ||
      { [[ $dep == beamimpact/* ]] && [[ ! -f $prefix/include/$dep ]]; }; then
      echo "install test: $h includes <$dep>, which is not installed"; missing=1
    fi
  done < <(sed -n 's/^#include <\([^>]*\)>.*/\1/p' "$inc/$h")
  case $h in
    solver/testing/* | *_test* | *test_* | *_impl* | */detail/*) echo "install test: internal header $h installed"; missing=1 ;;
  esac
done
# The package's only include directory is include/: a bare <api/run.hpp> does not resolve.
if grep -q 'include/beamimpact"\|include/beamimpact;' "$prefix"/lib*/cmake/beamimpact/beamimpactTargets.cmake; then
  echo "install test: include/beamimpact is an include directory of the package; expected include/ only"; missing=1
fi
((missing == 0)) || exit 1
echo "install test: ${#installed[@]} headers installed, each one's project includes installed too"
cmake -S "$root/examples/consumer" -B "$build/consumer" -DCMAKE_PREFIX_PATH="$prefix" \
  -DCMAKE_BUILD_TYPE=Release >> "$build/install-test.log"
cmake --build "$build/consumer" >> "$build/install-test.log"
scene=$prefix/share/beamimpact/verification/scenes/paper/s1_central.toml
out=$("$build/consumer/print_impulse" "$scene" exact)
echo "$out"
# S1, two equal free rods (references.md 1): the exact impulse is m v0 / 2 = 4 N s.
grep -q "impulse 4 N s (exact)" <<<"$out" || { echo "install test: expected impulse 4 N s"; exit 1; }
# From an empty folder outside the clone: the installed methods file and scenes are found from the
# program's own location (bin/ -> share/beamimpact), a shipped scene runs by name.
empty=$(mktemp -d "${TMPDIR:-/tmp}/beamimpact-install-test.XXXXXX")
methods=$(cd "$empty" && "$prefix/bin/beamimpact" methods)
grep -q "from: $prefix/share/beamimpact/verification/methods.toml" <<<"$methods" ||
  { echo "install test: the installed methods file is not read:"; echo "$methods"; rm -rf "$empty"; exit 1; }
(cd "$empty" && "$prefix/bin/beamimpact" run s1_central --method exact --out s1 --quiet)
imp=$(/usr/bin/python3 -c "import json, sys; print(json.load(open(sys.argv[1]))['contacts'][0]['impulse_normal'])" \
  "$empty/s1/summary.json")
[[ $imp == 4.0 ]] ||
  { echo "install test: run s1_central from $empty: expected impulse 4 N s"; rm -rf "$empty"; exit 1; }
# The installed score makes its page with the installed page generator (share/beamimpact/reports):
# exit 0 or 1 is the verdict (the card's tolerance), the page carries the same verdict line.
for f in $(grep -v '^#' "$root/reports/page_files.txt") templates/scorecard.html.j2 templates/conform.html.j2; do
  [[ -f $prefix/share/beamimpact/reports/$f ]] || { echo "install test: reports/$f is not installed"; rm -rf "$empty"; exit 1; }
done
rc=0
(cd "$empty" && "$prefix/bin/beamimpact" score paper --sets paper --scenes s1_central --no-ladder --out score \
  --cache cache) > "$empty/score.log" 2>&1 || rc=$?
verdict=$(grep -oE 'score paper: (PASSED|FAILED)' "$empty/score.log" | head -1)
if ((rc > 1)) || [[ -z $verdict ]] || ! grep -q "^page: score/scorecard.html$" "$empty/score.log" ||
  ! grep -q "$verdict" "$empty/score/scorecard.html"; then
  cat "$empty/score.log"; echo "install test: the installed score made no page with its verdict ($verdict)"; rm -rf "$empty"; exit 1
fi
echo "install test: the installed score made score/scorecard.html ($verdict)"
rm -rf "$empty"
# The Python package, when the build has it: importable from the prefix, same impulse.
pkg=$prefix/lib/python3/dist-packages
if [[ -d $pkg/beamimpact ]]; then
  imp=$(PYTHONPATH=$pkg PYTHONDONTWRITEBYTECODE=1 /usr/bin/python3 -c "import beamimpact
r = beamimpact.run('$scene', method='exact', progress=False)
print(round(r.summary['contacts'][0]['impulse_normal'], 9))")
  [[ $imp == 4.0 ]] || { echo "install test: the installed Python package gave impulse $imp, expected 4 N s"; exit 1; }
  echo "install test: Python package imported from $pkg, impulse $imp N s"
fi
echo "install test: passed (prefix $prefix)"
