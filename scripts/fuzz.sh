#!/usr/bin/env bash
# Fuzzes every file reader with libFuzzer: builds tests/fuzz with clang into build-fuzz/, seeds each
# target with the bundled data/ files of its format (plus tests/fuzz/regressions/), and runs each
# target for SEGMAT_FUZZ_SECONDS (default 20). A crash leaves crash-* in build-fuzz/findings/EXT/
# and fails the script; copy such a file into tests/fuzz/regressions/ once fixed.
# Usage: scripts/fuzz.sh [EXT ...]   (default: off ply obj stl pcd ma seg)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
seconds="${SEGMAT_FUZZ_SECONDS:-20}"
exts=("$@")
[ ${#exts[@]} -gt 0 ] || exts=(off ply obj stl pcd ma seg)
out="${SEGMAT_FUZZ_DIR:-$root/build-fuzz}"
mkdir -p "$out"
if ! { cmake -S "$root/tests/fuzz" -B "$out" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
         -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ &&
       cmake --build "$out" -j "${SEGMAT_JOBS:-$(nproc)}"; } >"$out/build.log" 2>&1; then
  tail -n 40 "$out/build.log" >&2
  echo "fuzz: build failed (log: $out/build.log)" >&2
  exit 1
fi
status=0
for ext in "${exts[@]}"; do
  seeds="$out/seeds/$ext" findings="$out/findings/$ext"
  mkdir -p "$seeds" "$findings"
  # Seeds: small bundled files of this format, the regressions, and tiny files written here.
  find "$root/data" "$root/tests/fuzz/regressions" -type f -name "*.$ext" -size -200k \
    -exec cp -t "$seeds" {} + 2>/dev/null || true
  bash "$root/tests/fuzz/make_seeds.sh" "$ext" "$seeds"
  echo "fuzz: $ext for ${seconds}s"
  if ! (cd "$findings" && ASAN_OPTIONS=detect_leaks=0 "$out/fuzz_$ext" -max_total_time="$seconds" \
          -timeout=10 -rss_limit_mb=2048 -max_len=65536 -print_final_stats=1 "$findings" "$seeds" \
          >"$findings.log" 2>&1); then
    echo "fuzz: $ext FOUND A PROBLEM (see $findings.log and $findings/crash-*)" >&2
    status=1
  fi
  grep -E "^stat::number_of_executed_units|^stat::peak_rss_mb" "$findings.log" | tr '\n' ' '
  echo
done
exit $status
