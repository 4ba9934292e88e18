/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include <segmat/geometry/oriented_box.h>
#include <segmat/geometry/surface_sampling.h>

extern "C" {
#include <libqhull_r/qhull_ra.h>
}

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <set>
#include <tuple>

namespace segmat {
namespace {

using Points = std::vector<Eigen::Vector3d>;

constexpr std::size_t kMaxCandidateVertices = 200;
constexpr std::size_t kRecheckedCandidates = 16;
constexpr std::size_t kMaxEdgePairDirections = 60;

/** The box with the given axes (rows) that just holds the points. */
OrientedBox
fitBox(const Points& points, const Eigen::Matrix3d& axes)
{
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector3d hi = -lo;
  for (const Eigen::Vector3d& p : points) {
    const Eigen::Vector3d t = axes * p;
    lo = lo.cwiseMin(t);
    hi = hi.cwiseMax(t);
  }
  OrientedBox box;
  box.axes = axes;
  if (points.empty())
    return box;
  box.extents = hi - lo;
  box.center = axes.transpose() * (0.5 * (lo + hi));
  return box;
}

/** What "smaller" means: volume first; among boxes of equal volume (flat or collinear points)
 * the smaller surface, then the shorter edge sum, so that degenerate sets get a tight box too.
 * Equal means within 1e-12 of the points' size to that power (rounding noise). */
struct BoxCost
{
  double volume = 0.0, area = 0.0, length = 0.0;

