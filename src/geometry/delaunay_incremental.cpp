/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
// Incremental (Bowyer–Watson) 3D Delaunay tetrahedralisation with exact predicates.
//
// Points are snapped to a 2^22 integer grid over their bounding box; orientation and in-sphere
// determinants on such coordinates fit in 128-bit integers (in-sphere: 4 × 2^46·2^69 < 2^127), so
// every predicate is exact and the algorithm cannot fail on rounding. Exact degeneracies (e.g.
// co-spherical grid points) are resolved by the usual conventions: a tetrahedron conflicts with p
// only when p is strictly inside its circumsphere; a hull facet conflicts when p is strictly
// beyond it, or in its plane and strictly inside the circumsphere of the tetrahedron behind it.
// The cavity of strictly conflicting tetrahedra is star-shaped from p, so re-triangulating it
// never makes a flat tetrahedron. Insertion follows a biased randomised order (BRIO) of
// Morton-sorted rounds, and points are located by a visibility walk with a deterministic
// pseudo-random face order.
#include <segmat/geometry/delaunay_3d.h>

#include "point_bounds.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>

#ifdef __SIZEOF_INT128__

namespace segmat {
namespace {
using i64 = std::int64_t;
using i128 = __int128;
constexpr int kInfinite = -1;
constexpr int kBits = 22;

struct IPoint
{
  i64 x, y, z;
  bool
  operator==(const IPoint& o) const
  {
    return x == o.x && y == o.y && z == o.z;
  }
};

/** Sign of det[b−a; c−a; d−a]: positive for (0,0,0), (1,0,0), (0,1,0), (0,0,1). */
int
orient(const IPoint& a, const IPoint& b, const IPoint& c, const IPoint& d)
{
  const i64 bx = b.x - a.x, by = b.y - a.y, bz = b.z - a.z;
  const i64 cx = c.x - a.x, cy = c.y - a.y, cz = c.z - a.z;
  const i64 dx = d.x - a.x, dy = d.y - a.y, dz = d.z - a.z;
  const i128 det = static_cast<i128>(bx) * (cy * dz - cz * dy) -
                   static_cast<i128>(by) * (cx * dz - cz * dx) +
                   static_cast<i128>(bz) * (cx * dy - cy * dx);
  return (det > 0) - (det < 0);
}

/** Positive when e is strictly inside the circumsphere of positively oriented (a, b, c, d). */
int
insphere(const IPoint& a, const IPoint& b, const IPoint& c, const IPoint& d, const IPoint& e)
{
  const IPoint* p[4] = {&a, &b, &c, &d};
  i64 x[4], y[4], z[4], w[4];
  for (int i = 0; i < 4; ++i) {
    x[i] = p[i]->x - e.x;
    y[i] = p[i]->y - e.y;
    z[i] = p[i]->z - e.z;
    w[i] = x[i] * x[i] + y[i] * y[i] + z[i] * z[i];
  }
  // 2×2 minors of the x, y columns, then 3×3 minors with z, then the lifted column.
  auto m = [&](int i, int j) { return x[i] * y[j] - x[j] * y[i]; };
  auto d3 = [&](int i, int j, int k) {
    return static_cast<i128>(z[i]) * m(j, k) - static_cast<i128>(z[j]) * m(i, k) +
           static_cast<i128>(z[k]) * m(i, j);
  };
  const i128 det = -static_cast<i128>(w[0]) * d3(1, 2, 3) + static_cast<i128>(w[1]) * d3(0, 2, 3) -
                   static_cast<i128>(w[2]) * d3(0, 1, 3) + static_cast<i128>(w[3]) * d3(0, 1, 2);
  // det < 0 means inside for orient > 0 (worked out on the unit corner tetrahedron).
  return (det < 0) - (det > 0);
}

std::uint64_t
spreadBits(std::uint64_t v)
{
  v &= 0x1FFFFF;
  v = (v | v << 32) & 0x1F00000000FFFFull;
  v = (v | v << 16) & 0x1F0000FF0000FFull;
  v = (v | v << 8) & 0x100F00F00F00F00Full;
  v = (v | v << 4) & 0x10C30C30C30C30C3ull;
  v = (v | v << 2) & 0x1249249249249249ull;
  return v;
}

class Triangulation
{
public:
  struct Tet
  {
    int v[4];
    int n[4];
  };

  explicit Triangulation(const std::vector<IPoint>& points) : points_(points) {}

  bool
  build(const std::vector<int>& order, std::string& error);

  std::vector<Tet> tets;
  std::vector<char> alive;

private:
  bool
  isInfinite(int t) const
  {
    const int* v = tets[t].v;
    return v[0] == kInfinite || v[1] == kInfinite || v[2] == kInfinite || v[3] == kInfinite;
  }

