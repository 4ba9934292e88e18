/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once

#include <segmat/common/error.h> // writers throw segmat::Error
#include <segmat/geometry/oriented_box.h>

#include <string>
#include <vector>

namespace segmat {
namespace io {

/** \brief Writes part boxes as JSON:
 * `{"boxes": [{"part": LABEL, "center": [x, y, z], "axes": [[..], [..], [..]],
 * "extents": [a, b, c], "volume": V}, ...]}` with unit axes as rows and extents the full edge
 * lengths along them (OrientedBox), one entry per box in the given order.
 *
 * Numbers are written in shortest round-trip form. Whole or not at all.
 * \throws segmat::Error naming \a path for a non-finite box or when the file cannot be written.
 */
void
saveBoxesJson(const std::string& path, const std::vector<PartBox>& boxes);

/** \brief Writes the boxes' surfaces as an ASCII PLY, each box's 12 triangles coloured by its
 * part (labelColor: the colours of saveColoredMeshPly, so the boxes match the coloured mesh
 * when both are opened together). Whole or not at all.
 * \throws segmat::Error naming \a path for a non-finite box or when the file cannot be written.
 */
void
saveBoxesPly(const std::string& path, const std::vector<PartBox>& boxes);

} // namespace io
} // namespace segmat
