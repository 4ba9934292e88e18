// A PSB mesh segmented with and without the flat-boundary rule, scored against its humans.
#pragma once

#include <segmat/evaluation/psb_metrics.h>
#include <segmat/geometry/triangle_mesh.h>

#include <cstddef>
#include <string>
#include <vector>

namespace segmat {
namespace test {

/** \brief The human segmentations PREFIX0.seg .. PREFIX(count − 1).seg of a mesh with
 * \a num_faces faces. */
std::vector<std::vector<int>>
loadHumans(const std::string& prefix, int count, std::size_t num_faces);

/** \brief Segments \a mesh (jitter seed \a jitter) with the flat-boundary rule on or off, checks
 * that getMatParts() has one entry per label, and returns the number of parts; \a rand_distance
 * gets the mean 1 − RI against \a humans, scored by \a evaluator. */
std::size_t
segmentWithFlatJoin(const TriangleMesh::Ptr& mesh, const PsbEvaluator& evaluator,
                    const std::vector<std::vector<int>>& humans, bool join, unsigned int jitter,
                    double& rand_distance);

} // namespace test
} // namespace segmat
