/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once

#include <segmat/geometry/triangle_mesh.h>

#include <Eigen/Core>

#include <cstddef>
#include <memory>
#include <vector>

namespace segmat {

/** \brief Generalised winding number of a triangle mesh (Jacobson, Kavan, Sorkine-Hornung 2013),
 * evaluated hierarchically (Barill, Dickson, Schmidt, Levin, Jacobson 2018, "Fast winding numbers
 * for soups and clouds").
 *
 * w(q) = (1/4π) Σ_f Ω_f(q), the signed solid angles of the faces seen from q: 1 inside a closed
 * outward-oriented mesh, 0 outside, and a smooth, nearly right value around small holes, gaps
 * and duplicated vertices, so `inside()` (w > 0.5) is a robust point-in-shape test.
 *
 * A bounding-volume hierarchy over the faces stores per node the area-weighted centre p̃, the
 * radius R of the ball about p̃ holding all its corners, the area vector Σ a_f n_f (dipole) and
 * the first- and second-order moments ∫ (p − p̃) nᵀ dA and ∫ (p − p̃)(p − p̃)ᵀ n_k dA (exact
 * triangle integrals). A node with |q − p̃| > β·R is replaced by its Taylor expansion to second
 * order (Barill et al. 2018, eq. 12 with orders 0–2; the second order captures the curvature of a
 * patch and cuts the error at β = 2 about twentyfold); otherwise its children are visited, and
 * faces in leaves get the exact solid angle (Van Oosterom & Strackee 1983).
 *
 * Winding numbers need consistently oriented faces. By default the constructor therefore orients
 * a copy of the faces with computeOutwardFaceSigns() (face_orientation.h; see its limits), after
 * welding vertices at equal positions so that unwelded meshes connect; the caller's mesh is not
 * changed. Faces with a repeated (welded) corner, an out-of-range index or a non-finite corner are
 * ignored.
 */
class WindingNumber
{
public:
  using Ptr = std::shared_ptr<WindingNumber>;
  using ConstPtr = std::shared_ptr<const WindingNumber>;

  /** \brief Builds the hierarchy, O(F log F).
   * \param[in] mesh the surface
   * \param[in] fix_orientation first orient faces consistently and outward
   *            (computeOutwardFaceSigns)
   */
  explicit WindingNumber(const TriangleMesh& mesh, bool fix_orientation = true);

  /** \brief Far-field accuracy β (default 2, as in Barill et al.): a node is expanded when the
   * query is farther than β times its radius. Larger is more exact and slower; β ≤ 0 or
   * infinity gives the exact sum.
   */
  void
  setAccuracy(double beta)
  {
    beta_ = beta;
  }

  /** \brief Far-field accuracy β. */
  double
  getAccuracy() const
  {
    return beta_;
  }

  /** \brief Hierarchical winding number at q (exact when β makes every node "near"). */
  double
  operator()(const Eigen::Vector3d& q) const;

  /** \brief Exact winding number at q: the sum over all faces, O(F). For tests and references. */
  double
  exact(const Eigen::Vector3d& q) const;

  /** \brief True when the winding number at q exceeds 0.5. */
  bool
  inside(const Eigen::Vector3d& q) const
  {
    return (*this)(q) > 0.5;
  }

  /** \brief Winding numbers of many points; OpenMP-parallel over points when `threads` > 1
   * (results do not depend on the thread count).
   * \param[in] queries the points
   * \param[out] values one winding number per point
   * \param[in] threads number of threads (0: OpenMP's default)
   */
  void
  evaluate(const std::vector<Eigen::Vector3d>& queries, std::vector<double>& values,
           unsigned threads = 1) const;

  /** \brief True when the (oriented) mesh has no boundary: every edge, with vertices at equal
   * positions taken as one, is walked as often in one direction as in the other. The winding
   * number of such a mesh is an integer everywhere off the surface and changes only where a path
   * crosses a face, which windingNumberChange() exploits.
   */
  bool
  isClosed() const
  {
    return closed_;
  }

  /** \brief w(to) − w(from) for a closed mesh, counted as the signed number of faces the segment
   * crosses (−1 for each face crossed from its back to its front), O(log F) for short segments.
   *
   * Edge tests are evaluated on the edge's corners in a fixed (welded index) order, so a segment
   * through a shared edge is counted by exactly one of its faces. A segment that passes within
   * 1e-10 × the mesh's size of an edge or vertex, or that ends on a face, is reported as uncertain.
   * \param[in] from start point
   * \param[in] to end point
   * \param[out] change w(to) − w(from) when true is returned
   * \return false when the mesh is not closed or the count is uncertain (evaluate w instead)
   */
  bool
  windingNumberChange(const Eigen::Vector3d& from, const Eigen::Vector3d& to, int& change) const;

  /** \brief Number of faces the orientation repair flipped in the constructor. */
  std::size_t
  numFlippedFaces() const
  {
    return num_flipped_;
  }

  /** \brief Number of faces used (degenerate and invalid ones excluded). */
  std::size_t
  numFaces() const
  {
    return triangles_.size();
  }

private:
  struct Node
  {
    Eigen::Vector3d center = Eigen::Vector3d::Zero(); ///< area-weighted centre p̃
    Eigen::Vector3d dipole = Eigen::Vector3d::Zero(); ///< Σ a_f n_f (half cross products)
    Eigen::Matrix3d moment = Eigen::Matrix3d::Zero(); ///< ∫ (p − p̃) nᵀ dA
    Eigen::Matrix3d second[3];                        ///< second[k] = ∫ (p − p̃)(p − p̃)ᵀ n_k dA
    Eigen::Vector3d second_trace = Eigen::Vector3d::Zero(); ///< k ↦ trace(second[k])
    Eigen::Vector3d second_diag = Eigen::Vector3d::Zero();  ///< Σ_i second[i].col(i)
    double radius2 = 0.0;                             ///< squared radius of the ball about p̃
    int begin = 0, end = 0;                           ///< face range [begin, end)
    int right = -1;                                   ///< right child (left is this + 1); -1: leaf
  };

  void
  computeMoments();

  int
  build(int begin, int end, std::vector<Eigen::Vector3d>& centroids, std::vector<int>& order);

  /** Axis-aligned box of a node with its face range and right child (copies of the Node's),
   * kept apart from the ~400-byte moments so that a segment query's traversal reads one 64-byte
   * record per node. */
  struct Box
  {
    Eigen::Vector3d lo, hi;
    int begin = 0, end = 0; ///< face range [begin, end)
    int right = -1;         ///< right child (left is this + 1); -1: leaf
  };

  std::vector<Box> boxes_;                 ///< per node, same indices as nodes_
  std::vector<Eigen::Matrix3d> triangles_; ///< corners as columns, in hierarchy order
  /// (t1 − t0) × (t2 − t0) and its length per face, precomputed for segment queries
  std::vector<Eigen::Vector4d> face_normals_;
  std::vector<Eigen::Vector3i> corner_ids_; ///< welded vertex index of each corner
  double size_ = 0.0;                        ///< bounding-box diagonal of the faces
  bool closed_ = false;
  std::vector<Node> nodes_;
  double beta_ = 2.0;
  std::size_t num_flipped_ = 0;
};

} // namespace segmat