  /** orient of tet t with corner i replaced by point p. */
  int
  orientWith(int t, int i, int p) const
  {
    const int* v = tets[t].v;
    const IPoint* q[4];
    for (int k = 0; k < 4; ++k)
      q[k] = &points_[k == i ? p : v[k]];
    return orient(*q[0], *q[1], *q[2], *q[3]);
  }

  bool
  inConflict(int t, int p) const
  {
    const Tet& tet = tets[t];
    for (int k = 0; k < 4; ++k)
      if (tet.v[k] == kInfinite) {
        const int o = orientWith(t, k, p);
        if (o != 0)
          return o > 0;
        // In the plane of the hull facet: conflict iff inside the circumsphere behind it.
        return inConflict(tet.n[k], p);
      }
    const int* v = tet.v;
    return insphere(points_[v[0]], points_[v[1]], points_[v[2]], points_[v[3]], points_[p]) > 0;
  }

  int
  newTet(const int v[4], const int n[4])
  {
    int id;
    if (!free_.empty()) {
      id = free_.back();
      free_.pop_back();
      alive[id] = 1;
    }
    else {
      id = static_cast<int>(tets.size());
      tets.emplace_back();
      alive.push_back(1);
    }
    std::copy(v, v + 4, tets[id].v);
    std::copy(n, n + 4, tets[id].n);
    return id;
  }

  int
  locate(int start, int p);

  bool
  insert(int p);

  std::uint32_t
  nextRandom()
  {
    random_ ^= random_ << 13;
    random_ ^= random_ >> 17;
    random_ ^= random_ << 5;
    return random_;
  }

