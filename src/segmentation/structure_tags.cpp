/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include <segmat/geometry/medial_mesh.h>
#include <segmat/segmentation/mat_graph.h>
#include <segmat/segmentation/structure_tags.h>

namespace segmat {

StructureTags
computeStructureTags(const MedialMesh& /*structured*/, const MatGraph& base)
{
  // STUB: all nodes bulky.
  StructureTags tags;
  tags.node_tag.assign(base.numNodes(), 0);
  return tags;
}

} // namespace segmat
