#!/usr/bin/env bash
# The README's demo command: install what is missing, build the library and the two programs it
# runs (not the tests and benchmarks), segment the bundled teddy (PSB 180) from the mesh alone (its
# medial meshes are computed) and score the result against its 13 human segmentations.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
SEGMAT_BUILD_TARGETS="segmat_mesh segmat_eval" bash "$root/scripts/build.sh"
bin="$root/build/bin"
data="$root/data/teddy"
out="$root/out/demo"
mkdir -p "$out"

echo "== segmat_mesh: teddy from the mesh alone (medial meshes computed, then parts)"
"$bin/segmat_mesh" "$data/teddy.off" -o "$out/teddy" --save-mat
echo
echo "== segmat_eval: against the 13 human segmentations (PSB metrics, lower is better)"
"$bin/segmat_eval" --mesh "$data/teddy.off" --pred "$out/teddy.seg" --truth "$data"/seg/180_*.seg
echo
echo "Outputs:"
echo "  $out/teddy.seg   one part label per face (PSB format)"
echo "  $out/teddy.ply   faces coloured by part (open in MeshLab)"
echo "  $out/teddy_base.ma, teddy_struct.ma   the computed medial meshes (Q-MAT .ma format)"
