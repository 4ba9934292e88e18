/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once

#include <segmat/geometry/delaunay_3d.h>
#include <segmat/geometry/medial_mesh.h>
#include <segmat/geometry/triangle_mesh.h>

#include <Eigen/Core>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace segmat {

class WindingNumber;

/** \brief Sizes and per-stage wall-clock times of one VoronoiMat::compute run. */
struct VoronoiMatStatistics
{
  std::size_t num_samples = 0;           ///< surface samples given to the Delaunay step
  std::size_t num_tetrahedra = 0;        ///< finite Delaunay tetrahedra
  std::size_t num_inside = 0;            ///< tetrahedra whose circumcentre is inside the shape
  std::size_t num_winding_evaluations = 0; ///< circumcentres whose winding number was evaluated
  std::size_t num_vertices = 0;          ///< medial-mesh vertices
  std::size_t num_edges = 0;             ///< medial-mesh edges
  std::size_t num_triangles = 0;         ///< medial-mesh triangles
  double seconds_sampling = 0.0;         ///< validation, sampling, deduplication, jitter
  double seconds_delaunay = 0.0;         ///< qhull and reading its tetrahedra back
  double seconds_inside = 0.0;           ///< winding-number hierarchy and inside test
  double seconds_assembly = 0.0;         ///< Voronoi edges and faces, MedialMesh construction
};

/** \brief The initial (unsimplified) Voronoi medial mesh of a closed triangle mesh: step one of
 * Q-MAT (Li, Wang, Sun, Komura, Wang, Taku, "Q-MAT: Computing Medial Axis Transform by Quadratic
 * Error Minimization", ACM TOG 2015), which SEG-MAT (Lin et al. 2022) builds on.
 *
 * 1. Sample the surface: every used mesh vertex, plus points on long edges and inside big
 *    triangles so that the gap is at most `max_spacing` (sampleSurface()); duplicates within
 *    1e-9 of the bounding-box diagonal are merged; more than `max_sample_count` samples are
 *    thinned where they are densest (thinPointsToCount()); each sample is moved by a seeded,
 *    index-hashed jitter of `jitter` × diagonal so that grid-like CAD input cannot stall qhull.
 * 2. 3D Delaunay tetrahedralisation: by default the exact incremental code
 *    (delaunayTetrahedralizeExact(), samples snapped to a 2^22 grid, 3–5× faster than qhull and
 *    the same tetrahedra on generic input); optionally qhull (`d Qt Qbb Qz`, libqhull_r). If the
 *    exact code fails, qhull is tried.
 * 3. A tetrahedron is inside when its circumcentre lies in the mesh's bounding box and has a
 *    generalised winding number above 0.5 (WindingNumber, robust to small holes and mixed
 *    orientation; Q-MAT's CGAL code used a point-in-polyhedron test).
 *    For a closed mesh the winding number is evaluated once per connected group of tetrahedra
 *    and carried across Voronoi edges by counting the faces they cross
 *    (WindingNumber::windingNumberChange), falling back to evaluation where that count is
 *    uncertain; for an open mesh it is evaluated at every circumcentre.
 *    Flat tetrahedra (no finite circumcentre) are never inside.
 * 4. Medial vertices are the circumcentres of inside tetrahedra, radius = circumradius; medial
 *    edges are Voronoi edges (dual to Delaunay facets) whose two tetrahedra are inside; medial
 *    faces are Voronoi faces (dual to Delaunay edges) whose whole ring of tetrahedra is finite and
 *    inside, fan-triangulated from the lowest-indexed tetrahedron of the ring, the fan's diagonals
 *    added as edges (as Q-MAT's initial MAT).
 *
 * With `max_spacing` = 0 and no sample limit the samples are the mesh vertices alone, which is
 * Q-MAT's own input.
 * No pole filtering or pruning is done (Q-MAT does none either; its simplification removes spikes).
 *
 * \code
 * segmat::VoronoiMat vmat;
 * vmat.setInputMesh(mesh);            // TriangleMesh::ConstPtr
 * segmat::MedialMesh mat;
 * if (vmat.compute(mat))
 *   std::cout << mat.numVertices() << " spheres\n";
 * \endcode
 */
class VoronoiMat
{
public:
  using Ptr = std::shared_ptr<VoronoiMat>;
  using ConstPtr = std::shared_ptr<const VoronoiMat>;

  /** \brief Defaults: max spacing 0.015 × diagonal, at most 12000 samples, jitter 1e-6 ×
   * diagonal, winding-number accuracy β = 2, one thread. */
  VoronoiMat();

