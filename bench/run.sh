#!/usr/bin/env bash
# Runs the benchmarks and writes their tables into doc/performance.md (between markers).
# usage: bench/run.sh [--large]     (--large adds the ~600 000-dof cases: long, ~20 GB)
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD=${BUILD_DIR:-build}
exe=$BUILD/bench/bench_elasticity
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
cases=("hex27 17" "tet10 17")
if [[ "${1:-}" == "--large" ]]; then cases+=("hex27 29" "tet10 29"); fi
table=$(mktemp)
first=1
for c in "${cases[@]}"; do
  for np in 1 2; do
    args=($c)
    [[ $first == 1 ]] && args+=(--header) && first=0
    mpirun -np $np --oversubscribe "$exe" "${args[@]}" | tee -a "$table"
  done
done
python3 - "$table" <<'PY'
import re, sys, datetime
table = open(sys.argv[1]).read()
doc = "doc/performance.md"
text = open(doc).read()
start, end = "<!-- bench:elasticity:start -->", "<!-- bench:elasticity:end -->"
block = f"{start}\nMeasured {datetime.date.today()} by `bench/run.sh`:\n\n{table}{end}"
text = re.sub(re.escape(start) + ".*?" + re.escape(end), block, text, flags=re.S)
open(doc, "w").write(text)
PY
# 3D Hertz with contact, every formulation (~100 000 dofs; --large: finer).
hertz=$(mktemp)
size=0.008
if [[ "${1:-}" == "--large" ]]; then size=0.005; fi
"$BUILD/bench/bench_hertz" tet4 $size --header | tee "$hertz"
python3 - "$hertz" <<'PY'
import re, sys, datetime
table = open(sys.argv[1]).read()
doc = "doc/performance.md"
text = open(doc).read()
start, end = "<!-- bench:hertz:start -->", "<!-- bench:hertz:end -->"
block = f"{start}\nMeasured {datetime.date.today()} by `bench/run.sh`:\n\n{table}{end}"
text = re.sub(re.escape(start) + ".*?" + re.escape(end), block, text, flags=re.S)
open(doc, "w").write(text)
PY
# Algorithms: presets x line searches x cycling treatments on the pad and the frictional 3D
# Hertz (about 15 minutes).
python3 bench/algorithms.py "$BUILD/apps/contactlab" scenes "$BUILD/bench-algorithms" \
  --doc doc/performance.md
# Uniqueness diagnostic on the frictional 3D Hertz up to ~1 000 contact points (~3 minutes).
python3 bench/critical_mu.py "$BUILD/apps/contactlab" scenes "$BUILD/bench-critical-mu" \
  --doc doc/performance.md
# Mortar against node-to-segment on the two-body 3D Hertz up to ~100 000 dofs (~25 minutes).
python3 bench/mortar.py "$BUILD/apps/contactlab" scenes "$BUILD/bench-mortar" \
  --doc doc/performance.md
# The seed's 3D ironing: every slab x method on the shipped scene (~25 minutes); --large adds
# the full travel (~40 minutes). Writes doc/verification.md.
/usr/bin/python3 bench/ironing3d.py "$BUILD/apps/contactlab" scenes "$BUILD/bench-ironing3d-small" \
  --small --doc doc/verification.md
if [[ "${1:-}" == "--large" ]]; then
  /usr/bin/python3 bench/ironing3d.py "$BUILD/apps/contactlab" scenes "$BUILD/bench-ironing3d" \
    --doc doc/verification.md
fi
echo "bench: doc/performance.md and doc/verification.md updated"
