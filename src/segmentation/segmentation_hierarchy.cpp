/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include <segmat/common/error.h>
#include <segmat/segmentation/mesh_segmentation.h>
#include <segmat/segmentation/segmentation_hierarchy.h>

#include <algorithm>
#include <map>
#include <numeric>
#include <utility>

namespace segmat {
namespace {

int
findRoot(std::vector<int>& parent, int i)
{
  while (parent[i] != i)
    i = parent[i] = parent[parent[i]];
  return i;
}

/** The smaller index becomes the root, so pieces are named by their first face. */
void
unite(std::vector<int>& parent, int a, int b)
{
  a = findRoot(parent, a);
  b = findRoot(parent, b);
  if (a != b)
    parent[std::max(a, b)] = std::min(a, b);
}

} // namespace

void
nestSegmentation(const TriangleMesh& mesh, const std::vector<int>& coarse,
                 const std::vector<int>& fine, double min_area_fraction, std::vector<int>& nested,
                 std::vector<int>& parents)
{
  const std::size_t n = mesh.numFaces();
  if (coarse.size() != n || fine.size() != n)
    throw Error("nestSegmentation: " + std::to_string(coarse.size()) + " and " +
                std::to_string(fine.size()) + " labels for " + std::to_string(n) + " faces");
  const std::vector<FaceAdjacency> adjacency = mesh.faceAdjacency();
  std::vector<int> root(n);
  std::iota(root.begin(), root.end(), 0);
  for (const FaceAdjacency& a : adjacency)
    if (coarse[a.face_a] == coarse[a.face_b] && fine[a.face_a] == fine[a.face_b])
      unite(root, a.face_a, a.face_b);

  std::vector<double> area(n, 0.0);
  double total = 0.0;
  for (std::size_t f = 0; f < n; ++f) {
    const double a = mesh.faceArea(static_cast<int>(f));
    area[findRoot(root, static_cast<int>(f))] += a;
    total += a;
  }
  const double threshold = min_area_fraction * total;
  // Merge the smallest piece that has a neighbour in the same coarse part, one at a time (a
  // merge changes the neighbours' areas and boundaries).
  std::vector<char> stuck(n, 0);
  for (;;) {
    int smallest = -1;
    for (std::size_t f = 0; f < n; ++f)
      if (findRoot(root, static_cast<int>(f)) == static_cast<int>(f) && !stuck[f] &&
          area[f] < threshold && (smallest < 0 || area[f] < area[smallest]))
        smallest = static_cast<int>(f);
    if (smallest < 0)
      break;
    std::map<int, double> boundary; // neighbouring piece -> shared edge length
    for (const FaceAdjacency& a : adjacency) {
      const int ra = findRoot(root, a.face_a), rb = findRoot(root, a.face_b);
      if (ra == rb || coarse[a.face_a] != coarse[a.face_b] || (ra != smallest && rb != smallest))
        continue;
      boundary[ra == smallest ? rb : ra] += (mesh.vertices[a.v0] - mesh.vertices[a.v1]).norm();
    }
    if (boundary.empty()) {
      stuck[smallest] = 1;
      continue;
    }
    int best = boundary.begin()->first;
    for (const auto& [piece, length] : boundary)
      if (length > boundary[best])
        best = piece;
    const double merged = area[smallest] + area[best];
    unite(root, smallest, best);
    const int r = findRoot(root, smallest);
    area[r] = merged;
    stuck[r] = 0;
  }

  nested.assign(n, -1);
  parents.clear();
  std::vector<int> label_of_root(n, -1);
  for (std::size_t f = 0; f < n; ++f) {
    const int r = findRoot(root, static_cast<int>(f));
    if (label_of_root[r] < 0) {
      label_of_root[r] = static_cast<int>(parents.size());
      parents.push_back(coarse[f]);
    }
    nested[f] = label_of_root[r];
  }
}

bool
segmentHierarchy(MeshSegmentation& segmentation, const std::vector<DetailLevel>& levels,
                 std::vector<HierarchyLevel>& hierarchy)
{
  hierarchy.clear();
  for (const DetailLevel& level : levels) {
    segmentation.setGrowingThreshold(level.growing_threshold);
    segmentation.setMinRegionFraction(level.min_region_fraction);
    std::vector<int> labels;
    if (!segmentation.segment(labels))
      return false;
    HierarchyLevel out;
    out.level = level;
    if (hierarchy.empty()) {
      // Named by first face like the finer levels; the first level has no parents.
      nestSegmentation(*segmentation.getInputMesh(), labels, labels, 0.0, out.labels, out.parents);
      std::fill(out.parents.begin(), out.parents.end(), -1);
    }
    else
      nestSegmentation(*segmentation.getInputMesh(), hierarchy.back().labels, labels,
                       level.min_region_fraction, out.labels, out.parents);
    hierarchy.push_back(std::move(out));
  }
  return true;
}

} // namespace segmat
