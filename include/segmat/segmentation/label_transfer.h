/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once

#include <segmat/geometry/triangle_mesh.h>
#include <segmat/graph_cut/alpha_expansion.h>
#include <segmat/medial/mat_graph.h>

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <Eigen/Core>

#include <memory>
#include <vector>

namespace segmat {

namespace detail {
struct BoundaryGraph;
} // namespace detail

/** \brief SEG-MAT's integer energy scale (reference `int enlarge = 10e4`, i.e. 1e5). Terms are
 * truncated to integers as in the reference, which also keeps every max-flow sum exact.
 */
constexpr double kTransferEnergyScale = 1e5;

/** \brief Graph-cut data term of SEG-MAT (Lin et al. 2022, §5; the authors' `transfer_MAT_mesh`).
 *
 * D(i, l) = ⌊ max(0, min_{s ∈ part l} (|x_i − c_s| − r_s)) / B · 1e5 ⌋, where s runs over the
 * spheres of part l's (coarse) MAT-graph nodes and B is the diagonal of the bounding box of all
 * sphere centres (graph.centerBoundingBoxDiagonal(); 1 when that is 0). A part without any
 * sphere costs 1e9 everywhere, so it never wins; a non-finite position costs 0 for every other
 * part (its neighbours decide). Exact, with one SphereTree per part.
 * \param[in] positions query points (face centroids, cloud points)
 * \param[in] graph the MAT graph whose node indices \a parts holds (must be valid indices)
 * \param[in] parts per part, its MAT-graph nodes
 * \param[in] threads threads (0: OpenMP's choice; the costs do not depend on it)
 * \return positions.size() × parts.size() costs
 */
Eigen::MatrixXd
computePartDistanceCosts(const std::vector<Eigen::Vector3d>& positions, const MatGraph& graph,
                         const std::vector<std::vector<int>>& parts, unsigned int threads = 0);

/** \brief How computeCreaseCost() prices a cut across a concave crease.
 *
 * Both models price a flat or convex pair alike: 2·⌊ω·(360 − θ)/180 · 1e5⌋ (a flat edge costs
 * 2ω·1e5). They differ on concave pairs only.
 */
enum class CreaseModel
{
  /** SEG-MAT's `smoothFn`: 2·⌊ω·(180 − θ)/180 · 1e5⌋. Any concave pair, however shallow, costs
   * at most half a flat edge (the jump at θ = 0), and a deep crease costs
   * little less than a shallow one (90°: a quarter of a flat edge; 10°: 0.47). */
  Reference,
  /** 2·⌊2ω·exp(−θ/τ) · 1e5⌋ with τ = kConcaveCreaseAngle (10°): continuous at θ = 0, and the
   * price falls fast with the crease's depth (10°: 0.37 of a flat edge, 20°: 0.14, 45°: 0.011),
   * so a cut follows a real concave seam — where people cut (the minima rule) — rather than
   * the shortest loop of noise-level concave edges. Not in SEG-MAT; the default (its effect on
   * the PSB scores: docs/benchmarks.md). */
  SharpConcave
};

/** \brief Angle scale τ of CreaseModel::SharpConcave, in degrees: a concave crease of τ costs
 * 1/e of a flat edge. The scores are insensitive to τ between 5° and 20°.
 */
constexpr double kConcaveCreaseAngle = 10.0;

/** \brief Cost of cutting between two surface elements (the authors' `smoothFn`), both
 * registrations of the reference summed: with CreaseModel::Reference 2·⌊ω·(180 − θ)/180 · 1e5⌋
 * for a concave pair and 2·⌊ω·(360 − θ)/180 · 1e5⌋ for a convex or flat one, θ the angle
 * between the normals in degrees (CreaseModel::SharpConcave prices concave pairs differently).
 *
 * Concave means that each element lies on the outer side of the other: (c_b − c_a)·(n_a − n_b)
 * > 1e-6·|c_b − c_a|. This is the reference test ((centroid midpoint − edge midpoint)·n_a >
 * 1e-6) made symmetric in a and b and free of the mesh's units (the reference evaluated it with
 * one face's normal only, and with an absolute tolerance). Needs outward normals.
 *
 * With CreaseModel::Reference the jump at θ = 0 is kept: any concave
 * crease, however shallow, costs at most half of a flat edge, and the data/smoothness balance
 * stays the one the authors tuned (the cloud transfer is calibrated on it).
 * Zero or non-finite normals give θ = 90° and count as convex: finite, never NaN.
 * \param[in] centre_a centroid (or position) of element a
 * \param[in] normal_a outward unit normal of a
 * \param[in] centre_b centroid (or position) of element b
 * \param[in] normal_b outward unit normal of b
 * \param[in] omega ω, the smoothness weight (paper default 0.3)
 * \param[in] model how a concave pair is priced (default: the reference's rule)
 */
double
computeCreaseCost(const Eigen::Vector3d& centre_a, const Eigen::Vector3d& normal_a,
                  const Eigen::Vector3d& centre_b, const Eigen::Vector3d& normal_b,
                  double omega, CreaseModel model = CreaseModel::Reference);

/** \brief The Potts edges of a mesh's face graph: one per face adjacency of
 * TriangleMesh::faceAdjacency() (border edges have none, non-manifold edges pair all their
 * faces), weighted by computeCreaseCost() on outward normals (computeOutwardFaceSigns()).
 * \param[in] mesh the surface
 * \param[in] omega ω
 * \param[in] model how concave pairs are priced (default: the reference's rule)
 */
std::vector<PottsEdge>
computeMeshSmoothnessEdges(const TriangleMesh& mesh, double omega,
                           CreaseModel model = CreaseModel::Reference);

/** \brief The Potts edges of a cloud's symmetric k-nearest-neighbour graph (an edge when either
 * point is among the other's k nearest), weighted by computeCreaseCost() between the points'
 * outward normals — or the flat-edge cost when \a normals is null — times 2/k. A symmetric
 * k-NN graph crosses a boundary with more (and longer) edges than a mesh's face graph; 2/k was
 * calibrated on teddy: area-uniform samples of 20k–1M points labelled this way agree with the
 * mesh transfer's face labels on 96–97.6 % of the points, and keep all 8 parts (3/k lost the
 * ears at 20k voxel representatives).
 * \param[in] cloud the points (searched with pcl::KdTreeFLANN's answers)
 * \param[in] normals outward unit normals, one per cloud point, or null
 * \param[in] nodes the cloud indices that are graph nodes (finite points); node a is nodes[a]
 * \param[in] k neighbours per point
 * \param[in] omega ω
 * \param[in] model how concave pairs are priced
 * \param[in] threads threads of the neighbour search (0: OpenMP's choice; the edges do not
 * depend on it)
 * \return edges between node numbers (positions in \a nodes), each pair once, sorted
 */
std::vector<PottsEdge>
computeCloudSmoothnessEdges(const pcl::PointCloud<pcl::PointXYZ>::ConstPtr& cloud,
                            const pcl::PointCloud<pcl::Normal>::ConstPtr& normals,
                            const std::vector<int>& nodes, int k, double omega,
                            CreaseModel model = CreaseModel::Reference, unsigned int threads = 0);

/** \brief Renumber labels densely (0..k−1) keeping their order; negative labels stay as they
 * are (unassigned). Absent labels disappear (as the authors' post-processing).
 * \return k, the number of distinct non-negative labels
 */
int
compactLabels(std::vector<int>& labels);

/** \brief What both transfers share: the MAT graph, its parts and the optimiser settings. */
class LabelTransferBase
{
public:
  virtual ~LabelTransferBase() = default;