  /** \brief The surface to compute the medial mesh of (should be closed; open meshes get a best
   * effort through the winding number). */
  void
  setInputMesh(const TriangleMesh::ConstPtr& mesh)
  {
    mesh_ = mesh;
  }

  /** \brief The input surface. */
  const TriangleMesh::ConstPtr&
  getInputMesh() const
  {
    return mesh_;
  }

  /** \brief Largest gap between surface samples, relative to the bounding-box diagonal (default
   * 0.015; 0 samples the mesh vertices only, as Q-MAT does). */
  void
  setMaxSpacing(double relative_spacing)
  {
    max_spacing_ = relative_spacing;
  }

  /** \brief Largest gap between surface samples, relative to the bounding-box diagonal. */
  double
  getMaxSpacing() const
  {
    return max_spacing_;
  }

  /** \brief Surface samples to use instead of sampling the input mesh (e.g. the points of a
   * cloud whose mesh is only a splat surface for the inside test; see CloudMedialMeshEstimation).
   * They are deduplicated, thinned to the sample limit and jittered like mesh samples; the mesh
   * then only serves the inside test and the bounding box. Null (the default) samples the mesh.
   *
   * With outward unit \a normals (one per sample), the centre of a ball wider than twice the
   * sample spacing (√(area / samples)) that lies clearly on the inner side of all four of its
   * samples' tangent planes — the direction to each sample within 60° of its normal, as at a
   * pole — is inside without a winding number, and one clearly on the outer side of all four is
   * outside; only the others (small balls, which noise leaves against the surface; a centre near
   * a tangent plane; samples that disagree, as across a thin wall) are evaluated. On a clean
   * cloud that skips most evaluations and changes no decision (test_cloud_medial_mesh). The
   * normals must be consistently oriented: four flipped ones around an exterior ball make it
   * look like a pole of the inside (docs/noise.md, "Limits").
   * \param[in] samples the points, or null
   * \param[in] normals their outward unit normals, or null (winding number everywhere) */
  void
  setSurfaceSamples(std::shared_ptr<const std::vector<Eigen::Vector3d>> samples,
                    std::shared_ptr<const std::vector<Eigen::Vector3d>> normals = nullptr)
  {
    surface_samples_ = std::move(samples);
    surface_normals_ = std::move(normals);
  }

  /** \brief The surface samples given with setSurfaceSamples() (null: the mesh is sampled). */
  const std::shared_ptr<const std::vector<Eigen::Vector3d>>&
  getSurfaceSamples() const
  {
    return surface_samples_;
  }

  /** \brief Largest number of surface samples (default 12000; 0: no limit). Denser samplings
   * are thinned by greedy Poisson-disk elimination (thinPointsToCount()), mesh vertices having
   * priority over fill points: sparse regions keep every sample, only the densest are thinned.
   * The whole step costs about 13 µs per sample and the medial mesh has about 3.4 vertices per
   * sample, so this bounds the time of this step and of the simplification after it.
   */
  void
  setMaxSampleCount(std::size_t count)
  {
    max_samples_ = count;
  }

  /** \brief Largest number of surface samples (0: no limit). */
  std::size_t
  getMaxSampleCount() const
  {
    return max_samples_;
  }

  /** \brief Bytes compute() needs for \a mesh sampled at \a relative_spacing (x the bounding-box
   * diagonal) with at most \a max_sample_count samples kept (0: all): the candidate samples
   * (estimateSurfaceSampleCount) at kBytesPerCandidate each plus the kept ones at
   * kBytesPerSample each (Delaunay tetrahedra, Voronoi vertices, the medial mesh). compute()
   * refuses to start, with an error, when this exceeds availableMemoryBytes(): an absurd spacing
   * stops at once instead of swapping.
   */
  static double
  estimateMemoryBytes(const TriangleMesh& mesh, double relative_spacing,
                      std::size_t max_sample_count);

  static constexpr double kBytesPerCandidate = 200.0; ///< sampling, welding, thinning
  static constexpr double kBytesPerSample = 4500.0;   ///< peak per kept sample, measured

  /** \brief Size of the deterministic jitter relative to the bounding-box diagonal (default 1e-6;
   * 0 disables it, which can make qhull very slow on grid-like input). */
  void
  setJitter(double relative_jitter)
  {
    jitter_ = relative_jitter;
  }

