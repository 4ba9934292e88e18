/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once

#include <segmat/geometry/triangle_mesh.h>

#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <vector>

namespace segmat {

/** \brief The Princeton Segmentation Benchmark scores of one segmentation (Chen, Golovinskiy,
 * Funkhouser, "A Benchmark for 3D Mesh Segmentation", SIGGRAPH 2009), or a mean of several.
 *
 * Every number is a fraction (0..1), lower is better; CD is in units of the mesh's average
 * radius. The names are the benchmark's column names: GCE/LCE are the area-measured consistency
 * errors the benchmark plots, GCEf/LCEf the face-count ones, RI is 1 − Rand index.
 */
struct PsbScores
{
  double CD = std::numeric_limits<double>::quiet_NaN(); ///< cut discrepancy; NaN when undefined
  double HD = 0.0;   ///< Hamming distance (Rm + Rf) / 2, by area
  double Rm = 0.0;   ///< Hamming missing rate (large: the prediction over-segments)
  double Rf = 0.0;   ///< Hamming false-alarm rate (large: the prediction under-segments)
  double RI = 0.0;   ///< 1 − Rand index, with the benchmark's n·⌊(n−1)/2⌋ divisor
  double GCE = 0.0;  ///< global consistency error, regions measured by area
  double LCE = 0.0;  ///< local consistency error, regions measured by area
  double GCEf = 0.0; ///< global consistency error, regions measured by face count
  double LCEf = 0.0; ///< local consistency error, regions measured by face count
  int count = 0;     ///< comparisons (or models) averaged into these numbers
  int cd_count = 0;  ///< how many of them have a CD

  /** \brief True when CD is defined (both segmentations have a cut, or some mean had one). */
  bool
  hasCD() const
  {
    return !std::isnan(CD);
  }
};

/** \brief Arithmetic mean of each column, as the benchmark's collectEvaluation.py takes it.
 *
 * CD is averaged only over the entries that have one (NaN when none has). The result's
 * \a count is the number of entries, its \a cd_count the number with a CD. An empty input gives
 * all-zero scores with CD NaN and count 0.
 */
PsbScores
averagePsbScores(const std::vector<PsbScores>& scores);

/** \brief Scores segmentations of one mesh with the Princeton Segmentation Benchmark metrics.
 *
 * Built once per mesh (face areas, average radius, the vertex edge graph and which faces lie on
 * either side of each edge are cached), then scores any number of labelings. It rebuilds the
 * face list and edge graph the benchmark's GAPS reader (`R3Mesh::ReadOffFile`) would make from
 * the same triangles:
 *  - a face with a repeated vertex index is dropped (GAPS never creates it); its label is
 *    ignored;
 *  - a face that would reuse a directed half-edge already used by an earlier face (a third face
 *    on an edge, or a flipped neighbour) stays in the face list but gets no neighbours, so it
 *    never makes a cut edge; the edges it would have had still join its original vertices in
 *    the distance graph (GAPS creates the edges before it finds the side taken). GAPS puts such a
 *    face on three fresh vertex copies; those copies cannot reach anything, so they can change
 *    no score and are not materialised here.
 * On a clean closed mesh (all of PSB) this is simply the mesh's faces and edges.
 *
 * Labels may be any integers; each labeling is mapped onto 0..K−1 first, which gives the
 * benchmark's numbers whenever its own code is well defined. A labeling has one entry per face
 * of the input mesh (TriangleMesh::numFaces()) or, equivalently for a GAPS-made `.seg` file, one
 * per evaluated face (numEvaluatedFaces()).
 *
 * Deviations where the benchmark's own code is undefined (never reached on PSB): meshes with
 * fewer than 3 faces use the textbook Rand divisor n(n−1)/2; an area-measured consistency ratio
 * of a zero-area region counts as no error (the official code gives NaN); meshes with zero area
 * are rejected. Where a zero-set vertex cannot reach the other cut set (disconnected mesh), the
 * benchmark adds FLT_MAX, and so does this class: such a CD is astronomically large, not small.
 */
class PsbEvaluator
{
public:
  using Ptr = std::shared_ptr<PsbEvaluator>;
  using ConstPtr = std::shared_ptr<const PsbEvaluator>;

