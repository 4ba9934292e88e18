/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once

// The MAT graph lives in the medial module (include <segmat/medial/mat_graph.h>); this header
// keeps the segmentation front classes compiling until their includes name it there.
#include <segmat/medial/mat_graph.h>
