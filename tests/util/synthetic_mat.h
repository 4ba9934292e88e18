// Synthetic medial meshes with known parts, for the region-growing tests.
#pragma once

#include <segmat/geometry/medial_mesh.h>
#include "../../src/segmentation/patch_merging.h"

#include <Eigen/Core>

#include <functional>
#include <vector>

namespace segmat {
namespace test {

/** A medial mesh under construction: add sheets and cone chains, then build(). */
class SyntheticMat
{
public:
  /** Flat sheet of slabs: vertices origin + (i/nu)·u + (j/nv)·v, i ≤ nu, j ≤ nv, radius
   * radius(i/nu, j/nv); each grid cell is split into two triangles.
   * \return index of vertex (i, j) is first + i·(nv + 1) + j, with first the returned value
   */
  int
  addSheet(const Eigen::Vector3d& origin, const Eigen::Vector3d& u, const Eigen::Vector3d& v,
           int nu, int nv, const std::function<double(double, double)>& radius);

  /** Chain of pure edges (medial cones) through the given spheres. When \a start >= 0 the chain
   * starts at that existing vertex (points[0] and radii[0] are then ignored); when \a end >= 0
   * it ends at that existing vertex (the last point and radius are ignored).
   * \return indices of the chain's spheres, in order
   */
  std::vector<int>
  addChain(int start, const std::vector<Eigen::Vector3d>& points, const std::vector<double>& radii,
           int end = -1);

  /** Straight chain from vertex \a start to vertex \a end (both existing) in \a segments
   * cones, radius(t) for the inner spheres, t ∈ (0, 1).
   */
  std::vector<int>
  connect(int start, int end, int segments, const std::function<double(double)>& radius);

  /** Straight chain from the existing vertex \a start to the new point \a b in \a segments
   * cones, radius(t) for t ∈ (0, 1].
   */
  std::vector<int>
  extend(int start, const Eigen::Vector3d& b, int segments,
         const std::function<double(double)>& radius);

  /** The position of vertex i. */
  const Eigen::Vector3d&
  center(int i) const
  {
    return centers_[i];
  }

  MedialMesh
  build() const;

private:
  std::vector<Eigen::Vector3d> centers_;
  std::vector<double> radii_;
  std::vector<Eigen::Vector2i> edges_;
  std::vector<Eigen::Vector3i> triangles_;
};

/** Visibility inside the union of a medial mesh's spheres: a segment is visible when sample
 * points every `step` along it (default: a quarter of the smallest positive radius) all lie in
 * some sphere. Stands in for the surface of a synthetic shape.
 */
SegmentVisibility
unionOfBallsVisibility(const MedialMesh& mat, double step = 0.0);

} // namespace test
} // namespace segmat
