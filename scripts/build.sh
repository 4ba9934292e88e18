#!/usr/bin/env bash
# Configures and builds segmat into build/ (programs in build/bin/). Used by demo.sh and test.sh.
# Arguments go to CMake's configure step; SEGMAT_BUILD_TARGETS="a b" builds only those targets
# (default: everything).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bash "$root/scripts/install_deps.sh"
jobs="${SEGMAT_JOBS:-$(nproc)}"
mkdir -p "$root/build"
log="$root/build/build.log"
echo "segmat: building into $root/build (log: $log)"
if ! { cmake -S "$root" -B "$root/build" -DCMAKE_BUILD_TYPE=Release "$@" &&
       cmake --build "$root/build" -j "$jobs" ${SEGMAT_BUILD_TARGETS:+--target $SEGMAT_BUILD_TARGETS}; } \
     >"$log" 2>&1; then
  tail -n 60 "$log" >&2
  echo "segmat: build failed (full log: $log)" >&2
  exit 1
fi
