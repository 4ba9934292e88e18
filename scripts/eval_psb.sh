#!/usr/bin/env bash
# Segments every mesh of a PSB-style folder from the mesh alone (segmat_mesh, default parameters,
# medial meshes computed) and prints segmat_eval's scores: per model, per category and overall.
#
#   scripts/eval_psb.sh [PSB_DIR] [OUT_DIR]
# PSB_DIR holds off/N.off and seg/Benchmark/N/N_k.seg (default: ../shared/data/psb-dev beside the
# repository); predictions go to OUT_DIR/N.seg (+ N.ply) (default: out/psb-eval). Needs a build
# (scripts/build.sh is run when build/bin/segmat_mesh is missing).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
psb="${1:-$root/../shared/data/psb-dev}"
out="${2:-$root/out/psb-eval}"
bin="$root/build/bin"
[[ -x "$bin/segmat_mesh" && -x "$bin/segmat_eval" ]] || bash "$root/scripts/build.sh"
[[ -d "$psb/off" ]] || { echo "eval_psb.sh: no $psb/off folder" >&2; exit 2; }
mkdir -p "$out"

shopt -s nullglob
meshes=("$psb"/off/*.off)
(( ${#meshes[@]} )) || { echo "eval_psb.sh: no .off file in $psb/off" >&2; exit 2; }
failed=0
start=$SECONDS
for mesh in "${meshes[@]}"; do
  id="$(basename "$mesh" .off)"
  if ! "$bin/segmat_mesh" "$mesh" -o "$out/$id" >/dev/null 2>"$out/$id.err"; then
    echo "eval_psb.sh: segmat_mesh failed on $mesh (see $out/$id.err)" >&2
    failed=$((failed + 1))
  else
    rm -f "$out/$id.err"
  fi
done
echo "segmented ${#meshes[@]} meshes in $((SECONDS - start)) s ($failed failed); predictions in $out"
echo
"$bin/segmat_eval" --psb "$psb" --pred "$out"