  /** \brief Size of the deterministic jitter relative to the bounding-box diagonal. */
  double
  getJitter() const
  {
    return jitter_;
  }

  /** \brief Which deterministic jitter the samples get (default 0). Each seed is an equally
   * valid draw of displacements below the jitter size; segmenting under several seeds shows
   * how much a shape's parts depend on such sub-micro displacements (bench_noise --draws). */
  void
  setJitterSeed(std::uint32_t seed)
  {
    jitter_seed_ = seed;
  }

  /** \brief Which deterministic jitter the samples get. */
  std::uint32_t
  getJitterSeed() const
  {
    return jitter_seed_;
  }

  /** \brief The Delaunay code (default DelaunayMethod::Exact). */
  void
  setDelaunayMethod(DelaunayMethod method)
  {
    delaunay_method_ = method;
  }

  /** \brief The Delaunay code. */
  DelaunayMethod
  getDelaunayMethod() const
  {
    return delaunay_method_;
  }

  /** \brief Accuracy β of the hierarchical winding number (default 2; see WindingNumber). */
  void
  setWindingNumberAccuracy(double beta)
  {
    beta_ = beta;
  }

  /** \brief Accuracy β of the hierarchical winding number. */
  double
  getWindingNumberAccuracy() const
  {
    return beta_;
  }

  /** \brief Winding-number hierarchy of the input mesh to use for the inside test instead of
   * building one in compute() (saves its O(F log F) construction when another stage, such as
   * QmatSimplification, needs the same one). It must have been built from the input mesh with
   * the default orientation repair; its own accuracy (WindingNumber::setAccuracy) then replaces
   * setWindingNumberAccuracy(). Null (the default) builds one per compute().
   * \param[in] winding_number the hierarchy, or null */
  void
  setWindingNumber(std::shared_ptr<const WindingNumber> winding_number)
  {
    winding_number_ = std::move(winding_number);
  }

  /** \brief The shared winding-number hierarchy (null unless set). */
  const std::shared_ptr<const WindingNumber>&
  getWindingNumber() const
  {
    return winding_number_;
  }

  /** \brief Threads for the inside test (default 1; 0: OpenMP's default). The output does not
   * depend on it. */
  void
  setNumberOfThreads(unsigned threads)
  {
    threads_ = threads;
  }

  /** \brief Threads for the inside test. */
  unsigned
  getNumberOfThreads() const
  {
    return threads_;
  }

  /** \brief Computes the initial medial mesh.
   * \param[out] output the medial mesh (empty on failure)
   * \return false, with a PCL_ERROR message, when there is no input, when it has a non-finite
   *         coordinate or an out-of-range face index, when there are fewer than 4 distinct samples
   *         or they are coplanar, or when qhull fails; true otherwise (possibly with an empty
   *         medial mesh, e.g. for an open sheet that encloses nothing)
   */
  bool
  compute(MedialMesh& output);

  /** \brief Sizes and timings of the last compute() call. */
  const VoronoiMatStatistics&
  getStatistics() const
  {
    return statistics_;
  }

  /** \brief The surface samples of the last compute() call, after deduplication, thinning,
   * jitter and (exact Delaunay) grid snapping: the points the tetrahedralisation is Delaunay for.
   */
  const std::vector<Eigen::Vector3d>&
  getSamples() const
  {
    return samples_;
  }

private:
  /** Step 1: fills samples_ (and the sample count); false with a PCL_ERROR when < 4. */
  bool
  sample(const TriangleMesh& mesh, double diagonal);

  /** Step 2: tetrahedralises samples_ and replaces them by the points it is Delaunay for. */
  bool
  tetrahedralize(DelaunayTetrahedra& delaunay);

  TriangleMesh::ConstPtr mesh_;
  std::shared_ptr<const WindingNumber> winding_number_; ///< shared hierarchy, or null
  std::shared_ptr<const std::vector<Eigen::Vector3d>> surface_samples_; ///< given samples, or null
  std::shared_ptr<const std::vector<Eigen::Vector3d>> surface_normals_; ///< their normals, or null
  double max_spacing_;
  std::size_t max_samples_;
  double jitter_;
  std::uint32_t jitter_seed_ = 0;
  DelaunayMethod delaunay_method_;
  double beta_;
  unsigned threads_;
  VoronoiMatStatistics statistics_;
  std::vector<Eigen::Vector3d> samples_;
  std::vector<Eigen::Vector3d> sample_normals_; ///< one per sample when surface_normals_ is set
};

} // namespace segmat
