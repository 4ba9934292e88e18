/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include <segmat/evaluation/psb_metrics.h>

#include <pcl/console/print.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cfloat>
#include <cstdint>
#include <functional>
#include <queue>
#include <utility>

namespace segmat {

namespace {

// The benchmark marks vertices a cut cannot reach with FLT_MAX (EvaluationMethods.h); CD copies it.
constexpr double kUnreachable = FLT_MAX;

// One cell of the contingency table: faces in segment i of S1 and segment j of S2.
struct Cell
{
  int i = 0;
  int j = 0;
  std::int64_t faces = 0;
  double area = 0.0;
};

std::int64_t
pairsOf(std::int64_t n)
{
  return n * (n - 1) / 2;
}

} // namespace

/// A labeling made ready for scoring: compact labels per evaluated face and its cut distances.
struct PsbEvaluator::Labeling
{
  std::vector<int> labels;           ///< 0..K-1 per evaluated face
  int num_segments = 0;              ///< K
  std::vector<double> distance;      ///< per vertex: edge-graph distance to the nearest cut vertex
  std::vector<int> zero_set;         ///< vertices at distance exactly 0
};

PsbScores
averagePsbScores(const std::vector<PsbScores>& scores)
{
  PsbScores mean;
  double cd_sum = 0.0;
  for (const PsbScores& s : scores) {
    mean.HD += s.HD;
    mean.Rm += s.Rm;
    mean.Rf += s.Rf;
    mean.RI += s.RI;
    mean.GCE += s.GCE;
    mean.LCE += s.LCE;
    mean.GCEf += s.GCEf;
    mean.LCEf += s.LCEf;
    if (s.hasCD()) {
      cd_sum += s.CD;
      ++mean.cd_count;
    }
  }
  mean.count = static_cast<int>(scores.size());
  if (mean.count > 0) {
    const double n = mean.count;
    mean.HD /= n;
    mean.Rm /= n;
    mean.Rf /= n;
    mean.RI /= n;
    mean.GCE /= n;
    mean.LCE /= n;
    mean.GCEf /= n;
    mean.LCEf /= n;
  }
  if (mean.cd_count > 0)
    mean.CD = cd_sum / mean.cd_count;
  return mean;
}

bool
PsbEvaluator::setInputMesh(const TriangleMesh& mesh)
{
  *this = PsbEvaluator();
  const int num_vertices = static_cast<int>(mesh.numVertices());
  for (const Eigen::Vector3d& p : mesh.vertices)
    if (!p.allFinite()) {
      PCL_ERROR("[segmat::PsbEvaluator::setInputMesh] the mesh has a non-finite vertex\n");
      return false;
    }

  // GAPS face list: faces with a repeated index are never created.
  std::vector<int> eval_faces;
  eval_faces.reserve(mesh.numFaces());
  for (std::size_t f = 0; f < mesh.numFaces(); ++f) {
    const Eigen::Vector3i& t = mesh.faces[f];
    if (t.minCoeff() < 0 || t.maxCoeff() >= num_vertices) {
      PCL_ERROR("[segmat::PsbEvaluator::setInputMesh] face %zu has a vertex index out of range\n",
                f);
      return false;
    }
    if (t[0] != t[1] && t[1] != t[2] && t[0] != t[2])
      eval_faces.push_back(static_cast<int>(f));
  }
  if (eval_faces.empty()) {
    PCL_ERROR("[segmat::PsbEvaluator::setInputMesh] the mesh has no non-degenerate face\n");
    return false;
  }

  // Areas, surface centroid and average radius, all area-weighted as in R3Mesh.
  const std::size_t n = eval_faces.size();
  std::vector<double> areas(n);
  double total_area = 0.0;
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for (std::size_t k = 0; k < n; ++k) {
    areas[k] = mesh.faceArea(eval_faces[k]);
    total_area += areas[k];
    centroid += areas[k] * mesh.faceCentroid(eval_faces[k]);
  }
  if (!(total_area > 0.0)) {
    PCL_ERROR("[segmat::PsbEvaluator::setInputMesh] the mesh has zero surface area\n");
    return false;
  }
  centroid /= total_area;
  double radius_sum = 0.0;
  for (std::size_t k = 0; k < n; ++k)
    radius_sum += areas[k] * (mesh.faceCentroid(eval_faces[k]) - centroid).norm();

  // Undirected edges: sort (min, max, corner) records so every edge gets one id.
  std::vector<std::array<int, 3>> records;
  records.reserve(3 * n);
  for (std::size_t k = 0; k < n; ++k) {
    const Eigen::Vector3i& t = mesh.faces[eval_faces[k]];
    for (int c = 0; c < 3; ++c) {
      const int a = t[c], b = t[(c + 1) % 3];
      records.push_back({std::min(a, b), std::max(a, b), static_cast<int>(3 * k + c)});
    }
  }
  std::sort(records.begin(), records.end());
  std::vector<int> corner_edge(3 * n);
  std::vector<std::array<int, 2>> edge_ends;
  for (std::size_t r = 0; r < records.size(); ++r) {
    if (r == 0 || records[r][0] != records[r - 1][0] || records[r][1] != records[r - 1][1])
      edge_ends.push_back({records[r][0], records[r][1]});
    corner_edge[records[r][2]] = static_cast<int>(edge_ends.size()) - 1;
  }

  // GAPS CreateFace, in face order: a face claims the three directed half-edges it runs along
  // only if all are free; otherwise it keeps its place in the list but gets no neighbours. Its
  // edges were created before the check, so they stay in the graph either way.
  std::vector<std::array<int, 2>> side(edge_ends.size(), {-1, -1});
  for (std::size_t k = 0; k < n; ++k) {
    const Eigen::Vector3i& t = mesh.faces[eval_faces[k]];
    std::array<int, 3> slot;
    bool free = true;
    for (int c = 0; c < 3; ++c) {
      const int e = corner_edge[3 * k + c];
      slot[c] = t[c] == edge_ends[e][0] ? 0 : 1; // 0: runs from the smaller index to the larger
      free = free && side[e][slot[c]] < 0;
    }
    if (free)
      for (int c = 0; c < 3; ++c)
        side[corner_edge[3 * k + c]][slot[c]] = static_cast<int>(k);
  }

  // CSR adjacency of the vertex graph and the list of two-sided edges.
  std::vector<int> offsets(num_vertices + 1, 0);
  for (const std::array<int, 2>& e : edge_ends) {
    ++offsets[e[0] + 1];
    ++offsets[e[1] + 1];
  }
  for (int v = 0; v < num_vertices; ++v)
    offsets[v + 1] += offsets[v];
  std::vector<int> targets(offsets.back());
  std::vector<double> lengths(offsets.back());
  std::vector<int> fill(offsets.begin(), offsets.end() - 1);
  for (std::size_t e = 0; e < edge_ends.size(); ++e) {
    const int a = edge_ends[e][0], b = edge_ends[e][1];
    const double len = (mesh.vertices[a] - mesh.vertices[b]).norm();
    targets[fill[a]] = b;
    lengths[fill[a]++] = len;
    targets[fill[b]] = a;
    lengths[fill[b]++] = len;
    if (side[e][0] >= 0 && side[e][1] >= 0)
      two_sided_edges_.push_back({a, b, side[e][0], side[e][1]});
  }

  num_input_faces_ = mesh.numFaces();
  num_eval_faces_ = n;
  eval_faces_ = std::move(eval_faces);
  face_areas_ = std::move(areas);
  total_area_ = total_area;
  average_radius_ = radius_sum / total_area;
  adjacency_offsets_ = std::move(offsets);
  adjacency_targets_ = std::move(targets);
  adjacency_lengths_ = std::move(lengths);
  return true;
}

std::vector<double>
PsbEvaluator::cutDistances(const std::vector<int>& labels) const
{
  const std::size_t num_vertices = adjacency_offsets_.size() - 1;
  std::vector<double> distance(num_vertices, kUnreachable);
  using Entry = std::pair<double, int>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> heap;
  for (const std::array<int, 4>& e : two_sided_edges_)
    if (labels[e[2]] != labels[e[3]])
      for (int c = 0; c < 2; ++c)
        if (distance[e[c]] != 0.0) {
          distance[e[c]] = 0.0;
          heap.emplace(0.0, e[c]);
        }
  // Multi-source Dijkstra over the edge graph, edge length as weight (benchmark: neither exact
  // geodesic nor straight-line distance). Stale heap entries are skipped: O(E log V).
  while (!heap.empty()) {
    const auto [d, v] = heap.top();
    heap.pop();
    if (d > distance[v])
      continue;
    for (int k = adjacency_offsets_[v]; k < adjacency_offsets_[v + 1]; ++k) {
      const int w = adjacency_targets_[k];
      const double dw = d + adjacency_lengths_[k];
      if (dw < distance[w]) {
        distance[w] = dw;
        heap.emplace(dw, w);
      }
    }
  }
  return distance;
}

bool
PsbEvaluator::prepare(const std::vector<int>& labels, const char* what, Labeling& out) const
{
  if (!ready()) {
    PCL_ERROR("[segmat::PsbEvaluator::score] no mesh set\n");
    return false;
  }
  const bool per_input_face = labels.size() == num_input_faces_;
  if (!per_input_face && labels.size() != num_eval_faces_) {
    PCL_ERROR("[segmat::PsbEvaluator::score] the %s has %zu labels, the mesh %zu faces\n", what,
              labels.size(), num_input_faces_);
    return false;
  }
  std::vector<int> raw(num_eval_faces_);
  for (std::size_t k = 0; k < num_eval_faces_; ++k)
    raw[k] = per_input_face ? labels[eval_faces_[k]] : labels[k];
  // Map any integers onto 0..K-1 (the benchmark indexes arrays with raw labels).
  std::vector<int> values = raw;
  std::sort(values.begin(), values.end());
  values.erase(std::unique(values.begin(), values.end()), values.end());
  out.num_segments = static_cast<int>(values.size());
  out.labels.resize(num_eval_faces_);
  for (std::size_t k = 0; k < num_eval_faces_; ++k)
    out.labels[k] = static_cast<int>(
        std::lower_bound(values.begin(), values.end(), raw[k]) - values.begin());
  out.distance = cutDistances(out.labels);
  out.zero_set.clear();
  for (std::size_t v = 0; v < out.distance.size(); ++v)
    if (out.distance[v] == 0.0)
      out.zero_set.push_back(static_cast<int>(v));
  return true;
}

void
PsbEvaluator::compare(const Labeling& s1, const Labeling& s2, PsbScores& scores) const
{
  scores = PsbScores();
  scores.count = 1;
  const std::size_t n = num_eval_faces_;
  const int k1 = s1.num_segments, k2 = s2.num_segments;

  // Sparse contingency table: bucket faces by S1 segment, then gather S2 segments per row in a
  // scratch row. O(n + K1 + K2) even when K1·K2 is huge (one segment per face); the faces of a
  // cell are summed in face order, as the benchmark does.
  std::vector<int> row_start(k1 + 1, 0);
  for (std::size_t f = 0; f < n; ++f)
    ++row_start[s1.labels[f] + 1];
  for (int i = 0; i < k1; ++i)
    row_start[i + 1] += row_start[i];
  std::vector<int> by_row(n);
  {
    std::vector<int> fill(row_start.begin(), row_start.end() - 1);
    for (std::size_t f = 0; f < n; ++f)
      by_row[fill[s1.labels[f]]++] = static_cast<int>(f);
  }
  std::vector<Cell> cells;
  std::vector<int> cell_of(k2, -1);
  for (int i = 0; i < k1; ++i) {
    const std::size_t first = cells.size();
    for (int r = row_start[i]; r < row_start[i + 1]; ++r) {
      const int f = by_row[r], j = s2.labels[f];
      if (cell_of[j] < 0) {
        cell_of[j] = static_cast<int>(cells.size());
        cells.push_back({i, j, 0, 0.0});
      }
      Cell& c = cells[cell_of[j]];
      ++c.faces;
      c.area += face_areas_[f];
    }
    for (std::size_t c = first; c < cells.size(); ++c)
      cell_of[cells[c].j] = -1;
  }

  std::vector<std::int64_t> size1(k1, 0), size2(k2, 0);
  std::vector<double> area1(k1, 0.0), area2(k2, 0.0), best1(k1, 0.0), best2(k2, 0.0);
  std::int64_t pairs12 = 0;
  for (const Cell& c : cells) {
    size1[c.i] += c.faces;
    size2[c.j] += c.faces;
    area1[c.i] += c.area;
    area2[c.j] += c.area;
    best1[c.i] = std::max(best1[c.i], c.area);
    best2[c.j] = std::max(best2[c.j], c.area);
    pairs12 += pairsOf(c.faces);
  }

  // Consistency errors (Martin et al. 2001). Trivial cases are exactly 0, as in the benchmark.
  const std::int64_t nn = static_cast<std::int64_t>(n);
  if (k1 != 1 && k2 != 1 && k1 != nn && k2 != nn) {
    double e12 = 0, e21 = 0, emin = 0, a12 = 0, a21 = 0, amin = 0;
    for (const Cell& c : cells) {
      const double w = static_cast<double>(c.faces);
      const double d12 = 1.0 - w / size1[c.i], d21 = 1.0 - w / size2[c.j];
      // A zero-area region has no area measure; it counts as no error (benchmark: NaN).
      const double da12 = area1[c.i] > 0.0 ? 1.0 - c.area / area1[c.i] : 0.0;
      const double da21 = area2[c.j] > 0.0 ? 1.0 - c.area / area2[c.j] : 0.0;
      e12 += w * d12;
      e21 += w * d21;
      emin += w * std::min(d12, d21);
      a12 += w * da12;
      a21 += w * da21;
      amin += w * std::min(da12, da21);
    }
    scores.GCEf = std::min(e12, e21) / n;
    scores.LCEf = emin / n;
    scores.GCE = std::min(a12, a21) / n;
    scores.LCE = amin / n;
  }

  // Hamming distance by area (Huang & Dom 1995): best-overlap area per reference segment.
  double matched2 = 0.0, matched1 = 0.0;
  for (double a : best2)
    matched2 += a;
  for (double a : best1)
    matched1 += a;
  // Mathematically matched <= A; clamp the rounding residue so a perfect match prints 0, not -1e-15.
  scores.Rm = std::max(0.0, total_area_ - matched2) / total_area_;
  scores.Rf = std::max(0.0, total_area_ - matched1) / total_area_;
  scores.HD = 0.5 * (scores.Rm + scores.Rf);

  // 1 - Rand index over face pairs. Quirk kept from the benchmark: it divides by n·⌊(n−1)/2⌋
  // (integer division), not n(n−1)/2. Below 3 faces that divisor is 0, so the textbook one is
  // used there instead.
  std::int64_t disagreements = -2 * pairs12;
  for (std::int64_t s : size1)
    disagreements += pairsOf(s);
  for (std::int64_t s : size2)
    disagreements += pairsOf(s);
  const double divisor = nn >= 3 ? static_cast<double>(nn) * ((nn - 1) / 2)
                                 : static_cast<double>(pairsOf(nn));
  scores.RI = divisor > 0 ? disagreements / divisor : 0.0;

  // Cut discrepancy: distances from each zero set to the other cut set, per vertex, over R.
  double sum = 0.0, nearest = kUnreachable;
  for (int v : s2.zero_set) {
    sum += s1.distance[v];
    nearest = std::min(nearest, s1.distance[v]);
  }
  for (int v : s1.zero_set) {
    sum += s2.distance[v];
    nearest = std::min(nearest, s2.distance[v]);
  }
  const std::size_t zero_count = s1.zero_set.size() + s2.zero_set.size();
  // Undefined (the benchmark writes no .CD) when there is no zero vertex or none reaches a cut:
  // that is when either segmentation has no cut.
  if (zero_count > 0 && nearest < kUnreachable) {
    scores.CD = sum / zero_count / average_radius_;
    scores.cd_count = 1;
  }
}

bool
PsbEvaluator::score(const std::vector<int>& prediction, const std::vector<int>& reference,
                    PsbScores& scores) const
{
  scores = PsbScores();
  Labeling s1, s2;
  if (!prepare(prediction, "prediction", s1) || !prepare(reference, "reference", s2))
    return false;
  compare(s1, s2, scores);
  return true;
}

bool
PsbEvaluator::scoreAgainstAll(const std::vector<int>& prediction,
                              const std::vector<std::vector<int>>& references, PsbScores& mean,
                              std::vector<PsbScores>* per_reference) const
{
  mean = PsbScores();
  if (per_reference)
    per_reference->clear();
  if (references.empty()) {
    PCL_ERROR("[segmat::PsbEvaluator::scoreAgainstAll] no reference segmentation\n");
    return false;
  }
  Labeling s1;
  if (!prepare(prediction, "prediction", s1))
    return false;
  std::vector<PsbScores> all(references.size());
  Labeling s2;
  for (std::size_t r = 0; r < references.size(); ++r) {
    if (!prepare(references[r], "reference", s2))
      return false;
    compare(s1, s2, all[r]);
  }
  mean = averagePsbScores(all);
  if (per_reference)
    *per_reference = std::move(all);
  return true;
}

PsbScores
evaluateSegmentation(const TriangleMesh& mesh, const std::vector<int>& prediction,
                     const std::vector<int>& reference)
{
  PsbScores scores;
  const PsbEvaluator evaluator(mesh);
  evaluator.score(prediction, reference, scores);
  return scores;
}

} // namespace segmat
