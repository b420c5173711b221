#!/usr/bin/env bash
# @brief Installs the Debian packages beamimpact needs (idempotent; skips what is present).
# Usage: tools/install-deps.sh [--no-fenicsx] [--sanitizers]
#   --no-fenicsx  skip python3-dolfinx (large: PETSc, MPI); the FEniCSx reference is then unavailable.
#   --sanitizers  only the packages of tools/sanitize.sh and tools/fuzz.sh (clang, its sanitizer and
#                 libFuzzer runtimes, ninja)
set -euo pipefail
pkgs=(cmake g++ make ninja-build ccache libeigen3-dev libsundials-dev libgsl-dev libgtest-dev libbenchmark-dev
      libtomlplusplus-dev libcli11-dev libfmt-dev nlohmann-json3-dev
      python3-numpy python3-scipy python3-matplotlib python3-jinja2 python3-dev pybind11-dev python3-pytest python3-siconos python3-getfem clang-format universal-ctags
      chromium libopenmpi-dev openmpi-bin python3-vtk9
      python3-venv python3-setuptools
      python3-sphinx furo python3-myst-parser doxygen python3-breathe)
[[ "${1:-}" == "--no-fenicsx" ]] || pkgs+=(python3-dolfinx)
[[ "${1:-}" == "--sanitizers" ]] && pkgs=(clang libclang-rt-14-dev ninja-build)
missing=()
for p in "${pkgs[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]} == 0)); then echo "install-deps: all packages present"; exit 0; fi
echo "install-deps: installing ${missing[*]}"
SUDO=""; [[ $(id -u) -eq 0 ]] || SUDO="sudo"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
echo "install-deps: done"
