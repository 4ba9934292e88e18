#!/usr/bin/env bash
# Runs segmat_batch over a collection as a Slurm job array of N shards plus a merge that waits
# for them (docs/batch.md):
#   scripts/slurm_batch.sh INPUT OUT [N] [JOBS_PER_SHARD]
# Shard K writes OUT/shard-K, logs go to OUT/log/, the merged result to OUT/all (report.html).
# Prints the two job ids. segmat_batch is taken from build/bin (else PATH).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
input="$(realpath "$1")"; out="$(realpath -m "$2")"; n="${3:-4}"; jobs="${4:-1}"
batch="$root/build/bin/segmat_batch"
[[ -x "$batch" ]] || batch="$(command -v segmat_batch)"
mkdir -p "$out/log"
array=$(sbatch --parsable --job-name=segmat-shard --array=0-$((n - 1)) --cpus-per-task="$jobs" \
  --output="$out/log/shard-%a.txt" \
  --wrap="$batch '$input' -o '$out/shard-'\$SLURM_ARRAY_TASK_ID --jobs $jobs --shard \$SLURM_ARRAY_TASK_ID/$n")
shards=()
for ((k = 0; k < n; ++k)); do shards+=("'$out/shard-$k'"); done
merge=$(sbatch --parsable --job-name=segmat-merge --dependency=afterany:"$array" \
  --output="$out/log/merge.txt" --wrap="$batch --merge -o '$out/all' ${shards[*]}")
echo "array job $array ($n shards), merge job $merge; report: $out/all/report.html"
