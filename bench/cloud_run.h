/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 *
 * One timed CloudSegmentation of a cloud sampled from a mesh, as the cloud benchmarks run it
 * (header only; include after tests/util/cloud_sampler.cpp, which bench programs compile in).
 */
#pragma once

#include <segmat/segmentation/cloud_segmentation.h>

#include <chrono>
#include <vector>

namespace segmat {
namespace bench {

/** \brief How the benchmarks segment a sampled cloud (defaults: the library's, one thread). */
struct CloudRunSettings
{
  bool normals = false;         ///< use the samples' true normals (else they are estimated)
  bool visibility = true;       ///< merging tests visibility in the ball union
  double eta = -1.0;            ///< minimal region fraction η (< 0: the library's)
  double omega = -1.0;          ///< transfer smoothness ω (< 0: the library's)
  bool meso_skeleton = false;   ///< the shrinking-ball medial points instead of the medial mesh
  int smoothing = -1;           ///< preprocessing smoothing iterations (< 0: the library's)
  bool keep_inside = false;     ///< Q-MAT keeps merged centres inside the splat surface
  bool reference_crease = false; ///< the reference's crease model in the transfer
  long samples = -1;            ///< Voronoi sample limit (< 0: the library's)
};

/** \brief What one segmentation gave. */
struct CloudRun
{
  std::vector<int> labels; ///< one per point (all 0 when the segmentation failed)
  int parts = 0;           ///< 0 when it failed
  int structured_spheres = 0; ///< of the structured MAT (0 for the meso-skeleton)
  double seconds = 0.0;    ///< wall time of segment()
  StageTimings stages;     ///< CloudSegmentation::getStageSeconds()
};

inline CloudRun
segmentSampledCloud(const test::SampledCloud& cloud, const CloudRunSettings& settings)
{
  CloudSegmentation<pcl::PointNormal> seg;
  seg.setInputCloud(cloud.toPointNormal());
  seg.setUseInputNormalsFlag(settings.normals);
  seg.setNumberOfThreads(1);
  seg.setVisibilityFlag(settings.visibility);
  if (settings.eta >= 0.0)
    seg.setMinRegionFraction(settings.eta);
  if (settings.omega >= 0.0)
    seg.setSmoothnessWeight(settings.omega);
  if (settings.meso_skeleton)
    seg.setMedialAxis(CloudMedialAxis::MesoSkeleton);
  if (settings.smoothing >= 0) {
    MesoSkeletonParameters params = seg.getMesoSkeletonParameters();
    params.smoothing_iterations = settings.smoothing;
    seg.setMesoSkeletonParameters(params);
  }
  MedialMeshEstimation& qmat = seg.getMedialMeshEstimation().getMedialMeshEstimation();
  qmat.setKeepCentresInside(settings.keep_inside);
  if (settings.samples >= 0)
    qmat.setMaxSampleCount(static_cast<std::size_t>(settings.samples));
  if (settings.reference_crease)
    seg.setCreaseModel(CreaseModel::Reference);
  std::vector<pcl::PointIndices> parts;
  const auto start = std::chrono::steady_clock::now();
  const bool ok = seg.segment(parts);
  CloudRun run;
  run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  run.parts = ok ? int(parts.size()) : 0;
  run.stages = seg.getStageSeconds();
  run.structured_spheres =
      seg.getStructuredMat() ? int(seg.getStructuredMat()->numVertices()) : 0;
  run.labels = ok ? seg.getLabels() : std::vector<int>(cloud.size(), 0);
  return run;
}

} // namespace bench
} // namespace segmat
