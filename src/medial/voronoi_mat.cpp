/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include <segmat/common/available_memory.h>
#include <segmat/geometry/delaunay_3d.h>
#include <segmat/geometry/surface_sampling.h>
#include <segmat/geometry/weld_points.h>
#include <segmat/geometry/winding_number.h>
#include <segmat/medial/voronoi_mat.h>

#include "../common/splitmix.h"

#include <pcl/console/print.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <exception>
#include <limits>

namespace segmat {
namespace {
using Clock = std::chrono::steady_clock;

double
secondsSince(Clock::time_point start)
{
  return std::chrono::duration<double>(Clock::now() - start).count();
}

/** A uniform number in [-0.5, 0.5) from a counter (splitmix64): the jitter of coordinate k of
 * sample i depends on (i, k) only, so it is the same on every platform and thread count. */
double
hashToUnit(std::uint64_t counter)
{
  return static_cast<double>(detail::splitmix64(counter) >> 11) * (1.0 / 9007199254740992.0) -
         0.5;
}

/** Circumcentre of tetrahedron (a, b, c, d); false when it is flat. Solved relative to a:
 * x = (|b'|²(c'×d') + |c'|²(d'×b') + |d'|²(b'×c')) / (2 b'·(c'×d')). */
bool
circumcentre(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
             const Eigen::Vector3d& d, Eigen::Vector3d& centre, double& radius)
{
  const Eigen::Vector3d bb = b - a, cc = c - a, dd = d - a;
  const Eigen::Vector3d cd = cc.cross(dd), db = dd.cross(bb), bc = bb.cross(cc);
  const double det = bb.dot(cd);
  // Relative flatness: det is six times the volume; compare with the edge lengths' product.
  const double scale = bb.norm() * cc.norm() * dd.norm();
  if (!(std::abs(det) > 1e-12 * scale))
    return false;
  const Eigen::Vector3d x =
      (bb.squaredNorm() * cd + cc.squaredNorm() * db + dd.squaredNorm() * bc) / (2.0 * det);
  if (!x.allFinite())
    return false;
  centre = a + x;
  radius = x.norm();
  return true;
}

// Local corner pairs of a tetrahedron's six edges.
const int kEdgeCorners[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};

/** Checks that faces index existing, finite vertices and returns the box of the used vertices
 * (empty with a PCL_ERROR otherwise). */
bool
usedVertexBounds(const TriangleMesh& mesh, Eigen::AlignedBox3d& bounds)
{
  bounds.setEmpty();
  if (mesh.faces.empty()) {
    PCL_ERROR("[segmat::VoronoiMat::compute] The input mesh has no faces.\n");
    return false;
  }
  const int nv = static_cast<int>(mesh.vertices.size());
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    const Eigen::Vector3i& face = mesh.faces[f];
    if (face.minCoeff() < 0 || face.maxCoeff() >= nv) {
      PCL_ERROR("[segmat::VoronoiMat::compute] Face %zu refers to a vertex out of range.\n", f);
      return false;
    }
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector3d& p = mesh.vertices[face[k]];
      if (!p.allFinite()) {
        PCL_ERROR("[segmat::VoronoiMat::compute] Vertex %d has a non-finite coordinate.\n",
                  face[k]);
        return false;
      }
      bounds.extend(p);
    }
  }
  const double diagonal = bounds.diagonal().norm();
  if (std::isinf(diagonal)) {
    PCL_ERROR("[segmat::VoronoiMat::compute] The input mesh's coordinates are so large that its "
              "size overflows (infinite bounding-box diagonal); rescale the mesh.\n");
    return false;
  }
  if (!(diagonal > 0.0)) {
    PCL_ERROR("[segmat::VoronoiMat::compute] The input mesh has no extent.\n");
    return false;
  }
  return true;
}

/** Marks the tetrahedra whose circumcentre is inside the shape (step 3 of VoronoiMat).
 * \param[in] candidates tetrahedra with a finite circumcentre inside the bounding box
 * \param[out] evaluations how many winding numbers were evaluated
 */
