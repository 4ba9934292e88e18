#!/usr/bin/env python3
"""Segment a mesh and a point cloud read with Open3D, colour them by part, write PLY files.

    PYTHONPATH=build/python /usr/bin/python3 examples/python/open3d_segment.py \
        [--mesh data/teddy/teddy.off] [--cloud CLOUD.ply] [-o OUTDIR]

Without --cloud, the cloud is sampled from the mesh with Open3D (with the faces' normals).
Writes OUTDIR/mesh_parts.ply and OUTDIR/cloud_parts.ply. Opens no window (runs headless).
"""
import argparse
from pathlib import Path

import numpy as np
import open3d as o3d

import segmat

ROOT = Path(__file__).resolve().parents[2]


def coloured_mesh(mesh, labels):
    """Open3D colours vertices, not faces: give every face its own three vertices."""
    vertices = np.asarray(mesh.vertices)[np.asarray(mesh.triangles)].reshape(-1, 3)
    out = o3d.geometry.TriangleMesh(
        o3d.utility.Vector3dVector(vertices),
        o3d.utility.Vector3iVector(np.arange(len(vertices), dtype=np.int32).reshape(-1, 3)))
    out.vertex_colors = o3d.utility.Vector3dVector(np.repeat(segmat.labels_to_colors(labels), 3, axis=0))
    return out


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--mesh", default=str(ROOT / "data" / "teddy" / "teddy.off"))
    parser.add_argument("--cloud", help="point cloud file (.ply, .pcd, .xyz ...); default: sampled from the mesh")
    parser.add_argument("--points", type=int, default=10000, help="points sampled without --cloud")
    parser.add_argument("-o", "--outdir", default=".")
    args = parser.parse_args()
    outdir = Path(args.outdir)
    outdir.mkdir(parents=True, exist_ok=True)

    mesh = o3d.io.read_triangle_mesh(args.mesh)
    # Open3D's arrays are float64 (n, 3) and int32 (m, 3): exactly what segmat takes.
    segmenter = segmat.MeshSegmenter(np.asarray(mesh.vertices), np.asarray(mesh.triangles))
    labels = segmenter.segment()
    print(f"mesh: {labels.max() + 1} parts, face counts {segmenter.info['face_counts']}")
    coarser = segmenter.segment(delta0=0.03)  # reuses the medial meshes: only the growing runs
    print(f"mesh with delta0=0.03: {coarser.max() + 1} parts in {segmenter.info['cpp_seconds']:.2f} s")
    o3d.io.write_triangle_mesh(str(outdir / "mesh_parts.ply"), coloured_mesh(mesh, labels))

    if args.cloud:
        cloud = o3d.io.read_point_cloud(args.cloud)
    else:
        mesh.compute_triangle_normals()
        cloud = mesh.sample_points_uniformly(number_of_points=args.points, use_triangle_normal=True)
    normals = np.asarray(cloud.normals) if cloud.has_normals() else None  # None: estimated
    cloud_labels = segmat.segment_cloud(np.asarray(cloud.points), normals)
    print(f"cloud: {len(cloud_labels)} points, {cloud_labels.max() + 1} parts")
    cloud.colors = o3d.utility.Vector3dVector(segmat.labels_to_colors(cloud_labels))
    o3d.io.write_point_cloud(str(outdir / "cloud_parts.ply"), cloud)
    print(f"wrote {outdir / 'mesh_parts.ply'} and {outdir / 'cloud_parts.ply'}")


if __name__ == "__main__":
    main()
