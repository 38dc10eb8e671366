#!/usr/bin/env bash
# The scene fuzz target at 10^6 mutations (the suite runs 10^5); prints its counts, which go to
# doc/verification.md ("Fuzzing the scene input").
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD=${BUILD_DIR:-build}
CONTACTLAB_FUZZ_MUTATIONS=${1:-1000000} CONTACTLAB_FUZZ_SEED=${2:-1} \
  "$BUILD/tests/unit/apps/unit_scene_fuzz" | grep -E "fuzz:|PASSED|FAILED"