  bool
  smallerThan(const BoxCost& other, double size) const
  {
    const double v = 1e-12 * size * size * size, a = 1e-12 * size * size, l = 1e-12 * size;
    if (volume < other.volume - v || volume > other.volume + v)
      return volume < other.volume;
    if (area < other.area - a || area > other.area + a)
      return area < other.area;
    return length < other.length - l;
  }
};

BoxCost
boxCost(const Points& points, const Eigen::Matrix3d& axes)
{
  const Eigen::Vector3d e = fitBox(points, axes).extents;
  return {e.prod(), e[0] * e[1] + e[1] * e[2] + e[2] * e[0], e.sum()};
}

/** Two unit vectors completing n to an orthonormal frame. */
void
planeBasis(const Eigen::Vector3d& n, Eigen::Vector3d& u, Eigen::Vector3d& v)
{
  const Eigen::Vector3d helper =
      std::abs(n.x()) < 0.6 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
  u = n.cross(helper).normalized();
  v = n.cross(u);
}

double
cross2(const Eigen::Vector2d& o, const Eigen::Vector2d& a, const Eigen::Vector2d& b)
{
  return (a - o).x() * (b - o).y() - (a - o).y() * (b - o).x();
}

/** Andrew's monotone chain: the 2D hull counter-clockwise, without collinear points. */
std::vector<Eigen::Vector2d>
hull2d(std::vector<Eigen::Vector2d> p)
{
  std::sort(p.begin(), p.end(), [](const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    return std::tie(a.x(), a.y()) < std::tie(b.x(), b.y());
  });
  if (p.size() < 3)
    return p;
  std::vector<Eigen::Vector2d> h(2 * p.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    while (k >= 2 && cross2(h[k - 2], h[k - 1], p[i]) <= 0.0)
      --k;
    h[k++] = p[i];
  }
  for (std::size_t i = p.size() - 1, t = k + 1; i-- > 0;) {
    while (k >= t && cross2(h[k - 2], h[k - 1], p[i]) <= 0.0)
      --k;
    h[k++] = p[i];
  }
  h.resize(k - 1);
  return h;
}

/** Direction (unit 2D) of one side of the minimal-area rectangle of a ccw convex polygon, by
 * rotating calipers: one side of the optimum is flush with a polygon edge (Freeman, Shapira
 * 1975), and the extreme vertices along the edge and its normal only move forward as the edge
 * advances, so all edges are tried in O(h). */
Eigen::Vector2d
minAreaRectangleSide(const std::vector<Eigen::Vector2d>& h)
{
  const std::size_t n = h.size();
  if (n < 2)
    return Eigen::Vector2d::UnitX();
  if (n == 2)
    return (h[1] - h[0]).normalized();
  double best_area = std::numeric_limits<double>::infinity();
  Eigen::Vector2d best = Eigen::Vector2d::UnitX();
  std::size_t far = 1, right = 1, left = 0; // extremes along the normal, +edge and −edge
  const auto next = [n](std::size_t i) { return (i + 1) % n; };
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Vector2d e = (h[next(i)] - h[i]).normalized();
    const Eigen::Vector2d normal(-e.y(), e.x()); // inward for a ccw polygon
    const auto advance = [&](std::size_t& j, const Eigen::Vector2d& dir) {
      for (std::size_t guard = 0; guard < n && dir.dot(h[next(j)]) >= dir.dot(h[j]); ++guard)
        j = next(j);
    };
    if (i == 0) { // the first edge starts the three callipers at their extremes
      for (std::size_t j = 0; j < n; ++j) {
        if (normal.dot(h[j]) > normal.dot(h[far]))
          far = j;
        if (e.dot(h[j]) > e.dot(h[right]))
          right = j;
        if (e.dot(h[j]) < e.dot(h[left]))
          left = j;
      }
    }
    advance(far, normal);
    advance(right, e);
    advance(left, -e);
    const double area = (e.dot(h[right]) - e.dot(h[left])) * (normal.dot(h[far] - h[i]));
    if (area < best_area) {
      best_area = area;
      best = e;
    }
  }
  return best;
}

/** Axes (rows) of the smallest box with one axis along n: n and the minimal-area rectangle of
 * the points projected onto the plane ⊥ n. */
Eigen::Matrix3d
boxAxesAround(const Points& points, const Eigen::Vector3d& n)
{
  Eigen::Vector3d u, v;
  planeBasis(n, u, v);
  std::vector<Eigen::Vector2d> projected(points.size());
  for (std::size_t i = 0; i < points.size(); ++i)
    projected[i] = Eigen::Vector2d(u.dot(points[i]), v.dot(points[i]));
  const Eigen::Vector2d side = minAreaRectangleSide(hull2d(std::move(projected)));
  Eigen::Matrix3d axes;
  axes.row(0) = n;
  axes.row(1) = (side.x() * u + side.y() * v).normalized();
  axes.row(2) = n.cross(Eigen::Vector3d(axes.row(1)));
  return axes;
}

/** Convex hull vertices, facet normals and edge directions by qhull ("Qt": triangulated output,
 * so every facet lists three vertices). False for flat, collinear or too few points. */
bool
convexHull(const Points& points, Points& vertices, Points& directions, Points& edges)
{
  if (points.size() < 4)
    return false;
  std::vector<coordT> coords(3 * points.size());
  for (std::size_t i = 0; i < points.size(); ++i)
    for (int k = 0; k < 3; ++k)
      coords[3 * i + k] = points[i][k];
  // qhull reports through a FILE*: keep its messages off the user's terminal.
  char* error_buffer = nullptr;
  std::size_t error_size = 0;
  FILE* error_file = open_memstream(&error_buffer, &error_size);
  qhT qh_qh;
  qhT* qh = &qh_qh;
  qh_zero(qh, error_file);
  char options[] = "qhull Qt";
  const int exit_code = qh_new_qhull(qh, 3, static_cast<int>(points.size()), coords.data(),
                                     False, options, nullptr, error_file);
  if (exit_code == 0) {
    vertexT* vertex;
    FORALLvertices
    vertices.push_back(points[qh_pointid(qh, vertex->point)]);
    facetT* facet;
    FORALLfacets
    {
      directions.emplace_back(facet->normal[0], facet->normal[1], facet->normal[2]);
      std::vector<Eigen::Vector3d> corners;
      vertexT** vertexp;
      FOREACHvertex_(facet->vertices)
      corners.push_back(points[qh_pointid(qh, vertex->point)]);
      for (std::size_t k = 0; k < corners.size(); ++k)
        edges.push_back(corners[(k + 1) % corners.size()] - corners[k]);
    }
  }
  qh_freeqhull(qh, !qh_ALL);
  int current_long = 0, total_long = 0;
  qh_memfreeshort(qh, &current_long, &total_long);
  std::fclose(error_file);
  std::free(error_buffer);
  return exit_code == 0 && vertices.size() >= 4;
}

/** Unit directions without repeats (up to sign and 1e-9), in a fixed order. */
Points
distinctDirections(const Points& directions)
{
  std::set<std::tuple<long long, long long, long long>> seen;
  Points out;
  for (Eigen::Vector3d d : directions) {
    const double length = d.norm();
    if (!(length > 0.0) || !std::isfinite(length))
      continue;
    d /= length;
    const int lead = std::abs(d.x()) > 1e-9 ? 0 : (std::abs(d.y()) > 1e-9 ? 1 : 2);
    if (d[lead] < 0.0)
      d = -d;
    const auto key = std::make_tuple(std::llround(d.x() * 1e9), std::llround(d.y() * 1e9),
                                     std::llround(d.z() * 1e9));
    if (seen.insert(key).second)
      out.push_back(d);
  }
  return out;
}

Eigen::Matrix3d
pcaAxes(const Points& points)
{
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& p : points)
    mean += p;
  mean /= static_cast<double>(std::max<std::size_t>(points.size(), 1));
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  for (const Eigen::Vector3d& p : points)
    covariance += (p - mean) * (p - mean).transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(covariance);
  Eigen::Matrix3d axes = solver.eigenvectors().transpose();
  axes.row(2) = Eigen::Vector3d(axes.row(0)).cross(Eigen::Vector3d(axes.row(1)));
  return axes;
}

