#!/usr/bin/env bash
# The README's test command: install what is missing, build, run every test.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bash "$root/scripts/build.sh" -DSEGMAT_BUILD_TESTS=ON
cd "$root/build"
ctest --output-on-failure -j "${SEGMAT_JOBS:-$(nproc)}"
# Fuzz every file reader for a short fixed time (docs/robustness.md); SEGMAT_FUZZ_SECONDS=0 skips.
if [ "${SEGMAT_FUZZ_SECONDS:-20}" != 0 ]; then
  SEGMAT_FUZZ_SECONDS="${SEGMAT_FUZZ_SECONDS:-20}" bash "$root/scripts/fuzz.sh"
fi
