#!/usr/bin/env bash
# @brief The install test: `cmake --install` the build into a fresh prefix, build the example
# consumer (examples/consumer) against it with find_package(beamimpact), run it on the shipped
# S1 scene with the exact method and check the impulse against theory (m v0 / 2 = 4 N s).
# Usage: tools/test-install.sh BUILD_DIR   (run by ctest as install_consumer)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=$(cd "$1" && pwd)
prefix=$build/install-test
rm -rf "$prefix" "$build/consumer"
cmake --install "$build" --prefix "$prefix" > "$build/install-test.log"
cmake -S "$root/examples/consumer" -B "$build/consumer" -DCMAKE_PREFIX_PATH="$prefix" \
  -DCMAKE_BUILD_TYPE=Release >> "$build/install-test.log"
cmake --build "$build/consumer" >> "$build/install-test.log"
scene=$prefix/share/beamimpact/verification/scenes/paper/s1_central.toml
out=$("$build/consumer/print_impulse" "$scene" exact)
echo "$out"
# S1, two equal free rods (references.md 1): the exact impulse is m v0 / 2 = 4 N s.
grep -q "impulse 4 N s (exact)" <<<"$out" || { echo "install test: expected impulse 4 N s"; exit 1; }
"$prefix/bin/beamimpact" methods > /dev/null
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
