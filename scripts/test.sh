#!/usr/bin/env bash
# The README's test command: install what is missing (with doxygen, so the API reference is
# checked), build everything, run every test.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
# Pictures (segmat_render) need VTK and, with no display, Xvfb with Mesa's software OpenGL;
# segmat_batch needs python3 and its report test chromium; the Python module needs pybind11 and
# numpy (tests: pytest; the Open3D example: python3-open3d); the API-reference test doxygen.
packages=(libvtk9-dev python3 xvfb libgl1-mesa-dri chromium python3-dev pybind11-dev
          python3-numpy python3-pytest python3-open3d doxygen)
bash "$root/scripts/install_deps.sh" "${packages[@]}"
bash "$root/scripts/build.sh" -DSEGMAT_BUILD_TESTS=ON
cd "$root/build"
ctest --output-on-failure -j "${SEGMAT_JOBS:-$(nproc)}"
# Fuzz every file reader for a short fixed time (docs/robustness.md); SEGMAT_FUZZ_SECONDS=0 skips.
# A finding is reported (with its input under build-fuzz/findings) but does not fail the run:
# a short run may or may not hit a new finding by chance, and the fixed ones are
# replayed by test_fuzz_regressions above, which does fail the run.
if [ "${SEGMAT_FUZZ_SECONDS:-20}" != 0 ]; then
  SEGMAT_FUZZ_SECONDS="${SEGMAT_FUZZ_SECONDS:-20}" bash "$root/scripts/fuzz.sh" ||
    echo "segmat: the fuzzers found a problem (see above); it does not fail this run" >&2
fi
