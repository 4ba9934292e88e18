#!/usr/bin/env bash
# The README's demo command (placeholder until the segmentation lands).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bash "$root/scripts/build.sh"
