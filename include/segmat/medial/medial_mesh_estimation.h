/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once

#include <segmat/geometry/medial_mesh.h>
#include <segmat/geometry/triangle_mesh.h>
#include <segmat/medial/voronoi_mat.h>

#include <cstddef>
#include <memory>

namespace segmat {

/** \brief Counts and wall-clock seconds of one MedialMeshEstimation::compute run. */
struct MedialMeshEstimationStatistics
{
  std::size_t initial_spheres = 0;    ///< spheres of the initial Voronoi medial mesh
  /// holes of the initial MAT's sheets closed before Q-MAT because their rim balls cover them
  std::size_t filled_holes = 0;
  std::size_t base_spheres = 0;       ///< spheres of the base MAT
  std::size_t structured_spheres = 0; ///< spheres of the structured MAT
  /// VoronoiMat (sampling, Delaunay, inside test, assembly) and the covered-hole filling
  double seconds_initial = 0.0;
  double seconds_simplification = 0.0; ///< QmatSimplification (both targets, one run)
  double seconds_total = 0.0;         ///< the whole compute()
  VoronoiMatStatistics voronoi;       ///< the initial step's own sizes and stage times
};

/** \brief The two medial meshes SEG-MAT needs, straight from a triangle mesh (Lin et al.,
 * "SEG-MAT: 3D Shape Segmentation Using Medial Axis Transform", TVCG 2022, §3): the initial
 * Voronoi MAT (VoronoiMat), simplified by Q-MAT (QmatSimplification, Li et al. 2015) to the base
 * MAT and, in the same collapse sequence, to the structured MAT. Q-MAT's normalisation is the
 * surface's bounding-box diagonal, as in the published code. Before Q-MAT, every hole of a
 * medial sheet that the balls on its rim cover is closed: such a hole has no hole of the shape
 * behind it (noise makes them), and Q-MAT, which keeps the topology, would otherwise turn the
 * sheet around it into a net of lines (docs/noise.md).
 *
 * \code
 * segmat::MedialMeshEstimation estimation;
 * estimation.setInputMesh(mesh);          // TriangleMesh::ConstPtr
 * segmat::MedialMesh base, structured;
 * if (estimation.compute(base, structured))
 *   std::cout << base.numVertices() << " / " << structured.numVertices() << " spheres\n";
 * \endcode
 */
class MedialMeshEstimation
{
public:
  using Ptr = std::shared_ptr<MedialMeshEstimation>;
  using ConstPtr = std::shared_ptr<const MedialMeshEstimation>;

  /** \brief Defaults: base 2000 spheres, structured max(15, ⌊0.001 × initial spheres⌋), and
   * VoronoiMat's sampling defaults (max spacing 0.015, at most 12000 samples). */
  MedialMeshEstimation() = default;

  /** \brief The closed triangle mesh whose medial axis is wanted. */
  void setInputMesh(const TriangleMesh::ConstPtr& mesh) { mesh_ = mesh; }
  /** \brief The input mesh. */
  const TriangleMesh::ConstPtr& getInputMesh() const { return mesh_; }

  /** \brief Spheres of the base MAT (default 2000; see QmatSimplification::setBaseTarget). */
  void setBaseTarget(int n) { simplification_base_target_ = n; }
  /** \brief Spheres of the base MAT. */
  int getBaseTarget() const { return simplification_base_target_; }

  /** \brief Spheres of the structured MAT (default −1: max(15, ⌊0.001 × initial⌋)). */
  void setStructuredTarget(int n) { simplification_structured_target_ = n; }
  /** \brief Spheres of the structured MAT (−1: automatic). */
  int getStructuredTarget() const { return simplification_structured_target_; }

  /** \brief Largest surface-sample gap relative to the diagonal (VoronoiMat::setMaxSpacing;
   * default 0.015, 0 = mesh vertices only as in Q-MAT). */
  void setMaxSpacing(double relative_spacing) { voronoi_.setMaxSpacing(relative_spacing); }
  /** \brief Largest surface-sample gap relative to the diagonal. */
  double getMaxSpacing() const { return voronoi_.getMaxSpacing(); }

  /** \brief Largest number of surface samples (VoronoiMat::setMaxSampleCount; default 12000,
   * 0 = no limit). Bounds the size of the initial MAT (about 3.4 spheres per sample). */
  void setMaxSampleCount(std::size_t count) { voronoi_.setMaxSampleCount(count); }
  /** \brief Largest number of surface samples. */
  std::size_t getMaxSampleCount() const { return voronoi_.getMaxSampleCount(); }