  /** \brief The MAT graph whose nodes the parts refer to. */
  void
  setInputGraph(const MatGraph::ConstPtr& graph)
  {
    graph_ = graph;
  }

  /** \brief The MAT graph. */
  MatGraph::ConstPtr
  getInputGraph() const
  {
    return graph_;
  }

  /** \brief Parts as lists of MAT-graph nodes: the grower's *coarse* groups
   * (MatRegionGrowing::getCoarseParts(); swallowed and tiny nodes never enter the data term).
   * Label l of the output is part l (before compaction).
   */
  void
  setParts(const std::vector<std::vector<int>>& parts)
  {
    parts_ = parts;
  }

  /** \brief The parts. */
  const std::vector<std::vector<int>>&
  getParts() const
  {
    return parts_;
  }

  /** \brief Threads of the data term and of the cloud's neighbour search (0, the default:
   * OpenMP's choice). The labels do not depend on it. */
  void
  setNumberOfThreads(unsigned int threads)
  {
    threads_ = threads;
  }

  /** \brief The thread count (0: OpenMP's choice). */
  unsigned int
  getNumberOfThreads() const
  {
    return threads_;
  }

  /** \brief ω, weight of the smoothness term (SEG-MAT default 0.3). Negative or non-finite
   * values are ignored with a warning. 0 gives the per-element nearest part.
   */
  void
  setSmoothnessWeight(double omega);

