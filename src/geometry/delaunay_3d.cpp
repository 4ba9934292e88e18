/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include <segmat/geometry/delaunay_3d.h>

#include "point_bounds.h"

extern "C" {
#include <libqhull_r/qhull_ra.h>
}

#include <algorithm>
#include <cstdio>
#include <cstdlib>

namespace segmat {

bool
delaunayTetrahedralize(const std::vector<Eigen::Vector3d>& points, DelaunayTetrahedra& output,
                       std::string& error_message)
{
  if (!detail::startDelaunay(points, output, error_message))
    return false;
  const int n = static_cast<int>(points.size());
  std::vector<coordT> coords(static_cast<std::size_t>(n) * 3);
  for (int i = 0; i < n; ++i) {
    for (int k = 0; k < 3; ++k)
      coords[3 * i + k] = points[i][k];
  }

  // qhull reports through a FILE*: collect it in memory instead of spamming stderr.
  char* error_buffer = nullptr;
  std::size_t error_size = 0;
#if defined(__unix__) || defined(__APPLE__)
  FILE* error_file = open_memstream(&error_buffer, &error_size);
#else
  FILE* error_file = std::tmpfile(); // read back below
#endif
  qhT qh_qh;
  qhT* qh = &qh_qh;
  qh_zero(qh, error_file);
  char options[] = "qhull d Qt Qbb Qz";
  const int exit_code =
      qh_new_qhull(qh, 3, n, coords.data(), False, options, nullptr, error_file);
  if (exit_code == 0) {
    facetT* facet;
    vertexT *vertex, **vertexp;
    facetT *neighbor, **neighborp;
    std::vector<int> tet_of_facet(qh->facet_id + 1, -1);
    FORALLfacets
    {
      if (facet->upperdelaunay || qh_setsize(qh, facet->vertices) != 4)
        continue;
      Eigen::Vector4i corners;
      int k = 0;
      bool finite = true;
      FOREACHvertex_(facet->vertices)
      {
        const int id = qh_pointid(qh, vertex->point);
        finite = finite && id >= 0 && id < n; // Qz's point at infinity has id n
        corners[k++] = id;
      }
      if (!finite)
        continue;
      tet_of_facet[facet->id] = static_cast<int>(output.tetrahedra.size());
      output.tetrahedra.push_back(corners);
    }
    output.neighbors.assign(output.tetrahedra.size(), Eigen::Vector4i::Constant(-1));
    FORALLfacets
    {
      const int t = tet_of_facet[facet->id];
      if (t < 0)
        continue;
      const Eigen::Vector4i& mine = output.tetrahedra[t];
      int k = 0;
      FOREACHneighbor_(facet)
      {
        const int slot = k++;
        const int u = neighbor->id < tet_of_facet.size() ? tet_of_facet[neighbor->id] : -1;
        if (u < 0)
          continue;
        // qhull: for a simplicial facet the k-th neighbour is opposite the k-th vertex.
        if (facet->simplicial && slot < 4) {
          output.neighbors[t][slot] = u;
          continue;
        }
        // Otherwise: the neighbour shares three corners and lies opposite the fourth.
        const Eigen::Vector4i& theirs = output.tetrahedra[u];
        for (int i = 0; i < 4; ++i)
          if ((theirs.array() != mine[i]).all()) {
            output.neighbors[t][i] = u;
            break;
          }
      }
    }
  }
  qh_freeqhull(qh, !qh_ALL);
  int current_long = 0, total_long = 0;
  qh_memfreeshort(qh, &current_long, &total_long);
#if !(defined(__unix__) || defined(__APPLE__))
  std::string captured;
  if (error_file) {
    std::rewind(error_file);
    char chunk[256];
    std::size_t got;
    while ((got = std::fread(chunk, 1, sizeof(chunk), error_file)) > 0)
      captured.append(chunk, got);
  }
  error_buffer = static_cast<char*>(std::malloc(captured.size() + 1));
  if (error_buffer) {
    std::copy(captured.begin(), captured.end(), error_buffer);
    error_buffer[captured.size()] = '\0';
    error_size = captured.size();
  }
#endif
  if (error_file)
    std::fclose(error_file);
  if (exit_code != 0) {
    std::string text(error_buffer ? error_buffer : "", error_size);
    // Keep the first non-empty line: "QH6154 qhull precision error: initial simplex is flat..."
    std::size_t start = text.find_first_not_of("\n ");
    if (start == std::string::npos)
      error_message = "qhull exit code " + std::to_string(exit_code);
    else
      error_message = text.substr(start, text.find('\n', start) - start);
    output.tetrahedra.clear();
    output.neighbors.clear();
  }
  std::free(error_buffer);
  if (exit_code == 0)
    output.points = points;
  return exit_code == 0;
}

} // namespace segmat
