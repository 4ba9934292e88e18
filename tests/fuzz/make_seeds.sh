#!/usr/bin/env bash
# Writes a few small valid files of format $1 into folder $2 (seeds for formats data/ lacks).
set -euo pipefail
ext="$1" dir="$2"
tet_v="0 0 0
1 0 0
0 1 0
0 0 1"
case "$ext" in
  off) printf 'OFF\n4 4 0\n%s\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n' "$tet_v" >"$dir/tet.off" ;;
  obj) printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nvn 0 0 1\nf 1 3 2\nf 1//1 2//1 4//1\nf 1 4 3\nf 2/1 3/1 4/1\n' >"$dir/tet.obj" ;;
  ply) printf 'ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\nelement face 4\nproperty list uchar int vertex_indices\nend_header\n%s\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n' "$tet_v" >"$dir/tet.ply" ;;
  stl) printf 'solid t\nfacet normal 0 0 -1\nouter loop\nvertex 0 0 0\nvertex 0 1 0\nvertex 1 0 0\nendloop\nendfacet\nfacet normal 0 -1 0\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 0 1\nendloop\nendfacet\nendsolid t\n' >"$dir/tet.stl" ;;
  pcd) printf '# .PCD v0.7\nVERSION 0.7\nFIELDS x y z normal_x normal_y normal_z\nSIZE 4 4 4 4 4 4\nTYPE F F F F F F\nCOUNT 1 1 1 1 1 1\nWIDTH 3\nHEIGHT 1\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS 3\nDATA ascii\n0 0 0 0 0 1\n1 0 0 0 0 1\n0 1 0 0 0 1\n' >"$dir/three.pcd" ;;
  ma) printf '3 2 1\nv 0 0 0 0.5\nv 1 0 0 0.4\nv 0 1 0 0.3\ne 0 1\ne 1 2\nf 0 1 2\n' >"$dir/tri.ma" ;;
  seg) printf '0\n0\n1\n2\n' >"$dir/four.seg" ;;
esac
