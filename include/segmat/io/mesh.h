/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once

#include <segmat/common/error.h> // readers and writers throw segmat::Error
#include <segmat/geometry/triangle_mesh.h>

#include <string>

namespace segmat {
namespace io {

/** \brief Reads a triangle mesh, choosing the reader by the file's extension (any case).
 *
 *  - `.off`: loadOff (segmat's own reader; face order kept, so PSB `.seg` labels line up);
 *  - `.obj`: loadObj (segmat's own reader; PCL's crashes on damaged files);
 *  - `.ply`: PCL's reader (ASCII and binary), after segmat checks the header (PCL would allocate
 *    whatever element counts a corrupt header announces);
 *  - `.stl`: PCL's VTK-based reader (ASCII and binary STL; VTK merges duplicate corners).
 * Coordinates stored as float, double or integers are all read; polygons with more than three
 * corners are fan-triangulated (v0, v_{k-1}, v_k) in order.
 * \throws segmat::Error naming \a path: with the line for OFF, OBJ and PLY header problems;
 *         line 0 when PCL's reader rejects the file or its content (no x/y/z, a non-finite
 *         coordinate, a face with fewer than 3 corners, an index out of range), and for an
 *         unknown extension, with the supported list.
 */
TriangleMesh
loadMesh(const std::string& path);

/** \brief Writes a triangle mesh, choosing the format by extension: `.off`, `.ply` (ASCII,
 * double coordinates) or `.obj`. Coordinates are written in shortest round-trip form, so
 * loadMesh gives back the same doubles. Whole or not at all.
 * \throws segmat::Error naming \a path for an unknown extension, a non-finite vertex, an index
 *         out of range or a write failure.
 */
void
saveMesh(const std::string& path, const TriangleMesh& mesh);

} // namespace io
} // namespace segmat
