#!/usr/bin/env bash
# The README's test command: install what is missing (with doxygen, so the API reference is
# checked), build everything, run every test.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bash "$root/scripts/install_deps.sh" doxygen
bash "$root/scripts/build.sh" -DSEGMAT_BUILD_TESTS=ON
cd "$root/build"
ctest --output-on-failure -j "${SEGMAT_JOBS:-$(nproc)}"
