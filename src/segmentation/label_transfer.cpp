/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include <segmat/geometry/face_orientation.h>
#include <segmat/geometry/sphere_tree.h>
#include <segmat/segmentation/label_transfer.h>

#include "../common/point_kd_tree.h"
#include "../common/thread_count.h"
#include "../graph_cut/coarse_expansion.h"
#include "../graph_cut/relabel_free_nodes.h"
#include "flat_boundaries.h"

#include <pcl/console/print.h>
#include <pcl/common/point_tests.h>
#include <pcl/pcl_base.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <numeric>
#include <utility>

namespace segmat {
namespace {

// A part without spheres can never be the closest one.
constexpr double kNoPartCost = 1e9;
constexpr double kRadiansToDegrees = 57.295779513082320876798154814105;

} // namespace

Eigen::MatrixXd
computePartDistanceCosts(const std::vector<Eigen::Vector3d>& positions, const MatGraph& graph,
                         const std::vector<std::vector<int>>& parts, unsigned int threads)
{
  const long n = static_cast<long>(positions.size());
  const int num_parts = static_cast<int>(parts.size());
  Eigen::MatrixXd costs(n, num_parts);
  double diagonal = graph.centerBoundingBoxDiagonal();
  if (!(diagonal > 0.0))
    diagonal = 1.0; // one sphere, or all centres equal: distances are then in model units
  const double scale = kTransferEnergyScale / diagonal;
  std::vector<SphereTree> trees;
  trees.reserve(num_parts);
  for (int l = 0; l < num_parts; ++l) {
    std::vector<int> spheres;
    for (int node : parts[l]) {
      const MatNode& m = graph.node(node);
      for (int k = 0; k < m.size(); ++k)
        spheres.push_back(m.v[k]);
    }
    trees.emplace_back(graph.centers(), graph.radii(), spheres);
  }
  // One parallel region for all parts (a fork/join per part costs more than it saves on busy
  // machines). Consecutive elements are usually close, so each part's previous answer is a good
  // first bound; the result does not depend on it (the minimum is exact), hence not on threads.
  std::vector<int> hints(num_parts, -1);
  [[maybe_unused]] const int num_threads = detail::threadCount(threads);
#pragma omp parallel for schedule(static) firstprivate(hints) num_threads(num_threads)
  for (long i = 0; i < n; ++i) {
    const bool finite = positions[i].allFinite();
    for (int l = 0; l < num_parts; ++l) {
      if (trees[l].empty())
        costs(i, l) = kNoPartCost;
      else if (!finite)
        costs(i, l) = 0.0; // no preference: the neighbours decide
      else {
        const double d = trees[l].signedDistance(positions[i], 0.0, &hints[l]);
        costs(i, l) = d > 0.0 ? std::floor(d * scale) : 0.0;
      }
    }
  }
  return costs;
}

double
computeCreaseCost(const Eigen::Vector3d& centre_a, const Eigen::Vector3d& normal_a,
                  const Eigen::Vector3d& centre_b, const Eigen::Vector3d& normal_b, double omega,
                  CreaseModel model)
{
  double cosine = normal_a.dot(normal_b);
  if (!std::isfinite(cosine))
    cosine = 0.0;
  const double theta = std::acos(std::clamp(cosine, -1.0, 1.0)) * kRadiansToDegrees;
  const Eigen::Vector3d step = centre_b - centre_a;
  const bool concave = step.dot(normal_a - normal_b) > 1e-6 * step.norm(); // NaN → convex
  double per_registration = omega * ((concave ? 180.0 : 360.0) - theta) / 180.0;
  // No jump at θ = 0, on purpose (docs/method.md).
  if (concave && model == CreaseModel::SharpConcave)
    per_registration = 2.0 * omega * std::exp(-theta / kConcaveCreaseAngle);
  // Truncated like the reference's int(), with a little slack so that exact angles (flat, 90°)
  // are not pushed one unit down by round-off in acos. The reference registered every adjacency
  // twice, (i, j) and (j, i): the cost counts double.
  return 2.0 * std::floor(std::max(0.0, per_registration * kTransferEnergyScale) + 1e-6);
}

namespace {

/// A boundary edge's curvature until measureSideCurvatures() measures it.
constexpr double kUnmeasured = std::numeric_limits<double>::quiet_NaN();

/// computeMeshSmoothnessEdges(), and with \a boundary the face pairs, each weighted by its
/// shared edge's length, and the outward face normals.
std::vector<PottsEdge>
meshSmoothnessEdges(const TriangleMesh& mesh, double omega, CreaseModel model,
                    detail::BoundaryGraph* boundary)
{
  const std::vector<FaceAdjacency> adjacency = mesh.faceAdjacency();
  const std::vector<int> signs = computeOutwardFaceSigns(mesh, adjacency);
  const int num_faces = static_cast<int>(mesh.numFaces());
  std::vector<Eigen::Vector3d> normals(num_faces), centroids(num_faces);
  for (int f = 0; f < num_faces; ++f) {
    normals[f] = signs[f] * mesh.faceNormal(f);
    centroids[f] = mesh.faceCentroid(f);
  }
  std::vector<PottsEdge> edges(adjacency.size());
  if (boundary) {
    boundary->edges.resize(adjacency.size());
    boundary->normals = normals;
  }
  for (std::size_t k = 0; k < adjacency.size(); ++k) {
    const int a = adjacency[k].face_a, b = adjacency[k].face_b;
    edges[k] = {a, b,
                computeCreaseCost(centroids[a], normals[a], centroids[b], normals[b], omega, model)};
    if (boundary)
      boundary->edges[k] = {
          a, b, kUnmeasured,
          (mesh.vertices[adjacency[k].v0] - mesh.vertices[adjacency[k].v1]).norm()};
  }
  if (boundary)
    detail::indexNeighbours(*boundary, num_faces);
  return edges;
}

} // namespace

std::vector<PottsEdge>
computeMeshSmoothnessEdges(const TriangleMesh& mesh, double omega, CreaseModel model)
{
  return meshSmoothnessEdges(mesh, omega, model, nullptr);
}

namespace {

/// computeCloudSmoothnessEdges(), and with \a boundary (and normals) the point pairs, weight 1,
/// and the points' normals.
std::vector<PottsEdge>
cloudSmoothnessEdges(const pcl::PointCloud<pcl::PointXYZ>::ConstPtr& cloud,
                     const pcl::PointCloud<pcl::Normal>::ConstPtr& normals,
                     const std::vector<int>& nodes, int k, double omega, CreaseModel model,
                     unsigned int threads, detail::BoundaryGraph* boundary)
{
  if (boundary)
    *boundary = {};
  std::vector<PottsEdge> edges;
  if (!cloud || nodes.size() < 2 || k < 1)
    return edges;
  const int num_nodes = static_cast<int>(nodes.size());
  std::vector<int> node_of(cloud->size(), -1);
  for (int a = 0; a < num_nodes; ++a)
    node_of[nodes[a]] = a;
  detail::PointKdTree tree;
  tree.setInputCloud(cloud, pcl::IndicesConstPtr(new pcl::Indices(nodes.begin(), nodes.end())));
  const int num_found = std::min(k + 1, num_nodes); // the point itself comes back too
  std::vector<int> found_nodes(static_cast<std::size_t>(num_nodes) * num_found, -1);
#pragma omp parallel for schedule(static) num_threads(detail::threadCount(threads))
  for (int a = 0; a < num_nodes; ++a) {
    pcl::Indices found;
    std::vector<float> sq;
    tree.nearestKSearch((*cloud)[nodes[a]], num_found, found, sq);
    for (std::size_t j = 0; j < found.size() && j < static_cast<std::size_t>(num_found); ++j)
      found_nodes[static_cast<std::size_t>(a) * num_found + j] = node_of[found[j]];
  }
  // Symmetric graph: an edge when either point lists the other. Sorted and unique, by a
  // counting sort on the lower end and small sorts of each one's higher ends (a sort of all
  // k·n pairs was ~1 % of a cloud's segmentation).
  std::vector<int> start(static_cast<std::size_t>(num_nodes) + 1, 0);
  auto forEachPair = [&](auto visit) {
    for (int a = 0; a < num_nodes; ++a)
      for (int j = 0; j < num_found; ++j) {
        const int b = found_nodes[static_cast<std::size_t>(a) * num_found + j];
        if (b >= 0 && b != a)
          visit(std::min(a, b), std::max(a, b));
      }
  };
  forEachPair([&](int lo, int) { ++start[lo + 1]; });
  for (int a = 0; a < num_nodes; ++a)
    start[a + 1] += start[a];
  std::vector<int> higher(start.back()), next(start.begin(), start.end() - 1);
  forEachPair([&](int lo, int hi) { higher[next[lo]++] = hi; });
  std::vector<std::pair<int, int>> pairs;
  pairs.reserve(higher.size());
  for (int a = 0; a < num_nodes; ++a) {
    const auto begin = higher.begin() + start[a], end = higher.begin() + start[a + 1];
    std::sort(begin, end);
    for (auto it = begin; it != end; ++it)
      if (it == begin || *it != *(it - 1))
        pairs.emplace_back(a, *it);
  }

  // Per-edge scale so that cutting a cloud costs about what cutting the mesh does (see header).
  const double degree_scale = 2.0 / k;
  // Without normals every edge costs what a flat edge costs on a mesh.
  const double flat = computeCreaseCost(Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ(),
                                        Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitZ(), omega);
  edges.reserve(pairs.size());
  if (boundary && normals) {
    boundary->edges.reserve(pairs.size());
    boundary->normals.resize(nodes.size());
    for (int a = 0; a < num_nodes; ++a)
      boundary->normals[a] = (*normals)[nodes[a]].getNormalVector3fMap().cast<double>();
  }
  for (const auto& p : pairs) {
    double w = flat;
    if (normals) {
      const int ia = nodes[p.first], ib = nodes[p.second];
      const Eigen::Vector3d ca = (*cloud)[ia].getVector3fMap().cast<double>(),
                            na = (*normals)[ia].getNormalVector3fMap().cast<double>(),
                            cb = (*cloud)[ib].getVector3fMap().cast<double>(),
                            nb = (*normals)[ib].getNormalVector3fMap().cast<double>();
      w = computeCreaseCost(ca, na, cb, nb, omega, model);
      if (boundary) // without normals nothing tells a flat boundary: none is joined
        boundary->edges.push_back({p.first, p.second, kUnmeasured, 1.0});
    }
    edges.push_back({p.first, p.second, std::floor(w * degree_scale)});
  }
  if (boundary)
    detail::indexNeighbours(*boundary, num_nodes);
  return edges;
}

} // namespace

std::vector<PottsEdge>
computeCloudSmoothnessEdges(const pcl::PointCloud<pcl::PointXYZ>::ConstPtr& cloud,
                            const pcl::PointCloud<pcl::Normal>::ConstPtr& normals,
                            const std::vector<int>& nodes, int k, double omega,
                            CreaseModel model, unsigned int threads)
{
  return cloudSmoothnessEdges(cloud, normals, nodes, k, omega, model, threads, nullptr);
}

int
compactLabels(std::vector<int>& labels)
{
  int max_label = -1;
  for (int l : labels)
    max_label = std::max(max_label, l);
  std::vector<int> rank(max_label + 1, -1);
  for (int l : labels)
    if (l >= 0)
      rank[l] = 0;
  int count = 0;
  for (int& r : rank)
    if (r == 0)
      r = count++;
  for (int& l : labels)
    if (l >= 0)
      l = rank[l];
  return count;
}

void
LabelTransferBase::setSmoothnessWeight(double omega)
{
  if (!std::isfinite(omega) || omega < 0.0) {
    PCL_WARN("[segmat::LabelTransfer::setSmoothnessWeight] %g ignored (must be finite and >= 0), "
             "keeping %g.\n",
             omega, omega_);
    return;
  }
  omega_ = omega;
}

void
LabelTransferBase::setMinPartFraction(double fraction)
{
  if (!(fraction >= 0.0 && fraction < 1.0)) {
    PCL_WARN("[segmat::LabelTransfer::setMinPartFraction] %g ignored (must be in [0, 1)), "
             "keeping %g.\n",
             fraction, min_part_fraction_);
    return;
  }
  min_part_fraction_ = fraction;
}

bool
LabelTransferBase::solve(const char* caller, const std::vector<Eigen::Vector3d>& positions,
                         const std::vector<double>& weights, std::vector<int>& labels)
{
  label_parts_.clear();
  energy_ = 0.0;
  cycles_ = 0;
  if (!graph_ || graph_->empty()) {
    PCL_ERROR("[segmat::%s::transfer] no MAT graph, or an empty one.\n", caller);
    return false;
  }
  if (parts_.empty()) {
    PCL_ERROR("[segmat::%s::transfer] no parts.\n", caller);
    return false;
  }
  const int num_nodes = static_cast<int>(graph_->numNodes());
  for (std::size_t l = 0; l < parts_.size(); ++l)
    for (int node : parts_[l])
      if (node < 0 || node >= num_nodes) {
        PCL_ERROR("[segmat::%s::transfer] part %zu names node %d; the graph has %d nodes.\n",
                  caller, l, node, num_nodes);
        return false;
      }
  if (parts_.size() == 1) {
    labels.assign(positions.size(), 0);
    label_parts_.assign(positions.empty() ? 0 : 1, std::vector<int>{0});
    return true;
  }
  const Eigen::MatrixXd unary = computePartDistanceCosts(positions, *graph_, parts_, threads_);
  solver_.setUnaryCosts(unary);
  const bool coarse =
      max_full_cut_ > 0 && static_cast<std::size_t>(unary.rows()) > max_full_cut_;
  // Half as many clusters as the limit: the coarse cut then costs no more than the full cut
  // of a surface just below the limit.
  const long clusters = static_cast<long>(std::max<std::size_t>(1, max_full_cut_ / 2));
  detail::CoarseExpansion report;
  if (coarse ? !detail::coarseToFineExpansion(
                   unary, solver_.getEdges(),
                   static_cast<int>((unary.rows() + clusters - 1) / clusters),
                   solver_.getMaxCycles(), labels, &report)
             : !solver_.compute(labels)) {
    labels.clear();
    return false;
  }
  cycles_ = coarse ? report.cycles : solver_.getCycles();
  // Parts below the minimal share are dropped, and only the elements they won get new labels,
  // with every other element held at its label: those were chosen under the same costs, and
  // cutting the whole surface again would cost up to two thirds of the first cut. Kept parts
  // only gain elements, so one round leaves none below the share.
  std::vector<int> kept(parts_.size());
  std::iota(kept.begin(), kept.end(), 0);
  energy_ = coarse ? computePottsEnergy(unary, solver_.getEdges(), labels) : solver_.getEnergy();
  if (min_part_fraction_ > 0.0 && kept.size() > 1) {
    std::vector<double> share(kept.size(), 0.0);
    double total = 0.0;
    for (std::size_t i = 0; i < labels.size(); ++i) {
      const double w = weights.empty() ? 1.0 : weights[i];
      share[labels[i]] += w;
      total += w;
    }
    std::vector<int> next;
    for (std::size_t r = 0; r < kept.size(); ++r)
      if (share[r] >= min_part_fraction_ * total)
        next.push_back(static_cast<int>(r));
    const bool dropped = std::any_of(share.begin(), share.end(), [&](double v) {
      return v > 0.0 && v < min_part_fraction_ * total;
    });
    if (dropped && !next.empty()) {
      Eigen::MatrixXd reduced(unary.rows(), static_cast<Eigen::Index>(next.size()));
      std::vector<int> column(kept.size(), -1); // label → its column in reduced
      for (std::size_t r = 0; r < next.size(); ++r) {
        reduced.col(static_cast<Eigen::Index>(r)) = unary.col(next[r]);
        column[next[r]] = static_cast<int>(r);
      }
      std::vector<char> dropped_element(labels.size());
      for (std::size_t i = 0; i < labels.size(); ++i) {
        dropped_element[i] = column[labels[i]] < 0;
        labels[i] = column[labels[i]];
      }
      if (!detail::relabelFreeNodes(reduced, solver_.getEdges(), dropped_element,
                                    solver_.getMaxCycles(), labels)) {
        labels.clear();
        return false;
      }
      energy_ = computePottsEnergy(reduced, solver_.getEdges(), labels);
      kept.swap(next);
    }
  }
  // Parts whose boundary crosses flat surface become one; a joined label is named by its
  // lowest part.
  std::vector<int> group(kept.size());
  std::iota(group.begin(), group.end(), 0);
  if (join_flat_boundaries_ && kept.size() > 1 && boundary_ && !boundary_->edges.empty()) {
    Eigen::AlignedBox3d box;
    for (const Eigen::Vector3d& p : positions)
      if (p.allFinite())
        box.extend(p);
    group = detail::joinFlatBoundaries(labels, static_cast<int>(kept.size()),
                                       detail::measureSideCurvatures(*boundary_, labels, positions),
                                       box.isEmpty() ? 0.0 : box.diagonal().norm());
  }
  std::vector<int> named(kept.size(), -1);
  for (std::size_t r = 0; r < kept.size(); ++r)
    if (named[group[r]] < 0)
      named[group[r]] = kept[r]; // kept ascends: the group's lowest part comes first
  for (int& l : labels)
    l = named[group[l]];
  std::vector<std::vector<int>> members(parts_.size());
  for (std::size_t r = 0; r < kept.size(); ++r)
    members[named[group[r]]].push_back(kept[r]);
  std::vector<char> present(parts_.size(), 0);
  for (int l : labels)
    present[l] = 1;
  for (std::size_t l = 0; l < parts_.size(); ++l)
    if (present[l])
      label_parts_.push_back(std::move(members[l]));
  compactLabels(labels);
  return true;
}

void
LabelTransferBase::setJoinFlatBoundaries(bool join)
{
  join_flat_boundaries_ = join;
}

detail::BoundaryGraph*
LabelTransferBase::newBoundary()
{
  boundary_ = std::make_shared<detail::BoundaryGraph>();
  return boundary_.get();
}

bool
MeshLabelTransfer::transfer(std::vector<int>& face_labels)
{
  face_labels.clear();
  label_parts_.clear();
  if (!mesh_ || mesh_->empty()) {
    PCL_ERROR("[segmat::MeshLabelTransfer::transfer] no mesh, or a mesh without faces.\n");
    return false;
  }
  // The face graph is only needed when there is something to cut (and then kept for reuse).
  if (parts_.size() > 1 && edgesStale()) {
    solver_.setEdges(meshSmoothnessEdges(*mesh_, omega_, crease_model_, newBoundary()));
    markEdgesBuilt();
  }
  std::vector<Eigen::Vector3d> centroids(mesh_->numFaces());
  std::vector<double> areas(mesh_->numFaces());
  for (std::size_t f = 0; f < centroids.size(); ++f) {
    centroids[f] = mesh_->faceCentroid(static_cast<int>(f));
    areas[f] = mesh_->faceArea(static_cast<int>(f));
  }
  return solve("MeshLabelTransfer", centroids, areas, face_labels);
}

namespace {

/** Voxel key of p: 21 bits per axis of floor((p − lo) / h). */
std::uint64_t
voxelKey(const pcl::PointXYZ& p, const Eigen::Vector3d& lo, double h)
{
  const Eigen::Vector3d g = (p.getVector3fMap().cast<double>() - lo) / h;
  std::uint64_t key = 0;
  for (int a = 0; a < 3; ++a)
    key |= static_cast<std::uint64_t>(std::clamp(std::floor(g[a]), 0.0, 2097151.0)) << (21 * a);
  return key;
}

/** One representative per occupied voxel: the lowest-index point in it. The voxel edge is set
 * so that about \a target voxels are occupied: starting from 2.5 times the median
 * nearest-neighbour spacing of an evenly strided subsample, it is corrected twice by
 * sqrt(count / target) (a surface's voxel count goes as 1/h²), counting on a 4·target-point
 * subsample. node_of_point[i] becomes the voxel number of point i (-1 for points not in
 * \a finite); reps lists the representatives in voxel-key order (spatially coherent, which the
 * data term's search likes). \a threads: of the spacing search (the result does not depend on
 * it).
 */
void
sampleVoxelRepresentatives(const pcl::PointCloud<pcl::PointXYZ>::ConstPtr& cloud,
                           const std::vector<int>& finite, std::size_t target,
                           std::vector<int>& reps, std::vector<int>& node_of_point,
                           unsigned int threads)
{
  const pcl::PointCloud<pcl::PointXYZ>& c = *cloud;
  const auto strided = [&](std::size_t count) {
    auto sample = std::make_shared<pcl::Indices>();
    const std::size_t stride = std::max<std::size_t>(1, finite.size() / count);
    for (std::size_t k = 0; k < finite.size(); k += stride)
      sample->push_back(finite[k]);
    return sample;
  };
  const auto sample = strided(target);
  detail::PointKdTree tree;
  tree.setInputCloud(cloud, sample);
  std::vector<float> spacing(sample->size(), 0.0f);
#pragma omp parallel for schedule(static) num_threads(detail::threadCount(threads))
  for (long k = 0; k < static_cast<long>(sample->size()); ++k) {
    pcl::Indices found;
    std::vector<float> sq;
    if (tree.nearestKSearch(c[(*sample)[k]], 2, found, sq) == 2)
      spacing[k] = std::sqrt(sq[1]);
  }
  std::nth_element(spacing.begin(), spacing.begin() + spacing.size() / 2, spacing.end());
  Eigen::Vector3d lo = c[finite[0]].getVector3fMap().cast<double>(), hi = lo;
  for (int i : finite) {
    lo = lo.cwiseMin(c[i].getVector3fMap().cast<double>());
    hi = hi.cwiseMax(c[i].getVector3fMap().cast<double>());
  }
  // 21 bits per axis bound the smallest edge; coincident points fall back to a box-sized grid.
  const double smallest = (hi - lo).maxCoeff() / 2097151.0;
  double h = std::max(2.5 * spacing[spacing.size() / 2], smallest);
  if (!(h > 0.0))
    h = 1.0;
  const auto calibration = strided(4 * target);
  std::vector<std::uint64_t> keys(calibration->size());
  for (int pass = 0; pass < 2; ++pass) {
    for (std::size_t k = 0; k < keys.size(); ++k)
      keys[k] = voxelKey(c[(*calibration)[k]], lo, h);
    std::sort(keys.begin(), keys.end());
    const double count =
        static_cast<double>(std::unique(keys.begin(), keys.end()) - keys.begin());
    h = std::max(h * std::sqrt(count / static_cast<double>(target)), smallest);
  }

  std::vector<std::pair<std::uint64_t, int>> keyed(finite.size());
  for (std::size_t k = 0; k < finite.size(); ++k)
    keyed[k] = {voxelKey(c[finite[k]], lo, h), finite[k]};
  std::sort(keyed.begin(), keyed.end());
  reps.clear();
  for (std::size_t k = 0; k < keyed.size(); ++k) {
    if (k == 0 || keyed[k].first != keyed[k - 1].first)
      reps.push_back(keyed[k].second); // lowest index of its voxel
    node_of_point[keyed[k].second] = static_cast<int>(reps.size()) - 1;
  }
}

} // namespace

void
CloudLabelTransfer::setNeighbourCount(int k)
{
  if (k < 1) {
    PCL_WARN("[segmat::CloudLabelTransfer::setNeighbourCount] %d < 1 ignored, keeping %d.\n", k,
             k_);
    return;
  }
  k_ = k;
  edges_valid_ = false;
}

bool
CloudLabelTransfer::transfer(std::vector<int>& point_labels)
{
  point_labels.clear();
  label_parts_.clear();
  if (!cloud_ || cloud_->empty()) {
    PCL_ERROR("[segmat::CloudLabelTransfer::transfer] no cloud, or an empty one.\n");
    return false;
  }
  if (normals_ && normals_->size() != cloud_->size()) {
    PCL_ERROR("[segmat::CloudLabelTransfer::transfer] %zu normals for %zu points.\n",
              static_cast<std::size_t>(normals_->size()),
              static_cast<std::size_t>(cloud_->size()));
    return false;
  }
  const pcl::PointCloud<pcl::PointXYZ>& cloud = *cloud_;
  if (!nodes_valid_) {
    std::vector<int> finite;
    for (std::size_t i = 0; i < cloud.size(); ++i)
      if (pcl::isFinite(cloud[i]))
        finite.push_back(static_cast<int>(i));
    node_of_point_.assign(cloud.size(), -1);
    if (max_graph_points_ > 0 && finite.size() > max_graph_points_)
      sampleVoxelRepresentatives(cloud_, finite, max_graph_points_, nodes_, node_of_point_,
                                 threads_);
    else {
      nodes_ = finite;
      for (std::size_t k = 0; k < finite.size(); ++k)
        node_of_point_[finite[k]] = static_cast<int>(k);
    }
    nodes_valid_ = true;
  }
  if (nodes_.empty()) {
    PCL_ERROR("[segmat::CloudLabelTransfer::transfer] no point has finite coordinates.\n");
    return false;
  }
  // The neighbour graph is only needed when there is something to cut (and then kept).
  if (parts_.size() > 1 && edgesStale()) {
    solver_.setEdges(cloudSmoothnessEdges(cloud_, normals_, nodes_, k_, omega_, crease_model_,
                                          threads_, newBoundary()));
    markEdgesBuilt();
  }
  std::vector<Eigen::Vector3d> positions(nodes_.size());
  for (std::size_t k = 0; k < nodes_.size(); ++k)
    positions[k] = cloud[nodes_[k]].getVector3fMap().cast<double>();
  std::vector<int> labels;
  if (!solve("CloudLabelTransfer", positions, {}, labels))
    return false;
  point_labels.assign(cloud.size(), -1);
  for (std::size_t i = 0; i < cloud.size(); ++i)
    if (node_of_point_[i] >= 0)
      point_labels[i] = labels[node_of_point_[i]];
  return true;
}

} // namespace segmat
