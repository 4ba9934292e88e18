/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include <segmat/segmentation/mesh_segmentation.h>
#include <segmat/medial/medial_mesh_estimation.h>

#include "../common/thread_count.h"
#include "../medial/surface_denoising.h"
#include "flat_boundaries.h"

#include <pcl/console/print.h>

#include <algorithm>
#include <chrono>
#include <numeric>

namespace segmat {
namespace {

class StageClock
{
public:
  double
  lap()
  {
    const auto now = std::chrono::steady_clock::now();
    const double seconds = std::chrono::duration<double>(now - start_).count();
    start_ = now;
    return seconds;
  }

private:
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

} // namespace

// The grower, the transfer and the estimation hold the defaults.
MeshSegmentation::MeshSegmentation() : estimation_(std::make_shared<MedialMeshEstimation>()) {}

void
MeshSegmentation::dropComputedMats()
{
  if (!mats_computed_)
    return;
  base_.reset();
  structured_.reset();
  mats_computed_ = false;
  graph_.reset();
  tags_valid_ = false;
}

const MedialMeshEstimationStatistics&
MeshSegmentation::getMatStatistics() const
{
  static const MedialMeshEstimationStatistics none;
  return mats_computed_ ? estimation_->getStatistics() : none;
}

void
MeshSegmentation::setInputMesh(const TriangleMesh::ConstPtr& mesh)
{
  if (mesh != mesh_)
    dropComputedMats(); // they belong to the previous mesh
  mesh_ = mesh;
  working_mesh_.reset();
  surface_tree_.reset();
  transfer_.setInputMesh(mesh); // drops the transfer's face-graph weights
}

void
MeshSegmentation::prepareWorkingMesh()
{
  if (working_mesh_)
    return;
  // The mesh's vertices are samples of its surface: the cloud path's noise design serves them,
  // with the mesh's rings as neighbourhoods. A clean mesh is left as it is (bit for bit).
  std::vector<Eigen::Vector3d> vertices = mesh_->vertices;
  const detail::SurfaceDenoising denoising =
      detail::denoiseMeshSurface(vertices, mesh_->faces, 32, 5,
                                 detail::threadCount(getNumberOfThreads()), 4.0);
  noise_sigma_ = denoising.noise.sigma;
  denoising_passes_ = denoising.passes;
  remaining_sigma_ = denoising.passes > 0 ? denoising.remaining_sigma : 0.0;
  if (denoising.passes == 0) {
    working_mesh_ = mesh_;
    return;
  }
  working_mesh_ = std::make_shared<TriangleMesh>(std::move(vertices), mesh_->faces);
}

void
MeshSegmentation::setPrincipalAxesFrame(bool enable)
{
  if (enable == principal_axes_)
    return;
  principal_axes_ = enable;
  dropComputedMats(); // computed in the other frame; segment() remakes the frame copy
  working_mesh_.reset();
  surface_tree_.reset();
}

void
MeshSegmentation::setBaseMat(const MedialMesh::ConstPtr& base)
{
  dropComputedMats(); // a given MAT never pairs with a computed one
  base_ = base;
  graph_.reset();
  tags_valid_ = false;
}

void
MeshSegmentation::setStructuredMat(const MedialMesh::ConstPtr& structured)
{
  dropComputedMats();
  structured_ = structured;
  tags_valid_ = false;
}

void
MeshSegmentation::setBaseMatTarget(int spheres)
{
  if (spheres != estimation_->getBaseTarget())
    dropComputedMats();
  estimation_->setBaseTarget(spheres);
}

int
MeshSegmentation::getBaseMatTarget() const
{
  return estimation_->getBaseTarget();
}

void
MeshSegmentation::setStructuredMatTarget(int spheres)
{
  if (spheres != estimation_->getStructuredTarget())
    dropComputedMats();
  estimation_->setStructuredTarget(spheres);
}

int
MeshSegmentation::getStructuredMatTarget() const
{
  return estimation_->getStructuredTarget();
}

void
MeshSegmentation::setJitterSeed(std::uint32_t seed)
{
  if (seed != estimation_->getJitterSeed())
    dropComputedMats();
  estimation_->setJitterSeed(seed);
}

std::uint32_t
MeshSegmentation::getJitterSeed() const
{
  return estimation_->getJitterSeed();
}

void
MeshSegmentation::setNumberOfThreads(unsigned threads)
{
  estimation_->setNumberOfThreads(threads); // the output does not depend on it: keep the MATs
  transfer_.setNumberOfThreads(threads);
}

unsigned
MeshSegmentation::getNumberOfThreads() const
{
  return estimation_->getNumberOfThreads();
}

bool
MeshSegmentation::segmentInFrame(std::vector<int>& face_labels)
{
  face_labels.clear();
  face_labels_.clear();
  mat_parts_.clear();
  stage_seconds_.clear();
  if (!mesh_ || mesh_->empty()) {
    PCL_ERROR("[segmat::MeshSegmentation::segment] no mesh, or a mesh without faces.\n");
    return false;
  }
  if (!base_ != !structured_) {
    PCL_ERROR("[segmat::MeshSegmentation::segment] only the %s medial mesh is given: give both "
              "(setBaseMat, setStructuredMat) or neither (they are then computed).\n",
              base_ ? "base" : "structured");
    return false;
  }

  StageClock clock;
  double seconds = 0.0;
  if (!working_mesh_) {
    prepareWorkingMesh();
    seconds = clock.lap();
  }
  if (transfer_.getInputMesh() != working_mesh_)
    transfer_.setInputMesh(working_mesh_); // drops the transfer's face-graph weights
  stage_seconds_.emplace_back("denoise", seconds);
  seconds = 0.0;
  if (!base_) {
    auto base = std::make_shared<MedialMesh>();
    auto structured = std::make_shared<MedialMesh>();
    estimation_->setInputMesh(working_mesh_);
    const bool ok = estimation_->compute(*base, *structured);
    estimation_->setInputMesh(nullptr); // hold the mesh only through mesh_
    if (!ok) {
      PCL_ERROR("[segmat::MeshSegmentation::segment] the medial meshes could not be computed "
                "from the mesh (see the message above).\n");
      stage_seconds_.clear();
      return false;
    }
    base_ = base;
    structured_ = structured;
    mats_computed_ = true;
    graph_.reset();
    tags_valid_ = false;
    seconds = clock.lap();
  }
  stage_seconds_.emplace_back("mat", seconds);
  if (base_->empty()) {
    PCL_ERROR("[segmat::MeshSegmentation::segment] the base medial mesh is empty.\n");
    stage_seconds_.clear();
    return false;
  }

  seconds = 0.0;
  clock.lap();
  if (!graph_) {
    graph_ = std::make_shared<MatGraph>(MatGraph::fromMedialMesh(*base_));
    grower_.setInputGraph(graph_);
    transfer_.setInputGraph(graph_);
    tags_valid_ = false;
    seconds = clock.lap();
  }
  if (graph_->empty()) {
    PCL_ERROR("[segmat::MeshSegmentation::segment] the base medial mesh has no triangle and no "
              "edge: no graph node.\n");
    stage_seconds_.clear();
    return false;
  }
  stage_seconds_.emplace_back("graph", seconds);

  seconds = 0.0;
  clock.lap();
  if (!tags_valid_) {
    if (structured_->empty()) {
      // Like the reference: only a warning, and every node counts as bulky.
      PCL_WARN("[segmat::MeshSegmentation::segment] empty structured medial mesh: no thin "
               "parts.\n");
      tags_ = StructureTags();
    }
    else
      tags_ = computeStructureTags(*structured_, *graph_);
    grower_.setStructureTags(tags_);
    tags_valid_ = true;
    seconds = clock.lap();
  }
  stage_seconds_.emplace_back("tags", seconds);

  seconds = 0.0;
  clock.lap();
  if (!surface_tree_) {
    surface_tree_ = std::make_shared<AabbTree>(*working_mesh_);
    // Two points see each other when the segment between them crosses no face (§4.4).
    const std::shared_ptr<const AabbTree> tree = surface_tree_;
    grower_.setSegmentVisibility([tree](const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
      return !tree->segmentIntersects(a, b);
    });
    seconds = clock.lap();
  }
  stage_seconds_.emplace_back("surface_tree", seconds);

  clock.lap();
  // Radius differences within the noise that denoising left are no evidence of a part boundary.
  grower_.setRadiusTolerance(remaining_sigma_);
  std::vector<pcl::PointIndices> grown;
  if (!grower_.extract(grown) || grown.empty()) {
    PCL_ERROR("[segmat::MeshSegmentation::segment] region growing failed.\n");
    stage_seconds_.clear();
    return false;
  }
  stage_seconds_.emplace_back("grow_merge", clock.lap());

  transfer_.setParts(grower_.getCoarseParts());
  std::vector<int> labels;
  if (!transfer_.transfer(labels)) {
    PCL_ERROR("[segmat::MeshSegmentation::segment] surface transfer failed.\n");
    stage_seconds_.clear();
    return false;
  }

  // Number parts by descending face count; ties keep growing order (the transfer's labels are
  // already in growing order).
  const std::vector<std::vector<int>>& label_parts = transfer_.getLabelParts();
  const int num_labels = static_cast<int>(label_parts.size());
  std::vector<int> counts(num_labels, 0);
  for (int l : labels)
    ++counts[l];
  std::vector<int> order(num_labels);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](int a, int b) { return counts[a] > counts[b]; });
  std::vector<int> rank(num_labels);
  for (int r = 0; r < num_labels; ++r)
    rank[order[r]] = r;
  for (int& l : labels)
    l = rank[l];
  mat_parts_.resize(num_labels);
  for (int r = 0; r < num_labels; ++r)
    mat_parts_[r] = detail::joinParts(grown, label_parts[order[r]]);
  stage_seconds_.emplace_back("transfer", clock.lap());

  face_labels_ = labels;
  face_labels.swap(labels);
  return true;
}

void
MeshSegmentation::getParts(std::vector<pcl::PointIndices>& parts) const
{
  parts.clear();
  int num_labels = 0;
  for (int l : face_labels_)
    num_labels = std::max(num_labels, l + 1);
  parts.resize(num_labels);
  for (std::size_t f = 0; f < face_labels_.size(); ++f)
    parts[face_labels_[f]].indices.push_back(static_cast<pcl::index_t>(f));
}

} // namespace segmat