  /** \brief An evaluator with no mesh; call setInputMesh() before scoring. */
  PsbEvaluator() = default;

  /** \brief Builds the evaluator for \a mesh (see setInputMesh(); check ready() afterwards).
   * \param[in] mesh the segmented mesh
   */
  explicit PsbEvaluator(const TriangleMesh& mesh) { setInputMesh(mesh); }

  /** \brief Caches what scoring needs of \a mesh.
   * \param[in] mesh the segmented mesh; not referenced after the call
   * \return false (PCL_ERROR, evaluator left empty) when the mesh has an out-of-range index, a
   *         non-finite vertex, no evaluated face, or zero total area
   */
  bool
  setInputMesh(const TriangleMesh& mesh);

  /** \brief True when a mesh has been set successfully. */
  bool
  ready() const
  {
    return num_eval_faces_ > 0;
  }

  /** \brief Faces of the input mesh (the length of a segmat labeling). */
  std::size_t
  numInputFaces() const
  {
    return num_input_faces_;
  }

  /** \brief Faces the benchmark evaluates: the input faces without repeated vertex indices. */
  std::size_t
  numEvaluatedFaces() const
  {
    return num_eval_faces_;
  }

  /** \brief Total surface area A of the evaluated faces. */
  double
  totalArea() const
  {
    return total_area_;
  }

  /** \brief Average radius R: area-weighted mean distance of face centroids to the surface
   * centroid (GAPS `R3Mesh::AverageRadius`), the unit of CD.
   */
  double
  averageRadius() const
  {
    return average_radius_;
  }

  /** \brief Scores \a prediction (S1) against one \a reference (S2).
   * \param[in] prediction one label per face (see class notes for the accepted lengths)
   * \param[in] reference one label per face, same convention
   * \param[out] scores the nine numbers; count = 1, cd_count = 0 or 1
   * \return false (PCL_ERROR, \a scores reset) when no mesh is set or a length is wrong
   */
  bool
  score(const std::vector<int>& prediction, const std::vector<int>& reference,
        PsbScores& scores) const;

  /** \brief The benchmark's per-model value: \a prediction scored against each of
   * \a references, then the arithmetic mean of each column (CD over the references where it
   * exists). The prediction's cut distances are computed once.
   * \param[in] prediction one label per face
   * \param[in] references the human segmentations of the model (at least one)
   * \param[out] mean the means; count = number of references, cd_count = those with a CD
   * \param[out] per_reference if not null, the score against each reference, in order
   * \return false (PCL_ERROR) when no mesh is set, \a references is empty or a length is wrong
   */
  bool
  scoreAgainstAll(const std::vector<int>& prediction,
                  const std::vector<std::vector<int>>& references, PsbScores& mean,
                  std::vector<PsbScores>* per_reference = nullptr) const;

private:
  struct Labeling;

  bool
  prepare(const std::vector<int>& labels, const char* what, Labeling& out) const;

  void
  compare(const Labeling& s1, const Labeling& s2, PsbScores& scores) const;

  std::vector<double>
  cutDistances(const std::vector<int>& labels) const;

  std::size_t num_input_faces_ = 0;
  std::size_t num_eval_faces_ = 0;
  std::vector<int> eval_faces_;     ///< input face index of each evaluated face
  std::vector<double> face_areas_;  ///< per evaluated face
  double total_area_ = 0.0;
  double average_radius_ = 0.0;
  // Vertex edge graph (CSR), every undirected edge once per direction, weight = edge length.
  std::vector<int> adjacency_offsets_;
  std::vector<int> adjacency_targets_;
  std::vector<double> adjacency_lengths_;
  // Edges with a face on both sides: endpoints and the two evaluated faces.
  std::vector<std::array<int, 4>> two_sided_edges_;
};

/** \brief One-shot convenience: PsbEvaluator(mesh).score(prediction, reference).
 * Returns all-zero scores with CD NaN and count 0 when the inputs are invalid (PCL_ERROR).
 */
PsbScores
evaluateSegmentation(const TriangleMesh& mesh, const std::vector<int>& prediction,
                     const std::vector<int>& reference);

} // namespace segmat