std::vector<char>
classifyTetrahedra(const WindingNumber& winding_number, const DelaunayTetrahedra& delaunay,
                   const std::vector<Eigen::Vector3d>& centres, const std::vector<double>& radii,
                   const std::vector<int>& candidates, const std::vector<Eigen::Vector3d>& normals,
                   double min_pole_radius, unsigned threads, std::size_t& evaluations)
{
  const int num_tets = static_cast<int>(delaunay.tetrahedra.size());
  std::vector<char> inside(num_tets, 0);
  evaluations = 0;
  if (!winding_number.isClosed()) {
    // Open input: the winding number is not piecewise constant, so evaluate it wherever the
    // samples' normals do not settle the question (all of them when there are no normals).
    constexpr double kCosPole = 0.5; // within 60° of the normal, as at a pole
    std::vector<int> undecided;
    undecided.reserve(candidates.size());
    for (int t : candidates) {
      if (normals.empty() || !(radii[t] > min_pole_radius)) {
        undecided.push_back(t);
        continue;
      }
      int behind = 0, ahead = 0;
      for (int k = 0; k < 4; ++k) {
        const int v = delaunay.tetrahedra[t][k];
        const double c = (delaunay.points[v] - centres[t]).dot(normals[v]) / radii[t];
        behind += c > kCosPole;
        ahead += c < -kCosPole;
      }
      if (behind == 4)
        inside[t] = 1;
      else if (ahead != 4)
        undecided.push_back(t);
    }
    std::vector<Eigen::Vector3d> queries;
    queries.reserve(undecided.size());
    for (int t : undecided)
      queries.push_back(centres[t]);
    std::vector<double> winding;
    winding_number.evaluate(queries, winding, threads);
    evaluations = queries.size();
    for (std::size_t i = 0; i < undecided.size(); ++i)
      inside[undecided[i]] = winding[i] > 0.5;
    return inside;
  }
  // A closed mesh has an integer winding number that changes only across faces: evaluate it at
  // one circumcentre per connected group of candidate tetrahedra and carry it along the Voronoi
  // edges (the segments between neighbouring circumcentres), counting the faces each crosses.
  // Exact where the hierarchical evaluation is approximate, and far cheaper.
  std::vector<char> is_candidate(num_tets, 0);
  for (int t : candidates)
    is_candidate[t] = 1;
  const int unset = std::numeric_limits<int>::min();
  std::vector<int> winding(num_tets, unset);
  auto evaluate = [&](int t) {
    ++evaluations;
    return static_cast<int>(std::lround(winding_number(centres[t])));
  };
  std::vector<int> queue;
  queue.reserve(candidates.size());
  for (int seed : candidates) {
    if (winding[seed] != unset)
      continue;
    winding[seed] = evaluate(seed);
    queue.assign(1, seed);
    for (std::size_t head = 0; head < queue.size(); ++head) {
      const int t = queue[head];
      for (int i = 0; i < 4; ++i) {
        const int u = delaunay.neighbors[t][i];
        if (u < 0 || !is_candidate[u] || winding[u] != unset)
          continue;
        int change = 0;
        winding[u] = winding_number.windingNumberChange(centres[t], centres[u], change)
                         ? winding[t] + change
                         : evaluate(u); // the crossing count was uncertain
        queue.push_back(u);
      }
    }
  }
  for (int t : candidates)
    inside[t] = winding[t] > 0;
  return inside;
}

/** Voronoi edges and fan-triangulated Voronoi faces between inside tetrahedra (step 4).
 * \param[in] vertex_of medial vertex of each tetrahedron, -1 when it is not inside
 */
void
voronoiEdgesAndFaces(const DelaunayTetrahedra& delaunay, const std::vector<int>& vertex_of,
                     std::vector<Eigen::Vector2i>& edges, std::vector<Eigen::Vector3i>& triangles)
{
  const int num_tets = static_cast<int>(delaunay.tetrahedra.size());
  std::vector<int> ring;
  for (int t = 0; t < num_tets; ++t) {
    if (vertex_of[t] < 0)
      continue;
    const Eigen::Vector4i& corners = delaunay.tetrahedra[t];
    const Eigen::Vector4i& across = delaunay.neighbors[t];
    // Voronoi edges: dual to the facets shared with an inside neighbour (each pair once).
    for (int i = 0; i < 4; ++i)
      if (across[i] > t && vertex_of[across[i]] >= 0)
        edges.emplace_back(vertex_of[t], vertex_of[across[i]]);
    // Voronoi faces: dual to the Delaunay edges of t. Circulate the ring of tetrahedra around
    // edge (a, b); it is made once, from its lowest-indexed tetrahedron, and only when every
    // tetrahedron of the ring is finite and inside.
    for (const auto& pair : kEdgeCorners) {
      const int a = corners[pair[0]], b = corners[pair[1]];
      int entry = -1; // the corner (not a, b) through whose opposite facet we leave
      for (int k = 0; k < 4 && entry < 0; ++k)
        if (k != pair[0] && k != pair[1])
          entry = corners[k];
      ring.assign(1, t);
      int current = t;
      bool closed = false;
      while (static_cast<int>(ring.size()) <= num_tets) {
        const Eigen::Vector4i& cur = delaunay.tetrahedra[current];
        int leave_slot = -1, other = -1;
        for (int k = 0; k < 4; ++k) {
          if (cur[k] == entry)
            leave_slot = k;
          else if (cur[k] != a && cur[k] != b)
            other = cur[k];
        }
        if (leave_slot < 0 || other < 0)
          break; // inconsistent adjacency: give up on this face
        const int next = delaunay.neighbors[current][leave_slot];
        if (next < t || vertex_of[next] < 0) // hull, outside, or made from a lower tetrahedron
          break;
        if (next == t) {
          closed = true;
          break;
        }
        ring.push_back(next);
        entry = other;
        current = next;
      }
      if (!closed || ring.size() < 3)
        continue;
      const int apex = vertex_of[ring[0]];
      for (std::size_t k = 1; k + 1 < ring.size(); ++k) {
        triangles.emplace_back(apex, vertex_of[ring[k]], vertex_of[ring[k + 1]]);
        if (k >= 2)
          edges.emplace_back(apex, vertex_of[ring[k]]); // fan diagonal
      }
    }
  }
}
} // namespace

