#!/usr/bin/env bash
# Concurrent starts at scale: STREAMS x STARTS `contactlab validate` (default 8 x 1250 = 10 000),
# each process with its own Open MPI session directory (apps/MpiSessionDirectory); fails on one
# failed start, one shared session directory seen or anything left in the private TMPDIR.
# The suite runs 90 (app.concurrent_starts). About 0.4 s of CPU a start: ~35 min on 2 cores.
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD=${BUILD_DIR:-build}
exec /usr/bin/python3 tests/app/check_concurrent_starts.py "$BUILD/apps/contactlab" \
  scenes/patch-test-2d.yaml "$BUILD/bench-concurrent-starts" "${1:-8}" "${2:-1250}"
