/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once
// The parts of the Python module, one per file.

#include <pybind11/pybind11.h>

namespace segmat_python {

/** segment_mesh, segment_cloud, default_parameters, MeshSegmenter, CloudSegmenter. */
void
bindSegmentation(pybind11::module_& m);

/** medial_mesh, psb_metrics, labels_to_colors, load_mesh. */
void
bindTools(pybind11::module_& m);

} // namespace segmat_python