/** Descent over small rotations about the box's own axes: halves the step when no rotation
 * helps. The optimum is usually a corner of the hull's combinatorics, where a candidate of
 * computeMinimumVolumeBox already sits; this catches boxes resting on two hull edges. */
Eigen::Matrix3d
refineByRotation(const Points& points, Eigen::Matrix3d axes, double size)
{
  const double kPi = 3.14159265358979323846;
  BoxCost cost = boxCost(points, axes);
  for (double step = 2.0 * kPi / 180.0; step > 1e-3 * kPi / 180.0; step *= 0.5) {
    bool improved = true;
    for (int round = 0; improved && round < 50; ++round) {
      improved = false;
      for (int axis = 0; axis < 3; ++axis)
        for (const double sign : {1.0, -1.0}) {
          const Eigen::Matrix3d rotated =
              axes * Eigen::AngleAxisd(sign * step, Eigen::Vector3d::Unit(axis)).toRotationMatrix();
          const BoxCost c = boxCost(points, rotated);
          if (c.smallerThan(cost, size)) {
            cost = c;
            axes = rotated;
            improved = true;
          }
        }
    }
  }
  return axes;
}

/** Finite points only. */
Points
finitePoints(const Points& points)
{
  Points out;
  out.reserve(points.size());
  for (const Eigen::Vector3d& p : points)
    if (p.allFinite())
      out.push_back(p);
  return out;
}

/** Sorts the axes by decreasing extent, makes them right-handed and refits on all points. */
OrientedBox
canonicalBox(const Points& points, const Eigen::Matrix3d& axes)
{
  const OrientedBox fitted = fitBox(points, axes);
  int order[3] = {0, 1, 2};
  std::stable_sort(order, order + 3,
                   [&](int a, int b) { return fitted.extents[a] > fitted.extents[b]; });
  Eigen::Matrix3d sorted;
  for (int i = 0; i < 3; ++i)
    sorted.row(i) = axes.row(order[i]).normalized();
  sorted.row(2) = Eigen::Vector3d(sorted.row(0)).cross(Eigen::Vector3d(sorted.row(1))).normalized();
  return fitBox(points, sorted);
}

} // namespace

bool
OrientedBox::contains(const Eigen::Vector3d& p, double tolerance) const
{
  const Eigen::Vector3d t = axes * (p - center);
  return (t.cwiseAbs().array() <= 0.5 * extents.array() + tolerance).all();
}

std::array<Eigen::Vector3d, 8>
OrientedBox::corners() const
{
  std::array<Eigen::Vector3d, 8> out;
  for (int k = 0; k < 8; ++k) {
    Eigen::Vector3d p = center;
    for (int i = 0; i < 3; ++i)
      p += ((k >> i) & 1 ? 0.5 : -0.5) * extents[i] * Eigen::Vector3d(axes.row(i));
    out[k] = p;
  }
  return out;
}