  /** \brief ω. */
  double
  getSmoothnessWeight() const
  {
    return omega_;
  }

  /** \brief How a cut across a concave crease is priced (default CreaseModel::SharpConcave;
   * CreaseModel::Reference reproduces SEG-MAT's transfer, e.g. teddy's reference parts).
   */
  void
  setCreaseModel(CreaseModel model)
  {
    crease_model_ = model;
  }

  /** \brief How a cut across a concave crease is priced. */
  CreaseModel
  getCreaseModel() const
  {
    return crease_model_;
  }

  /** \brief Largest number of α-expansion cycles (default 100, i.e. until converged; the
   * reference ran 2).
   */
  void
  setMaxCycles(int cycles)
  {
    solver_.setMaxCycles(cycles);
  }

  /** \brief Largest number of α-expansion cycles. */
  int
  getMaxCycles() const
  {
    return solver_.getMaxCycles();
  }

  /** \brief Energy of the last labelling (in the integer units of kTransferEnergyScale). */
  double
  getEnergy() const
  {
    return energy_;
  }

  /** \brief For each output label of the last transfer, the indices of its parts in getParts(),
   * ascending: one part, or several that setJoinFlatBoundaries() joined (labels are compacted:
   * parts that won no element get no label).
   */
  const std::vector<std::vector<int>>&
  getLabelParts() const
  {
    return label_parts_;
  }

  /** \brief Join parts whose shared boundary crosses flat surface (default true).
   *
   * People cut shapes where the surface folds inwards (the minima rule, Hoffman & Richards
   * 1984), and the crease term already draws the cut along such folds. But the medial axis
   * also splits a shape where its thickness changes without any fold: the middle of a box's
   * face lies on spheres of the box's full half-thickness, its rims on the thinner spheres
   * near the edges, and the cut can follow that split across the flat face. After the cut, two
   * labels become one when, along most of their boundary, the surface curves less than the
   * shape's bounding sphere: the median of |θ| / d over the boundary's edges (θ the turn of the
   * outward normals across the edge, d the distance between the two elements; weighted by the
   * shared edge's length on a mesh) is at most 2 / the surface's bounding-box diagonal. The
   * flattest boundary is joined first, then the others are measured again. A cloud without
   * normals is never joined. Not in SEG-MAT (docs/method.md, §5).
   */
  void
  setJoinFlatBoundaries(bool join);

  /** \brief Whether parts with a flat boundary are joined. */
  bool
  getJoinFlatBoundaries() const
  {
    return join_flat_boundaries_;
  }

  /** \brief Smallest share of the surface a part may keep: of the mesh's area, or of the
   * cloud's points (default 0.002, the value of the grower's minimal region η). A part
   * that the cut leaves with less is dropped, and its elements alone are cut again among the
   * other parts (every other element keeps its label), so they go to the parts that suit them
   * best; noise leaves such slivers where a medial island wins a handful of faces. 0 keeps
   * every part that wins an element. Values outside [0, 1) are ignored with a warning.
   */
  void
  setMinPartFraction(double fraction);

  /** \brief Smallest share of the surface a part may keep. */
  double
  getMinPartFraction() const
  {
    return min_part_fraction_;
  }