  /** \brief Deterministic sample jitter relative to the diagonal (VoronoiMat::setJitter). */
  void setJitter(double relative_jitter) { voronoi_.setJitter(relative_jitter); }
  /** \brief Sample jitter relative to the diagonal. */
  double getJitter() const { return voronoi_.getJitter(); }
  /** \brief Which deterministic jitter the samples get (VoronoiMat::setJitterSeed; default 0). */
  void setJitterSeed(std::uint32_t seed) { voronoi_.setJitterSeed(seed); }
  /** \brief Which deterministic jitter the samples get. */
  std::uint32_t getJitterSeed() const { return voronoi_.getJitterSeed(); }

  /** \brief Surface samples to use instead of sampling the mesh, optionally with their outward
   * unit normals (VoronoiMat::setSurfaceSamples; null, the default, samples the mesh). */
  void
  setSurfaceSamples(std::shared_ptr<const std::vector<Eigen::Vector3d>> samples,
                    std::shared_ptr<const std::vector<Eigen::Vector3d>> normals = nullptr)
  {
    voronoi_.setSurfaceSamples(std::move(samples), std::move(normals));
  }

  /** \brief Winding-number hierarchy of the input mesh for the inside tests, instead of the one
   * compute() builds with orientation repair (null, the default). A splat surface, whose faces
   * are already oriented and share no edge, needs one built without the repair.
   * \param[in] winding_number the hierarchy, or null */
  void
  setWindingNumber(std::shared_ptr<const WindingNumber> winding_number)
  {
    winding_number_ = std::move(winding_number);
  }

  /** \brief Keep every merged sphere centre inside the surface (default true; see
   * QmatSimplification::setInputSurface). Costs one O(log F) face-crossing count per collapse,
   * small next to the simplification; without it a few centres of thin parts end up outside. */
  void setKeepCentresInside(bool on) { keep_centres_inside_ = on; }
  /** \brief Whether merged centres are kept inside the surface. */
  bool getKeepCentresInside() const { return keep_centres_inside_; }

  /** \brief Threads for the parts that use them (VoronoiMat's inside test, Q-MAT's first cost
   * evaluation); 0 = OpenMP's default. The output does not depend on it. */
  void setNumberOfThreads(unsigned threads) { voronoi_.setNumberOfThreads(threads); }
  /** \brief Threads. */
  unsigned getNumberOfThreads() const { return voronoi_.getNumberOfThreads(); }

  /** \brief Computes the initial MAT, then the base and structured MATs: computeInitialMat(),
   * then simplify().
   * \param[out] base the base MAT (input units)
   * \param[out] structured the structured MAT (input units)
   * \return false (PCL_ERROR, empty outputs) when there is no input, VoronoiMat fails, the mesh
   *         encloses no medial sphere, or the simplification rejects its settings.
   */
  bool
  compute(MedialMesh& base, MedialMesh& structured);

  /** \brief The expensive half of compute(): the initial Voronoi MAT, its covered holes closed
   * (getInitialMat()). A caller that chooses between inputs by their initial MATs (their
   * components, say) simplifies only the one it keeps.
   * \return false (PCL_ERROR) as compute() before the simplification */
  bool
  computeInitialMat();

  /** \brief The other half: Q-MAT of the initial MAT of the last computeInitialMat(), with the
   * input mesh and winding number it used (the mesh must not have been changed since). Once per
   * computeInitialMat(): it releases the winding-number hierarchy.
   * \return false (PCL_ERROR, empty outputs) without a successful computeInitialMat() since the
   *         last simplify(), or when the simplification rejects its settings */
  bool
  simplify(MedialMesh& base, MedialMesh& structured);

  /** \brief The initial Voronoi medial mesh of the last computeInitialMat(), its covered holes
   * closed. */
  const MedialMesh& getInitialMat() const { return *initial_; }

  /** \brief Counts and timings of the last compute(). */
  const MedialMeshEstimationStatistics& getStatistics() const { return statistics_; }

private:
  TriangleMesh::ConstPtr mesh_;
  std::shared_ptr<const WindingNumber> winding_number_; ///< given hierarchy, or null
  VoronoiMat voronoi_;
  int simplification_base_target_ = 2000;
  int simplification_structured_target_ = -1;
  bool keep_centres_inside_ = true;
  MedialMesh::Ptr initial_ = std::make_shared<MedialMesh>();
  /// The hierarchy of the last computeInitialMat(), for simplify(); released by simplify().
  std::shared_ptr<const WindingNumber> initial_winding_number_;
  MedialMeshEstimationStatistics statistics_;
};

} // namespace segmat
