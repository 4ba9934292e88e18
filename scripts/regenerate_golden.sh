#!/usr/bin/env bash
# Rewrites tests/golden/mesh_labels.txt (part count and label checksum of the default mesh
# segmentation per shape) from the current code. Only for a deliberate change of the labels:
# review `git diff tests/golden` and say why in the commit. Needs ../shared beside the clone.
#   scripts/regenerate_golden.sh            (builds build/bin/test_golden_labels if needed)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
table="$root/tests/golden/mesh_labels.txt"
if [[ ! -x "$root/build/bin/test_golden_labels" ]]; then
  cmake -S "$root" -B "$root/build" -DCMAKE_BUILD_TYPE=Release -DSEGMAT_BUILD_TESTS=ON >/dev/null
  cmake --build "$root/build" -j "${SEGMAT_JOBS:-$(nproc)}" --target test_golden_labels >/dev/null
fi
tmp="$table.tmp$$"
trap 'rm -f "$tmp"' EXIT
SEGMAT_GOLDEN_WRITE="$tmp" "$root/build/bin/test_golden_labels" --gtest_filter=GoldenTable.Regenerate
mv "$tmp" "$table"
echo "wrote $table"
