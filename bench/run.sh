#!/usr/bin/env bash
# Runs the benchmarks and writes their tables into doc/performance.md (between markers).
# usage: bench/run.sh [--large] [SECTION...]
#   --large adds the ~600 000-dof cases (long, ~20 GB); SECTIONs (elasticity, hertz, nonlinear,
#   ironing, algorithms, critical-mu, mortar, ironing3d, normal-field, tube-expansion,
#   blade-root, factorization-reuse, single-precision, peers, study-process, scene-presets,
#   python-module)
#   run only those tables, all by default (ironing3d and normal-field write
#   doc/verification.md, study-process doc/studies.md, scene-presets doc/algorithms.md; peers
#   installs GetFEM and CalculiX with apt-get when they are missing).
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD=${BUILD_DIR:-build}
exe=$BUILD/bench/bench_elasticity
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
large=0
sections=()
for a in "$@"; do
  if [[ $a == --large ]]; then large=1; else sections+=("$a"); fi
done
want() { [[ ${#sections[@]} == 0 || " ${sections[*]} " == *" $1 "* ]]; }

if want elasticity; then
  cases=("hex27 17" "tet10 17")
  if [[ $large == 1 ]]; then cases+=("hex27 29" "tet10 29"); fi
  table=$(mktemp)
  first=1
  for c in "${cases[@]}"; do
    for np in 1 2; do
      args=($c)
      [[ $first == 1 ]] && args+=(--header) && first=0
      mpirun -np $np --oversubscribe "$exe" "${args[@]}" | tee -a "$table"
    done
  done
  python3 bench/docblock.py doc/performance.md elasticity bench/run.sh "$table"
fi
if want hertz; then
  # 3D Hertz with contact, every formulation (~100 000 dofs; --large: finer).
  hertz=$(mktemp)
  size=0.008
  if [[ $large == 1 ]]; then size=0.005; fi
  "$BUILD/bench/bench_hertz" tet4 $size --header | tee "$hertz"
  python3 bench/docblock.py doc/performance.md hertz bench/run.sh "$hertz"
fi
if want nonlinear; then
  # Finite-strain and plastic assembly against one MUMPS factorization (issue 16): each material
  # at a deformed state (10 % stretch and shear), 130 000 dofs, 1 and 2 ranks (~8 minutes).
  nonlinear=$(mktemp)
  first=1
  for c in "hex27 17" "tet10 17"; do
    for material in linear-elastic neo-hookean simo-miehe; do
      for np in 1 2; do
        args=($c --material $material)
        [[ $first == 1 ]] && args+=(--header) && first=0
        mpirun -np $np --oversubscribe "$exe" "${args[@]}" | tee -a "$nonlinear"
      done
    done
  done
  python3 bench/docblock.py doc/performance.md nonlinear bench/run.sh "$nonlinear"
fi
if want ironing; then
  # Newton iterations per load step of the 2D ironing scene, each algorithm preset (~3 minutes).
  python3 bench/ironing.py "$BUILD/apps/contactlab" scenes "$BUILD/bench-ironing" \
    --doc doc/performance.md
fi
if want algorithms; then
  # Algorithms: presets x line searches x cycling treatments on the pad and the frictional 3D
  # Hertz (about 15 minutes).
  python3 bench/algorithms.py "$BUILD/apps/contactlab" scenes "$BUILD/bench-algorithms" \
    --doc doc/performance.md
fi
if want scene-presets; then
  # Every shipped scene under each algorithm preset (about 6 minutes).
  python3 bench/scene_presets.py "$BUILD/apps/contactlab" scenes "$BUILD/bench-scene-presets" \
    --doc doc/algorithms.md
fi
if want critical-mu; then
  # Uniqueness diagnostic on the frictional 3D Hertz up to ~1 000 contact points (~3 minutes).
  python3 bench/critical_mu.py "$BUILD/apps/contactlab" scenes "$BUILD/bench-critical-mu" \
    --doc doc/performance.md
fi
if want mortar; then
  # Mortar against node-to-segment on the two-body 3D Hertz up to ~100 000 dofs (~25 minutes).
  python3 bench/mortar.py "$BUILD/apps/contactlab" scenes "$BUILD/bench-mortar" \
    --doc doc/performance.md
fi
if want ironing3d; then
  # The seed's 3D ironing: every slab x method on the shipped scene (~25 minutes); --large adds
  # the full travel (~40 minutes). Writes doc/verification.md.
  /usr/bin/python3 bench/ironing3d.py "$BUILD/apps/contactlab" scenes \
    "$BUILD/bench-ironing3d-small" --small --doc doc/verification.md
  if [[ $large == 1 ]]; then
    /usr/bin/python3 bench/ironing3d.py "$BUILD/apps/contactlab" scenes "$BUILD/bench-ironing3d" \
      --doc doc/verification.md
  fi
fi
if want normal-field; then
  # The normal-field augmented Lagrangian against the augmented Lagrangian (~5 minutes).
  /usr/bin/python3 bench/normal_field.py "$BUILD/apps/contactlab" scenes \
    "$BUILD/bench-normal-field" --doc doc/verification.md
fi
if want tube-expansion; then
  # The seed's tube-expansion table in its shape, mu x PF/NP/NG at 32 steps: hex8 node-to-segment
  # (~3 minutes); --large adds the scene's hex27 mortar (about an hour).
  python3 bench/tube_expansion.py "$BUILD/apps/contactlab" "$BUILD/bench-tube-expansion-hex8" \
    --element hex8 --discretization node-to-segment --doc doc/performance.md
  if [[ $large == 1 ]]; then
    python3 bench/tube_expansion.py "$BUILD/apps/contactlab" "$BUILD/bench-tube-expansion-hex27" \
      --element hex27 --discretization mortar --doc doc/performance.md
  fi
fi
if want blade-root; then
  # The seed's blade-root table in its shape, PF/NP/NG on the 3D slice: the scene's size (~30 s);
  # --large adds the seed's 600 000 dofs.
  python3 bench/blade_root_seed.py "$BUILD/apps/contactlab" "$BUILD/bench-blade-root" \
    --size default --doc doc/performance.md
  if [[ $large == 1 ]]; then
    python3 bench/blade_root_seed.py "$BUILD/apps/contactlab" "$BUILD/bench-blade-root" \
      --size seed --doc doc/performance.md
  fi
fi
if want factorization-reuse; then
  # MUMPS' factorization reuse against a factorization per iteration, tet10 Hertz at 129 780
  # dofs on 1 and 2 ranks (~6 minutes).
  python3 bench/factorization_reuse.py "$BUILD/apps/contactlab" scenes \
    "$BUILD/bench-factorization-reuse" --doc doc/performance.md
fi
if want single-precision; then
  # MUMPS' single-precision factors against double: tet10 Hertz at 46 572 and 129 780 dofs
  # (~3 minutes); --large adds the seed-size frictional tube (about an hour).
  cases=(hertz-46k hertz-130k)
  if [[ $large == 1 ]]; then cases+=(tube-seed); fi
  python3 bench/single_precision.py "$BUILD/apps/contactlab" scenes \
    "$BUILD/bench-single-precision" --cases "${cases[@]}" --doc doc/performance.md
fi
if want study-process; then
  # Studies run the default way (as many runs at a time as the cores), in one `contactlab batch`
  # process one at a time, and a process per run, and against one run (issue 19's 100-run
  # study): five studies, about 8 minutes.
  python3 bench/study_process.py "$BUILD/apps/contactlab" scenes "$BUILD/bench-study-process" \
    --doc doc/studies.md
fi
if want python-module; then
  # The same scenes by `contactlab run` and by the Python module's contactlab.run(), whole
  # processes (about a minute).
  python3 bench/python_module.py "$BUILD/apps/contactlab" "$BUILD/python" scenes \
    "$BUILD/bench-python-module" --doc doc/performance.md
fi
if want peers; then
  # contactlab, GetFEM and CalculiX on the same tet10 quarter hemisphere, one program at a
  # time (issue 19): 125 730 dofs, several minutes per program; --size 0.02 for seconds.
  /usr/bin/python3 bench/peers/peers.py "$BUILD/apps/contactlab" "$BUILD/bench-peers" \
    --size 0.00713 --doc doc/performance.md
fi
echo "bench: doc/performance.md, doc/verification.md and doc/studies.md updated"
