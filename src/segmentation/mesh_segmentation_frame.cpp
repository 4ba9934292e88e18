/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 *
 * MeshSegmentation::segment(): the pipeline (segmentInFrame) runs on a copy of the mesh in its
 * normalised frame, and its results are mapped back to the input's frame.
 */
#include <segmat/segmentation/mesh_segmentation.h>

#include "../geometry/normalized_frame.h"
#include "../geometry/position_order.h"

namespace segmat {

struct MeshSegmentation::FrameCache
{
  TriangleMesh::ConstPtr source;  // the input mesh the copy was made from
  bool principal_axes = false;    // the frame option it was made with
  TriangleMesh::ConstPtr mesh;    // its copy in the normalised frame, in position order
  std::vector<int> face_of;       // face k of the copy is input face face_of[k]
  detail::NormalizedFrame frame;
  // Given MATs: the caller's pointers and their frame copies.
  MedialMesh::ConstPtr given_base, given_structured, base, structured;
  // Computed MATs: in the frame (what the pipeline holds) and in the input's frame (returned).
  MedialMesh::ConstPtr computed_base, computed_structured, shown_base, shown_structured;
};

bool
MeshSegmentation::segment(std::vector<int>& face_labels)
{
  if (!mesh_ || mesh_->empty())
    return segmentInFrame(face_labels); // reports the error
  if (!frame_)
    frame_ = std::make_shared<FrameCache>();
  FrameCache& cache = *frame_;
  if (cache.source != mesh_ || cache.principal_axes != principal_axes_) {
    cache = FrameCache();
    cache.source = mesh_;
    cache.principal_axes = principal_axes_;
    cache.frame = detail::NormalizedFrame::of(mesh_->vertices, principal_axes_);
    auto copy = std::make_shared<TriangleMesh>(cache.frame.toFrame(*mesh_));
    cache.face_of = detail::sortMeshByPosition(*copy);
    cache.mesh = std::move(copy);
    surface_tree_.reset();
  }
  // The transfer's mesh is set by segmentInFrame: the frame copy, or its denoised version.

  // Swap the frame copies in; the caller's objects come back on return.
  const TriangleMesh::ConstPtr input_mesh = mesh_;
  mesh_ = cache.mesh;
  if (mats_computed_) {
    base_ = cache.computed_base;
    structured_ = cache.computed_structured;
  }
  else {
    if (base_ && base_ != cache.given_base) {
      cache.given_base = base_;
      cache.base = std::make_shared<const MedialMesh>(cache.frame.toFrame(*base_));
    }
    if (structured_ && structured_ != cache.given_structured) {
      cache.given_structured = structured_;
      cache.structured = std::make_shared<const MedialMesh>(cache.frame.toFrame(*structured_));
    }
    base_ = base_ ? cache.base : nullptr;
    structured_ = structured_ ? cache.structured : nullptr;
  }

  std::vector<int> labels;
  const bool ok = segmentInFrame(labels);

  mesh_ = input_mesh;
  if (mats_computed_) {
    if (base_ != cache.computed_base) {
      cache.computed_base = base_;
      cache.computed_structured = structured_;
      cache.shown_base = std::make_shared<const MedialMesh>(cache.frame.fromFrame(*base_));
      cache.shown_structured =
          std::make_shared<const MedialMesh>(cache.frame.fromFrame(*structured_));
    }
    base_ = cache.shown_base;
    structured_ = cache.shown_structured;
  }
  else {
    base_ = base_ ? cache.given_base : nullptr;
    structured_ = structured_ ? cache.given_structured : nullptr;
  }

  face_labels.clear();
  if (!ok)
    return false;
  face_labels.resize(labels.size());
  for (std::size_t k = 0; k < labels.size(); ++k)
    face_labels[cache.face_of[k]] = labels[k];
  face_labels_ = face_labels;
  return true;
}

double
MeshSegmentation::getEstimatedNoise() const
{
  return frame_ ? noise_sigma_ / frame_->frame.scale : noise_sigma_;
}

double
MeshSegmentation::getRemainingNoise() const
{
  return frame_ ? remaining_sigma_ / frame_->frame.scale : remaining_sigma_;
}

} // namespace segmat
