#!/usr/bin/env bash
# @brief Mutation testing of the paper's integrator against the quick verification tier.
# Usage: tools/mutation-test.sh [--all] [--only NAME,...] [--out DIR] [--scratch DIR] [--jobs N]
# Default: the fast CI subset of tools/mutation/mutants.py; --all: every mutant. Writes
# out/mutation/mutation.json; exits 1 if a mutant survives. Details: tools/mutation/mutation_test.py.
set -euo pipefail
exec python3 "$(dirname "$0")/mutation/mutation_test.py" "$@"
