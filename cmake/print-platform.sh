#!/usr/bin/env bash
# Where a run happened: CPU model, the BLAS/LAPACK the system links (Debian alternatives) and
# the OpenBLAS kernel set it picked for this CPU. A red CI run says where it ran; iteration
# counts of chaotic runs depend on this (doc/algorithms.md "Round-off").
cpu=$(grep -m1 "model name" /proc/cpuinfo 2>/dev/null | cut -d: -f2- | sed 's/^ *//')
flags=$(grep -m1 "^flags" /proc/cpuinfo 2>/dev/null | tr ' ' '\n' | grep -E "^(avx2|avx512f|fma)$" | tr '\n' ' ')
echo "platform: cpu: ${cpu:-unknown} ($(nproc) cores; ${flags:-no avx2/avx512})"
blas=$(readlink -f /usr/lib/x86_64-linux-gnu/libblas.so.3 2>/dev/null || echo unknown)
lapack=$(readlink -f /usr/lib/x86_64-linux-gnu/liblapack.so.3 2>/dev/null || echo unknown)
echo "platform: blas: $blas; lapack: $lapack"
core=$(/usr/bin/python3 - 2>/dev/null <<'PY'
import ctypes
lib = ctypes.CDLL("libopenblas.so.0")
lib.openblas_get_corename.restype = ctypes.c_char_p
lib.openblas_get_config.restype = ctypes.c_char_p
print(lib.openblas_get_corename().decode(), "|", lib.openblas_get_config().decode())
PY
)
echo "platform: openblas kernels: ${core:-not found}${OPENBLAS_CORETYPE:+ (OPENBLAS_CORETYPE=$OPENBLAS_CORETYPE)}"