VoronoiMat::VoronoiMat()
: max_spacing_(0.015)
, max_samples_(12000)
, jitter_(1e-6)
, delaunay_method_(DelaunayMethod::Exact)
, beta_(2.0)
, threads_(1)
{}

double
VoronoiMat::estimateMemoryBytes(const TriangleMesh& mesh, double relative_spacing,
                                std::size_t max_sample_count)
{
  const double candidates =
      estimateSurfaceSampleCount(mesh, relative_spacing * mesh.boundingBoxDiagonal());
  const double kept = max_sample_count > 0 ? std::min(candidates, double(max_sample_count))
                                           : candidates;
  return candidates * kBytesPerCandidate + kept * kBytesPerSample;
}

bool
VoronoiMat::sample(const TriangleMesh& mesh, double diagonal)
{
  const double spacing = max_spacing_ > 0.0 ? max_spacing_ * diagonal : 0.0;
  const double need = estimateMemoryBytes(mesh, max_spacing_, max_samples_);
  if (!surface_samples_ && need > static_cast<double>(availableMemoryBytes())) {
    PCL_ERROR("[segmat::VoronoiMat::compute] The sampling (spacing %g x the diagonal, sample "
              "limit %zu) needs about %.3g GB, more than the %.3g GB available: raise the "
              "spacing or lower the sample limit.\n", max_spacing_, max_samples_, need * 1e-9,
              static_cast<double>(availableMemoryBytes()) * 1e-9);
    return false;
  }
  std::vector<Eigen::Vector3d> candidates, candidate_normals;
  const bool with_normals = surface_samples_ && surface_normals_ &&
                            surface_normals_->size() == surface_samples_->size();
  if (surface_samples_ && surface_normals_ && !with_normals)
    PCL_WARN("[segmat::VoronoiMat::compute] %zu sample normals for %zu samples: ignored.\n",
             surface_normals_->size(), surface_samples_->size());
  if (surface_samples_) {
    for (std::size_t i = 0; i < surface_samples_->size(); ++i)
      if ((*surface_samples_)[i].allFinite()) {
        candidates.push_back((*surface_samples_)[i]);
        if (with_normals)
          candidate_normals.push_back((*surface_normals_)[i]);
      }
  }
  else
    candidates = sampleSurface(mesh, spacing);
  const std::vector<int> representative = weldPoints(candidates, 1e-9 * diagonal);
  samples_.clear();
  sample_normals_.clear();
  samples_.reserve(candidates.size());
  for (std::size_t i = 0; i < candidates.size(); ++i)
    if (representative[i] == static_cast<int>(i)) {
      samples_.push_back(candidates[i]);
      if (with_normals)
        sample_normals_.push_back(candidate_normals[i]);
    }
  if (max_samples_ > 0 && samples_.size() > max_samples_) {
    std::vector<Eigen::Vector3d> thinned, thinned_normals;
    for (int i : thinPointsToCount(samples_, max_samples_)) {
      thinned.push_back(samples_[i]);
      if (with_normals)
        thinned_normals.push_back(sample_normals_[i]);
    }
    samples_.swap(thinned);
    sample_normals_.swap(thinned_normals);
  }
  if (jitter_ > 0.0) {
    const double amplitude = jitter_ * diagonal;
    const std::uint64_t stream = static_cast<std::uint64_t>(jitter_seed_) << 40;
    for (std::size_t i = 0; i < samples_.size(); ++i)
      for (int k = 0; k < 3; ++k)
        samples_[i][k] += amplitude * hashToUnit(stream + 3 * static_cast<std::uint64_t>(i) + k);
  }
  statistics_.num_samples = samples_.size();
  if (samples_.size() < 4) {
    PCL_ERROR("[segmat::VoronoiMat::compute] Only %zu distinct surface samples (need 4).\n",
              samples_.size());
    return false;
  }
  return true;
}

