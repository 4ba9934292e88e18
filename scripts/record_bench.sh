#!/usr/bin/env bash
# Runs one benchmark command and keeps its output for docs/benchmarks.md:
#   scripts/record_bench.sh NAME COMMAND [ARGS...]
# writes bench/results/NAME.txt (a header with date, machine, commit and the command, then the
# command's stdout) and regenerates docs/benchmarks.md. Run from the repository root.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
name="$1"; shift
out="$root/bench/results/$name.txt"
mkdir -p "$root/bench/results"
tmp="$out.tmp$$"
trap 'rm -f "$tmp"' EXIT
cpu="$(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ *//')"
{
  echo "date: $(date -u +%Y-%m-%dT%H:%MZ)"
  echo "machine: ${cpu:-unknown cpu}, $(nproc) cores, $(awk '/MemTotal/ {printf "%.0f GiB", $2/1048576}' /proc/meminfo)"
  # Records written by other runs are not changes to the code being measured.
  echo "commit: $(git -C "$root" rev-parse --short HEAD 2>/dev/null || echo unknown)$(git -C "$root" diff --quiet HEAD -- . ':(exclude)bench/results' ':(exclude)docs/benchmarks.md' 2>/dev/null || echo ' (with uncommitted changes)')"
  echo "command: $*"
  echo "---"
  "$@"
} >"$tmp"
mv "$tmp" "$out"
python3 "$root/scripts/make_benchmarks_md.py"
