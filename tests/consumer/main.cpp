// Downstream use of an installed segmat: read a medial mesh and print its size.
#include <segmat/io/ma.h>

#include <iostream>

int main(int argc, char** argv)
{
  if (argc != 2) {
    std::cerr << "usage: segmat_consumer FILE.ma\n";
    return 2;
  }
  try {
    const segmat::MedialMesh mat = segmat::io::loadMa(argv[1]);
    std::cout << mat.numVertices() << " spheres, " << mat.numEdges() << " edges, "
              << mat.numTriangles() << " triangles\n";
    return mat.numVertices() > 0 ? 0 : 1;
  } catch (const segmat::Error& e) {
    std::cerr << e.what() << "\n";
    return 1;
  }
}
