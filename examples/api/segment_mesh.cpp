// Segment a triangle mesh into parts with the default parameters and write one label per face
// (PSB .seg) and a PLY with the faces coloured by part.
//   example_segment_mesh MESH.off OUT_PREFIX
#include <segmat/io/colored_ply.h>
#include <segmat/io/mesh.h>
#include <segmat/io/seg.h>
#include <segmat/segmentation/mesh_segmentation.h>

#include <iostream>

int
main(int argc, char** argv)
{
  if (argc != 3) {
    std::cerr << "usage: example_segment_mesh MESH OUT_PREFIX\n";
    return 2;
  }
  segmat::TriangleMesh::Ptr mesh;
  try {
    mesh = std::make_shared<segmat::TriangleMesh>(segmat::io::loadMesh(argv[1]));
  } catch (const segmat::Error& e) { // the file's name, line and what is wrong
    std::cerr << e.what() << '\n';
    return 2;
  }

  segmat::MeshSegmentation seg; // the paper's defaults: δ0 0.015, η 0.002, α 0.05, λ 1.5, ω 0.3
  seg.setInputMesh(mesh);       // the medial meshes are computed from it
  std::vector<int> face_labels;
  if (!seg.segment(face_labels))
    return 1; // PCL_ERROR said why

  std::vector<pcl::PointIndices> parts;
  seg.getParts(parts); // faces of each part, largest part first
  std::cout << parts.size() << " parts:";
  for (const pcl::PointIndices& part : parts)
    std::cout << ' ' << part.indices.size();
  std::cout << " faces\n";

  const std::string prefix = argv[2];
  segmat::io::saveSeg(prefix + ".seg", face_labels);
  segmat::io::saveColoredMeshPly(prefix + ".ply", *mesh, face_labels);
  return 0;
}