  /** \brief Largest number of elements (faces, or the cloud's graph points) cut at full
   * resolution in one α-expansion (default 65536; 0: no limit).
   *
   * The cut's cost grows with the elements times the parts; a scanned mesh of 800 000 faces
   * would spend most of its time in it. A larger surface is cut coarse to fine: its elements
   * are grouped into connected clusters, half as many as the limit; the clusters are labelled
   * by α-expansion of the summed costs; and the elements of the clusters within three clusters
   * of a boundary are labelled again at full resolution, with every other element held. The
   * boundaries so follow the fine edges, but the coarse cut can settle in another local optimum
   * a few clusters away (docs/method.md, §5). Every psb-dev mesh has fewer faces than the default,
   * and is cut whole.
   */
  void
  setMaxFullCutElements(std::size_t count)
  {
    max_full_cut_ = count;
  }

  /** \brief Largest number of elements cut at full resolution in one α-expansion. */
  std::size_t
  getMaxFullCutElements() const
  {
    return max_full_cut_;
  }

  /** \brief α-expansion cycles run by the last transfer's first cut (of the clusters, for a
   * surface cut coarse to fine). */
  int
  getCycles() const
  {
    return cycles_;
  }

protected:
  LabelTransferBase() = default;

  /** \brief Check the graph and the parts, then label \a positions: data term, cached
   * smoothness edges (already in solver_), α-expansion, dropping parts below the minimal
   * share of \a weights (one per position; empty: equal), compaction.
   */
  bool
  solve(const char* caller, const std::vector<Eigen::Vector3d>& positions,
        const std::vector<double>& weights, std::vector<int>& labels);

  /** \brief True when the cached smoothness edges are missing or were built with another ω
   * or crease model. */
  bool
  edgesStale() const
  {
    return !edges_valid_ || edges_omega_ != omega_ || edges_crease_ != crease_model_;
  }

  /** \brief Records that the solver's edges now match ω and the crease model. */
  void
  markEdgesBuilt()
  {
    edges_valid_ = true;
    edges_omega_ = omega_;
    edges_crease_ = crease_model_;
  }

  MatGraph::ConstPtr graph_;
  std::vector<std::vector<int>> parts_;
  double omega_ = 0.3;
  double min_part_fraction_ = 0.002;
  std::size_t max_full_cut_ = 65536;
  CreaseModel crease_model_ = CreaseModel::SharpConcave;
  unsigned int threads_ = 0;
  bool edges_valid_ = false; ///< the solver holds smoothness edges of the current input
  double edges_omega_ = 0.0;
  CreaseModel edges_crease_ = CreaseModel::SharpConcave;
  /** \brief A new, empty boundary list for the smoothness edges being built. */
  detail::BoundaryGraph*
  newBoundary();

  AlphaExpansion solver_;
  double energy_ = 0.0; ///< of the last labelling, after dropping parts
  int cycles_ = 0;
  std::vector<std::vector<int>> label_parts_;
  bool join_flat_boundaries_ = true;
  /// The smoothness edges as joinFlatBoundaries() reads them.
  std::shared_ptr<detail::BoundaryGraph> boundary_;
};

/** \brief Carries parts of the MAT graph to the faces of a triangle mesh by α-expansion
 * (SEG-MAT, Lin et al. 2022, §5; reference `transfer_MAT_mesh`).
 *
 * Energy: computePartDistanceCosts() on face centroids plus computeMeshSmoothnessEdges(). The
 * mesh-dependent smoothness edges are computed once per mesh and ω and reused, so re-running
 * with new parts only pays for the data term and the cut.
 *
 * \code
 * segmat::MeshLabelTransfer transfer;
 * transfer.setInputMesh(mesh);      // TriangleMesh::ConstPtr
 * transfer.setInputGraph(graph);    // MatGraph::ConstPtr
 * transfer.setParts(coarse_parts);  // from MatRegionGrowing::getCoarseParts()
 * std::vector<int> face_labels;
 * if (!transfer.transfer(face_labels)) { ... }
 * \endcode
 */
class MeshLabelTransfer : public LabelTransferBase
{
public:
  using Ptr = std::shared_ptr<MeshLabelTransfer>;
  using ConstPtr = std::shared_ptr<const MeshLabelTransfer>;

  /** \brief ω = 0.3, CreaseModel::SharpConcave. */
  MeshLabelTransfer() = default;

  /** \brief The surface to label (any triangle mesh: open, non-manifold, inconsistently wound
   * and degenerate faces are handled).
   */
  void
  setInputMesh(const TriangleMesh::ConstPtr& mesh)
  {
    mesh_ = mesh;
    edges_valid_ = false;
  }