bool
VoronoiMat::tetrahedralize(DelaunayTetrahedra& delaunay)
{
  std::string message;
  bool done = false;
  if (delaunay_method_ == DelaunayMethod::Exact) {
    done = delaunayTetrahedralizeExact(samples_, delaunay, message);
    if (!done)
      PCL_WARN("[segmat::VoronoiMat::compute] Exact Delaunay failed (%s); trying qhull.\n",
               message.c_str());
  }
  if (!done && !delaunayTetrahedralize(samples_, delaunay, message)) {
    PCL_ERROR("[segmat::VoronoiMat::compute] Delaunay tetrahedralisation failed: %s\n",
              message.c_str());
    return false;
  }
  samples_.swap(delaunay.points); // what the tetrahedra are Delaunay for
  statistics_.num_tetrahedra = delaunay.tetrahedra.size();
  return true;
}

bool
VoronoiMat::compute(MedialMesh& output)
{
  output = MedialMesh();
  statistics_ = VoronoiMatStatistics();
  samples_.clear();
  sample_normals_.clear();
  if (!mesh_) {
    PCL_ERROR("[segmat::VoronoiMat::compute] No input mesh set.\n");
    return false;
  }
  const TriangleMesh& mesh = *mesh_;

  // 1. samples
  auto start = Clock::now();
  Eigen::AlignedBox3d bounds;
  if (!usedVertexBounds(mesh, bounds) || !sample(mesh, bounds.diagonal().norm()))
    return false;
  statistics_.seconds_sampling = secondsSince(start);

  // 2. Delaunay
  start = Clock::now();
  DelaunayTetrahedra delaunay;
  if (!tetrahedralize(delaunay))
    return false;
  statistics_.seconds_delaunay = secondsSince(start);

  // 3. inside test on the circumcentres; Q-MAT keeps a circumcentre only inside the bounding
  // box, which is also a cheap pre-filter.
  start = Clock::now();
  const int num_tets = static_cast<int>(delaunay.tetrahedra.size());
  std::vector<Eigen::Vector3d> centres(num_tets);
  std::vector<double> radii(num_tets, 0.0);
  std::vector<int> candidates;
  candidates.reserve(num_tets);
  for (int t = 0; t < num_tets; ++t) {
    const Eigen::Vector4i& v = delaunay.tetrahedra[t];
    if (circumcentre(samples_[v[0]], samples_[v[1]], samples_[v[2]], samples_[v[3]], centres[t],
                     radii[t]) &&
        bounds.contains(centres[t]))
      candidates.push_back(t);
  }
  std::shared_ptr<const WindingNumber> winding_number = winding_number_;
  if (!winding_number) {
    auto own = std::make_shared<WindingNumber>(mesh);
    own->setAccuracy(beta_);
    winding_number = std::move(own);
  }
  // Normals decide only balls wider than twice the sample spacing: noise leaves small empty
  // balls against the surface whose four normals agree by chance.
  double area = 0.0;
  for (int f = 0; f < static_cast<int>(mesh.numFaces()); ++f)
    area += mesh.faceArea(f);
  const double min_pole_radius = 2.0 * std::sqrt(area / double(samples_.size()));
  const std::vector<char> inside = classifyTetrahedra(
      *winding_number, delaunay, centres, radii, candidates, sample_normals_, min_pole_radius,
      threads_, statistics_.num_winding_evaluations);
  std::vector<int> vertex_of(num_tets, -1);
  std::vector<Eigen::Vector3d> mat_centres;
  std::vector<double> mat_radii;
  for (int t : candidates)
    if (inside[t]) {
      vertex_of[t] = static_cast<int>(mat_centres.size());
      mat_centres.push_back(centres[t]);
      mat_radii.push_back(radii[t]);
    }
  statistics_.num_inside = mat_centres.size();
  statistics_.seconds_inside = secondsSince(start);

  // 4. medial edges and triangles
  start = Clock::now();
  std::vector<Eigen::Vector2i> edges;
  std::vector<Eigen::Vector3i> triangles;
  voronoiEdgesAndFaces(delaunay, vertex_of, edges, triangles);
  try {
    output = MedialMesh(std::move(mat_centres), std::move(mat_radii), edges, triangles);
  }
  catch (const std::exception& e) {
    PCL_ERROR("[segmat::VoronoiMat::compute] Could not build the medial mesh: %s\n", e.what());
    output = MedialMesh();
    return false;
  }
  statistics_.num_vertices = output.numVertices();
  statistics_.num_edges = output.numEdges();
  statistics_.num_triangles = output.numTriangles();
  statistics_.seconds_assembly = secondsSince(start);
  return true;
}

} // namespace segmat