TriangleMesh
OrientedBox::toMesh() const
{
  const std::array<Eigen::Vector3d, 8> c = corners();
  TriangleMesh mesh;
  mesh.vertices.assign(c.begin(), c.end());
  // Corner bits (x, y, z) = (1, 2, 4); quads listed counter-clockwise seen from outside for
  // right-handed axes.
  const int quads[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4},
                           {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
  for (const auto& q : quads) {
    mesh.faces.emplace_back(q[0], q[1], q[2]);
    mesh.faces.emplace_back(q[0], q[2], q[3]);
  }
  return mesh;
}

OrientedBox
computeAxisAlignedBox(const std::vector<Eigen::Vector3d>& points)
{
  return fitBox(finitePoints(points), Eigen::Matrix3d::Identity());
}

OrientedBox
computePcaBox(const std::vector<Eigen::Vector3d>& points)
{
  const Points finite = finitePoints(points);
  return canonicalBox(finite, pcaAxes(finite));
}

OrientedBox
computeMinimumVolumeBox(const std::vector<Eigen::Vector3d>& points)
{
  const Points finite = finitePoints(points);
  if (finite.empty())
    return OrientedBox();
  Points hull, directions, edges;
  if (!convexHull(finite, hull, directions, edges))
    hull = finite;
  // Candidates cost O(h log h) each and a hull has about 5h of them: a large hull proposes its
  // candidates from the hull of kMaxCandidateVertices spread-out hull vertices instead; the
  // rotation descent and the final fit then use the whole hull.
  Points candidate_hull = hull;
  if (hull.size() > kMaxCandidateVertices) {
    Points spread, spread_hull, spread_directions, spread_edges;
    for (const int i : thinPointsToCount(hull, kMaxCandidateVertices))
      spread.push_back(hull[i]);
    if (convexHull(spread, spread_hull, spread_directions, spread_edges)) {
      candidate_hull = std::move(spread_hull);
      directions = std::move(spread_directions);
      edges = std::move(spread_edges);
    }
  }
  const Eigen::Matrix3d pca = pcaAxes(finite);
  for (int i = 0; i < 3; ++i) {
    directions.push_back(pca.row(i).transpose());
    directions.push_back(Eigen::Vector3d::Unit(i));
  }
  // Edge directions; and for small hulls the normals of edge pairs, the axis shared by two box
  // faces each flush with one edge (O'Rourke's second case, e.g. a regular tetrahedron's cube).
  const Points edge_directions = distinctDirections(edges);
  directions.insert(directions.end(), edge_directions.begin(), edge_directions.end());
  if (edge_directions.size() <= kMaxEdgePairDirections)
    for (std::size_t i = 0; i < edge_directions.size(); ++i)
      for (std::size_t j = i + 1; j < edge_directions.size(); ++j)
        directions.push_back(edge_directions[i].cross(edge_directions[j]));
  // The axis-aligned box is the reference: a candidate replaces it only when strictly smaller.
  const double size = std::max(fitBox(finite, Eigen::Matrix3d::Identity()).extents.norm(), 1e-300);
  Eigen::Matrix3d best_axes = Eigen::Matrix3d::Identity();
  BoxCost best = boxCost(hull, best_axes);
  // Ranked on the candidate hull; the best kRecheckedCandidates are redone on the whole hull.
  std::vector<std::pair<BoxCost, Eigen::Vector3d>> ranked;
  for (const Eigen::Vector3d& n : distinctDirections(directions))
    ranked.emplace_back(boxCost(candidate_hull, boxAxesAround(candidate_hull, n)), n);
  const std::size_t rechecked = candidate_hull.size() < hull.size()
                                    ? std::min(ranked.size(), kRecheckedCandidates)
                                    : ranked.size();
  std::partial_sort(
    ranked.begin(), ranked.begin() + rechecked, ranked.end(), [size](const auto& a, const auto& b) {
      return a.first.smallerThan(b.first, size);
    });
  for (std::size_t i = 0; i < rechecked; ++i) {
    const Eigen::Matrix3d axes = boxAxesAround(hull, ranked[i].second);
    const BoxCost cost = boxCost(hull, axes);
    if (cost.smallerThan(best, size)) {
      best = cost;
      best_axes = axes;
    }
  }
  return canonicalBox(finite, refineByRotation(hull, best_axes, size));
}

TriangleMesh
boxesToMesh(const std::vector<OrientedBox>& boxes)
{
  TriangleMesh mesh;
  for (const OrientedBox& box : boxes) {
    const TriangleMesh one = box.toMesh();
    const int offset = static_cast<int>(mesh.vertices.size());
    mesh.vertices.insert(mesh.vertices.end(), one.vertices.begin(), one.vertices.end());
    for (const Eigen::Vector3i& f : one.faces)
      mesh.faces.push_back(f + Eigen::Vector3i::Constant(offset));
  }
  return mesh;
}

} // namespace segmat
