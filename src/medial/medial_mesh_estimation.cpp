/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include <segmat/medial/medial_mesh_estimation.h>
#include <segmat/geometry/winding_number.h>
#include <segmat/medial/qmat_simplification.h>

#include "covered_hole_filling.h"

#include <pcl/console/print.h>

#include <chrono>


namespace segmat {

bool
MedialMeshEstimation::compute(MedialMesh& base, MedialMesh& structured)
{
  base = MedialMesh();
  structured = MedialMesh();
  return computeInitialMat() && simplify(base, structured);
}

bool
MedialMeshEstimation::computeInitialMat()
{
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  initial_ = std::make_shared<MedialMesh>();
  initial_winding_number_.reset();
  statistics_ = MedialMeshEstimationStatistics();
  if (!mesh_ || mesh_->empty()) {
    PCL_ERROR("[segmat::MedialMeshEstimation::compute] no input mesh (or it has no faces)\n");
    return false;
  }

  // One winding-number hierarchy serves VoronoiMat's inside test and Q-MAT's centre test.
  std::shared_ptr<const WindingNumber> winding_number = winding_number_;
  if (!winding_number) {
    auto own = std::make_shared<WindingNumber>(*mesh_);
    own->setAccuracy(voronoi_.getWindingNumberAccuracy());
    winding_number = std::move(own);
  }
  voronoi_.setInputMesh(mesh_);
  voronoi_.setWindingNumber(winding_number);
  const bool voronoi_ok = voronoi_.compute(*initial_);
  voronoi_.setWindingNumber(nullptr); // voronoi_ is a member: do not keep the hierarchy alive
  statistics_.voronoi = voronoi_.getStatistics();
  statistics_.initial_spheres = initial_->numVertices();
  if (!voronoi_ok)
    return false; // VoronoiMat said why
  if (initial_->numEdges() == 0) {
    PCL_ERROR("[segmat::MedialMeshEstimation::compute] the mesh encloses no medial sphere pair "
              "(%zu spheres, no edge): is it closed?\n",
              initial_->numVertices());
    return false;
  }
  statistics_.filled_holes = std::size_t(detail::fillCoveredHoles(*initial_));
  initial_winding_number_ = std::move(winding_number);
  statistics_.seconds_initial = std::chrono::duration<double>(Clock::now() - start).count();
  statistics_.seconds_total = statistics_.seconds_initial;
  return true;
}

bool
MedialMeshEstimation::simplify(MedialMesh& base, MedialMesh& structured)
{
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  base = MedialMesh();
  structured = MedialMesh();
  if (!initial_winding_number_ || !mesh_) {
    PCL_ERROR("[segmat::MedialMeshEstimation::simplify] no initial MAT: call computeInitialMat() "
              "first.\n");
    return false;
  }
  QmatSimplification qmat;
  qmat.setInputMat(initial_);
  if (keep_centres_inside_)
  {
    qmat.setInputSurface(mesh_); // normalisation by its diagonal; merged centres stay inside
    qmat.setWindingNumber(initial_winding_number_);
  }
  else
    qmat.setNormalisationScale(mesh_->boundingBoxDiagonal()); // Q-MAT's normalisation
  qmat.setBaseTarget(simplification_base_target_);
  qmat.setStructuredTarget(simplification_structured_target_);
  qmat.setNumberOfThreads(voronoi_.getNumberOfThreads());
  const bool ok = qmat.compute(base, structured);
  initial_winding_number_.reset();
  statistics_.seconds_simplification = std::chrono::duration<double>(Clock::now() - start).count();
  statistics_.seconds_total = statistics_.seconds_initial + statistics_.seconds_simplification;
  statistics_.base_spheres = base.numVertices();
  statistics_.structured_spheres = structured.numVertices();
  return ok;
}

} // namespace segmat