  const std::vector<IPoint>& points_;
  std::vector<int> free_;
  std::vector<int> cavity_, boundary_tet_, boundary_face_, created_;
  std::vector<char> in_cavity_;
  std::vector<std::pair<std::uint64_t, int>> open_faces_; // hash table: cavity edge → (tet, face)
  std::uint32_t random_ = 2463534242u;
  int hint_ = 0;
};

int
Triangulation::locate(int start, int p)
{
  int t = start;
  if (isInfinite(t))
    for (int k = 0; k < 4; ++k)
      if (tets[t].v[k] == kInfinite)
        t = tets[t].n[k];
  for (std::size_t steps = 0; steps < 4 * tets.size() + 16; ++steps) {
    if (isInfinite(t))
      return t; // entered across a hull facet that p is strictly beyond: in conflict
    const int first = static_cast<int>(nextRandom() & 3);
    int next = -1;
    for (int k = 0; k < 4 && next < 0; ++k) {
      const int i = (first + k) & 3;
      if (orientWith(t, i, p) < 0)
        next = tets[t].n[i];
    }
    if (next < 0)
      return t; // p is inside t or on its boundary
    t = next;
  }
  return -1;
}

bool
Triangulation::insert(int p)
{
  const int start = locate(hint_, p);
  if (start < 0)
    return false;
  for (int k = 0; k < 4; ++k) {
    const int v = tets[start].v[k];
    if (v != kInfinite && points_[v] == points_[p])
      return true; // duplicate point: nothing to insert
  }
  if (!inConflict(start, p))
    return false; // cannot happen with exact predicates; refuse rather than corrupt
  // Cavity: every tetrahedron reachable through conflicting neighbours.
  cavity_.assign(1, start);
  in_cavity_[start] = 1;
  boundary_tet_.clear();
  boundary_face_.clear();
  for (std::size_t head = 0; head < cavity_.size(); ++head) {
    const int t = cavity_[head];
    for (int i = 0; i < 4; ++i) {
      const int u = tets[t].n[i];
      if (in_cavity_[u])
        continue;
      if (inConflict(u, p)) {
        in_cavity_[u] = 1;
        cavity_.push_back(u);
      }
      else {
        boundary_tet_.push_back(t);
        boundary_face_.push_back(i);
      }
    }
  }
  // One new tetrahedron per boundary facet: the old one with the far corner replaced by p, which
  // keeps its orientation because the cavity is star-shaped from p.
  created_.clear();
  // Faces through p are matched on their cavity edge in a small open-addressing table.
  std::size_t capacity = 16;
  while (capacity < 6 * boundary_tet_.size())
    capacity *= 2;
  open_faces_.assign(capacity, {~std::uint64_t(0), -1});
  for (std::size_t b = 0; b < boundary_tet_.size(); ++b) {
    const int t = boundary_tet_[b], i = boundary_face_[b];
    int v[4], n[4] = {-1, -1, -1, -1};
    std::copy(tets[t].v, tets[t].v + 4, v);
    v[i] = p;
    const int outside = tets[t].n[i];
    n[i] = outside;
    const int id = newTet(v, n);
    if (in_cavity_.size() < tets.size())
      in_cavity_.resize(tets.size(), 0);
    for (int k = 0; k < 4; ++k)
      if (tets[outside].n[k] == t) {
        tets[outside].n[k] = id;
        break;
      }
    created_.push_back(id);
    // The faces through p: face opposite corner j ≠ i is shared with the new tetrahedron on the
    // other side of cavity edge {v[k], v[l]}; match on that unordered pair.
    for (int j = 0; j < 4; ++j) {
      if (j == i)
        continue;
      int a = -2, c = -2;
      for (int k = 0; k < 4; ++k)
        if (k != i && k != j)
          (a == -2 ? a : c) = v[k];
      const std::uint64_t key =
          (static_cast<std::uint64_t>(static_cast<std::uint32_t>(std::min(a, c))) << 32) |
          static_cast<std::uint32_t>(std::max(a, c));
      std::size_t slot = static_cast<std::size_t>((key * 0x9E3779B97F4A7C15ull) >> 40) & (capacity - 1);
      while (open_faces_[slot].first != key && open_faces_[slot].first != ~std::uint64_t(0))
        slot = (slot + 1) & (capacity - 1);
      if (open_faces_[slot].first == key) {
        const int other = open_faces_[slot].second >> 2, face = open_faces_[slot].second & 3;
        tets[id].n[j] = other;
        tets[other].n[face] = id;
      }
      else
        open_faces_[slot] = {key, (id << 2) | j};
    }
  }
  for (int t : cavity_) {
    in_cavity_[t] = 0;
    alive[t] = 0;
    free_.push_back(t);
  }
  hint_ = created_.back();
  return true;
}

bool
Triangulation::build(const std::vector<int>& order, std::string& error)
{
  // First tetrahedron: four affinely independent points, exactly.
  const int n = static_cast<int>(order.size());
  int corner[4] = {order.empty() ? -1 : order[0], -1, -1, -1};
  int used[4] = {0, -1, -1, -1};
  for (int i = 1; i < n && corner[1] < 0; ++i)
    if (!(points_[order[i]] == points_[corner[0]]))
      corner[1] = order[i], used[1] = i;
  for (int i = 1; i < n && corner[1] >= 0 && corner[2] < 0; ++i) {
    const IPoint &a = points_[corner[0]], &b = points_[corner[1]], &c = points_[order[i]];
    const i128 ux = b.x - a.x, uy = b.y - a.y, uz = b.z - a.z;
    const i128 vx = c.x - a.x, vy = c.y - a.y, vz = c.z - a.z;
    if (uy * vz - uz * vy != 0 || uz * vx - ux * vz != 0 || ux * vy - uy * vx != 0)
      corner[2] = order[i], used[2] = i;
  }
  for (int i = 1; i < n && corner[2] >= 0 && corner[3] < 0; ++i)
    if (orient(points_[corner[0]], points_[corner[1]], points_[corner[2]], points_[order[i]]) != 0)
      corner[3] = order[i], used[3] = i;
  if (corner[3] < 0) {
    error = "all points are coplanar (or fewer than 4 distinct points)";
    return false;
  }
  if (orient(points_[corner[0]], points_[corner[1]], points_[corner[2]], points_[corner[3]]) < 0)
    std::swap(corner[0], corner[1]);
  tets.reserve(7 * static_cast<std::size_t>(n) + 16);
  alive.reserve(tets.capacity());
  const int none[4] = {-1, -1, -1, -1};
  const int finite = newTet(corner, none);
  int hull[4];
  for (int i = 0; i < 4; ++i) {
    // Facet opposite corner i seen from outside: corner i becomes the infinite vertex, and two
    // other corners swap so that the infinite vertex lies on the outer side.
    int v[4];
    std::copy(corner, corner + 4, v);
    v[i] = kInfinite;
    const int j = (i + 1) & 3, k = (i + 2) & 3;
    std::swap(v[j], v[k]);
    hull[i] = newTet(v, none);
    tets[hull[i]].n[i] = finite;
    tets[finite].n[i] = hull[i];
  }
  // Hull tetrahedra i and m share the infinite vertex and the two corners other than i and m.
  for (int i = 0; i < 4; ++i)
    for (int m = 0; m < 4; ++m)
      if (m != i) {
        // In hull[i], corner m (finite) sits at position m unless it was swapped.
        const int j = (i + 1) & 3, k = (i + 2) & 3;
        const int position = m == j ? k : (m == k ? j : m);
        tets[hull[i]].n[position] = hull[m];
      }
  in_cavity_.assign(tets.size(), 0);
  hint_ = finite;
  for (int i = 0; i < n; ++i) {
    if (i == used[0] || i == used[1] || i == used[2] || i == used[3])
      continue;
    if (in_cavity_.size() < tets.size())
      in_cavity_.resize(tets.capacity(), 0);
    if (!insert(order[i])) {
      error = "point location failed";
      return false;
    }
  }
  return true;
}
} // namespace

bool
delaunayTetrahedralizeExact(const std::vector<Eigen::Vector3d>& points, DelaunayTetrahedra& output,
                            std::string& error_message)
{
  if (!detail::startDelaunay(points, output, error_message))
    return false;
  const int n = static_cast<int>(points.size());
  const Eigen::AlignedBox3d box = detail::finiteBounds(points);
  const Eigen::Vector3d lo = box.min();
  const double extent = box.sizes().maxCoeff();
  if (!(extent > 0.0)) {
    error_message = "all points are equal";
    return false;
  }
  const double cells = static_cast<double>((i64(1) << kBits) - 1);
  const double scale = extent / cells;
  std::vector<IPoint> grid(n);
  output.points.resize(n);
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector3d q = ((points[i] - lo) / scale).array().round();
    grid[i] = {static_cast<i64>(q.x()), static_cast<i64>(q.y()), static_cast<i64>(q.z())};
    output.points[i] = lo + scale * q;
  }
  // Biased randomised insertion order (BRIO, Amenta, Choi, Rote 2003): a pseudo-random half of
  // the points goes last, a quarter before it, and so on; each round in Morton order, so that
  // consecutive insertions are close and cavities stay small. The "randomness" is a hash of the
  // index: the order, and so the output, is deterministic.
  std::vector<std::uint64_t> key(n);
  std::vector<int> round(n);
  for (int i = 0; i < n; ++i) {
    key[i] = spreadBits(static_cast<std::uint64_t>(grid[i].x) >> 1) << 2 |
             spreadBits(static_cast<std::uint64_t>(grid[i].y) >> 1) << 1 |
             spreadBits(static_cast<std::uint64_t>(grid[i].z) >> 1);
    std::uint64_t h = static_cast<std::uint64_t>(i) * 0x9E3779B97F4A7C15ull;
    h = (h ^ (h >> 30)) * 0xBF58476D1CE4E5B9ull;
    h = (h ^ (h >> 27)) * 0x94D049BB133111EBull;
    h ^= h >> 31;
    // Round r (0 = last) holds about n / 2^(r+1) points; the first rounds are merged until
    // they hold some 64 points.
    int r = 0;
    while (r < 62 && (h >> (63 - r) & 1) == 0)
      ++r;
    const int max_round = std::max(0, static_cast<int>(std::log2(std::max(n, 64) / 64.0)));
    round[i] = std::min(r, max_round);
  }
  std::vector<int> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int a, int b) {
    if (round[a] != round[b])
      return round[a] > round[b];
    return key[a] < key[b] || (key[a] == key[b] && a < b);
  });

  Triangulation dt(grid);
  if (!dt.build(order, error_message)) {
    output = DelaunayTetrahedra();
    return false;
  }
  // Finite tetrahedra, numbered in storage order; infinite neighbours become -1.
  std::vector<int> index(dt.tets.size(), -1);
  for (std::size_t t = 0; t < dt.tets.size(); ++t) {
    if (!dt.alive[t])
      continue;
    const auto& v = dt.tets[t].v;
    if (v[0] == kInfinite || v[1] == kInfinite || v[2] == kInfinite || v[3] == kInfinite)
      continue;
    index[t] = static_cast<int>(output.tetrahedra.size());
    output.tetrahedra.emplace_back(v[0], v[1], v[2], v[3]);
  }
  output.neighbors.resize(output.tetrahedra.size());
  for (std::size_t t = 0; t < dt.tets.size(); ++t)
    if (index[t] >= 0)
      for (int k = 0; k < 4; ++k)
        output.neighbors[index[t]][k] = index[dt.tets[t].n[k]];
  return true;
}

} // namespace segmat

#else // no 128-bit integers (e.g. MSVC): callers fall back to qhull

namespace segmat {
bool
delaunayTetrahedralizeExact(const std::vector<Eigen::Vector3d>& points, DelaunayTetrahedra& output,
                            std::string& error_message)
{
  if (detail::startDelaunay(points, output, error_message))
    error_message = "the exact Delaunay code needs a compiler with 128-bit integers";
  return false;
}
} // namespace segmat

#endif