  /** \brief The surface. */
  TriangleMesh::ConstPtr
  getInputMesh() const
  {
    return mesh_;
  }

  /** \brief Label every face.
   * \param[out] face_labels one label per face, dense 0..k−1 in part order (empty on failure)
   * \return false (PCL_ERROR) when the mesh, the graph or the parts are missing or empty, or a
   *         part names a node outside the graph. One part → every face 0.
   */
  bool
  transfer(std::vector<int>& face_labels);

private:
  TriangleMesh::ConstPtr mesh_;
};

/** \brief Carries parts of the MAT graph to the points of a cloud by α-expansion: the mesh
 * transfer's energy on the symmetric k-nearest-neighbour graph of the points.
 *
 * Data term: computePartDistanceCosts() at the points. Smoothness: computeCloudSmoothnessEdges()
 * (normals, when given, must be oriented outward, as the medial estimation needs anyway). The
 * neighbour graph is built once per cloud, normals, k and ω. Clouds larger than
 * getMaxGraphPoints() are cut on voxel representatives (see setMaxGraphPoints()). Points with a
 * non-finite coordinate get label -1 and take no part.
 */
class CloudLabelTransfer : public LabelTransferBase
{
public:
  using Ptr = std::shared_ptr<CloudLabelTransfer>;
  using ConstPtr = std::shared_ptr<const CloudLabelTransfer>;

  /** \brief ω = 0.3, k = 10, at most 20000 graph points. */
  CloudLabelTransfer() = default;

  /** \brief The points to label. */
  void
  setInputCloud(const pcl::PointCloud<pcl::PointXYZ>::ConstPtr& cloud)
  {
    cloud_ = cloud;
    nodes_valid_ = false;
    edges_valid_ = false;
  }

  /** \brief The points. */
  pcl::PointCloud<pcl::PointXYZ>::ConstPtr
  getInputCloud() const
  {
    return cloud_;
  }

  /** \brief Outward unit normals, one per point (optional; null for none). */
  void
  setInputNormals(const pcl::PointCloud<pcl::Normal>::ConstPtr& normals)
  {
    normals_ = normals;
    edges_valid_ = false;
  }

  /** \brief The normals (may be null). */
  pcl::PointCloud<pcl::Normal>::ConstPtr
  getInputNormals() const
  {
    return normals_;
  }

  /** \brief k of the k-nearest-neighbour graph (default 10); values < 1 are ignored with a
   * warning.
   */
  void
  setNeighbourCount(int k);

  /** \brief k of the k-nearest-neighbour graph. */
  int
  getNeighbourCount() const
  {
    return k_;
  }

  /** \brief Largest number of points the graph cut works on (default 20000; 0: no limit).
   * A larger cloud is cut on one representative point per voxel (the voxel edge is chosen so
   * that about this many voxels are occupied on a surface) and every point takes its voxel's
   * label: linear in the cloud size, with the boundary resolution of a 20k-point sample
   * (teddy's mesh has 19k faces).
   */
  void
  setMaxGraphPoints(std::size_t count)
  {
    max_graph_points_ = count;
    nodes_valid_ = false;
    edges_valid_ = false;
  }

  /** \brief Largest number of points the graph cut works on. */
  std::size_t
  getMaxGraphPoints() const
  {
    return max_graph_points_;
  }

  /** \brief Label every point.
   * \param[out] point_labels one label per point: dense 0..k−1 in part order, -1 for
   *             non-finite points (empty on failure)
   * \return false (PCL_ERROR) when the cloud, the graph or the parts are missing or empty, the
   *         normals' size differs from the cloud's, or a part names a node outside the graph.
   */
  bool
  transfer(std::vector<int>& point_labels);

private:
  pcl::PointCloud<pcl::PointXYZ>::ConstPtr cloud_;
  pcl::PointCloud<pcl::Normal>::ConstPtr normals_;
  int k_ = 10;
  bool nodes_valid_ = false;
  std::size_t max_graph_points_ = 20000;
  std::vector<int> nodes_;         ///< cloud index of each graph node
  std::vector<int> node_of_point_; ///< graph node of each cloud point (-1: not finite)
};

} // namespace segmat
