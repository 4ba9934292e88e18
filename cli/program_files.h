/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once
// The input and output files of a program run, checked before any work (not installed).

#include <segmat/geometry/triangle_mesh.h>
#include <segmat/io/atomic_file.h>

#include <string>
#include <vector>

namespace segmat {
namespace cli {

/** \brief Declares PREFIX + each suffix as an output of \a outputs (checked now: not an input,
 * writable, not a device), installs the temporaries' signal cleanup, and rejects a prefix that
 * is a directory. Throws UsageError naming the file. */
void
declareOutputs(io::OutputSet& outputs, const std::string& prefix,
               const std::vector<std::string>& suffixes);

/** \brief Checks that \a path is a readable regular file (not a directory); throws UsageError
 * naming it. The readers give the finer messages. */
void
checkInputFile(const std::string& path);

/** \brief Throws UsageError naming \a path when \a mesh's size is not a finite positive number:
 * coordinates near the floating-point limit overflow the bounding-box diagonal, and every
 * computation after that would be meaningless. */
void
checkMeshSize(const std::string& path, const TriangleMesh& mesh);

/** \brief Warns on stderr, naming \a path and the counts, when \a mesh is not a closed
 * manifold surface (boundary or non-manifold edges: countMeshEdges). The medial axis of an open
 * surface is not defined; segmat still runs, with parts that may leak through the holes. */
void
warnIfNotClosed(const std::string& program, const std::string& path, const TriangleMesh& mesh);

} // namespace cli
} // namespace segmat
