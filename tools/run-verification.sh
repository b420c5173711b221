#!/usr/bin/env bash
# @brief The main job: installs what is missing, builds, runs the verification matrix on the
# shipped scenes and writes its report under out/verify/.
# Usage: tools/run-verification.sh [--tier quick|full]   (default: quick)
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/build.sh
build=${BEAMIMPACT_BUILD_DIR:-build}
args=("$@")
((${#args[@]})) || args=(--tier quick)
"$build"/beamimpact verify verification/matrix.toml --out out/verify --jobs "$(nproc)" "${args[@]}"
