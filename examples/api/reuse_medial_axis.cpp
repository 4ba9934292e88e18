// Compute the medial meshes of a mesh once, then segment it at several growing thresholds δ0:
// only region growing and the surface cut run again.
//   example_reuse_medial_axis MESH
#include <segmat/io/mesh.h>
#include <segmat/medial/medial_mesh_estimation.h>
#include <segmat/segmentation/mesh_segmentation.h>

#include <iostream>

int
main(int argc, char** argv)
{
  if (argc != 2) {
    std::cerr << "usage: example_reuse_medial_axis MESH\n";
    return 2;
  }
  segmat::TriangleMesh::Ptr mesh;
  try {
    mesh = std::make_shared<segmat::TriangleMesh>(segmat::io::loadMesh(argv[1]));
  } catch (const segmat::Error& e) {
    std::cerr << e.what() << '\n';
    return 2;
  }

  // The base (about 2000 spheres) and structured medial meshes, computed once. They could also
  // be read from Q-MAT .ma files (segmat::io::loadMa).
  segmat::MedialMeshEstimation estimation;
  estimation.setInputMesh(mesh);
  auto base = std::make_shared<segmat::MedialMesh>();
  auto structured = std::make_shared<segmat::MedialMesh>();
  if (!estimation.compute(*base, *structured))
    return 1;

  segmat::MeshSegmentation seg;
  seg.setInputMesh(mesh);
  seg.setBaseMat(base);
  seg.setStructuredMat(structured);
  for (double delta0 : {0.01, 0.015, 0.03}) {
    seg.setGrowingThreshold(delta0); // the MAT graph and structure tags are kept
    std::vector<int> face_labels;
    if (!seg.segment(face_labels))
      return 1;
    std::vector<pcl::PointIndices> parts;
    seg.getParts(parts);
    std::cout << "delta0 " << delta0 << ": " << parts.size() << " parts\n";
  }
  return 0;
}
