/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
// The edge collapser's construction, costs, collapses, queue loop and output; the topology tests
// are in qmat_edge_collapser_topology.cpp.
#include "qmat_edge_collapser.h"

#include <segmat/geometry/cone_tangent_plane.h>
#include <segmat/geometry/medial_primitives.h>
#include <segmat/geometry/winding_number.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

#include "../common/thread_count.h"

namespace segmat {
namespace qmat {
namespace {

constexpr double kHalfPi = 1.57079632679489661923;

} // namespace

EdgeCollapser::EdgeCollapser(const MedialMesh& mat, const Eigen::Vector3d& origin, double scale,
                             const Settings& settings, const WindingNumber* inside)
: settings_(settings), origin_(origin), scale_(scale), inside_(inside)
{
  const int n_in = static_cast<int>(mat.numVertices());
  // Isolated spheres cannot collapse; Q-MAT drops them (CleanIsolatedVertices).
  std::vector<int> kept;
  for (int v = 0; v < n_in; ++v)
    if (!mat.vertexEdges(v).empty())
      kept.push_back(v);
  const int n = static_cast<int>(kept.size());
  alive_count_ = static_cast<std::size_t>(n);

  // Internal order: breadth-first along the edges (as reverse Cuthill–McKee orders a sparse
  // matrix), so that a collapse's neighbourhood is close in memory; about 10 % faster on Voronoi
  // MATs, whose own order is that of the tetrahedra. Ties and the output keep the input order
  // (output_rank_).
  std::vector<int> kept_index(n_in, -1);
  for (int i = 0; i < n; ++i)
    kept_index[kept[i]] = i;
  std::vector<int> order;
  order.reserve(n);
  std::vector<char> seen(n, 0);
  for (int start = 0; start < n; ++start) {
    if (seen[start])
      continue;
    seen[start] = 1;
    std::size_t tail = order.size();
    order.push_back(start);
    for (; tail < order.size(); ++tail) {
      const int v = kept[order[tail]];
      for (int e : mat.vertexEdges(v)) {
        const int k = kept_index[mat.edges()[e][0] == v ? mat.edges()[e][1] : mat.edges()[e][0]];
        if (!seen[k]) {
          seen[k] = 1;
          order.push_back(k);
        }
      }
    }
  }
  std::vector<int> to_internal(n_in, -1);
  for (int i = 0; i < n; ++i)
    to_internal[kept[order[i]]] = i;

  // A merged sphere reuses a slot, so n slots hold every sphere there will be, and a merge stays
  // near its neighbours in memory: appending merges at the end scattered the late collapses'
  // neighbourhoods, whose evaluations then waited on cache misses.
  num_kept_ = n;
  sphere_.reserve(n);
  q_.reserve(n);
  v_alive_.reserve(n);
  v_edges_.reserve(n);
  v_faces_.reserve(n);
  mark_.assign(n, 0);
  edge_to_.assign(n, -1);
  output_rank_.resize(n);
  for (int i = 0; i < n; ++i) {
    const int v = kept[order[i]];
    Eigen::Vector4d s;
    s.head<3>() = (mat.centers()[v] - origin_) / scale_;
    s[3] = mat.radii()[v] / scale_;
    sphere_.push_back(s);
    v_alive_.push_back(1);
    output_rank_[i] = order[i];
  }
  q_.resize(n);
  v_edges_.resize(n);
  v_faces_.resize(n);
  for (int i = 0; i < n; ++i) { // exact sizes: one allocation per list, no regrowth
    v_edges_[i].reserve(mat.vertexEdges(kept[order[i]]).size());
    v_faces_[i].reserve(mat.vertexTriangles(kept[order[i]]).size());
  }

  // Edges and triangles in the order of their smallest internal corner, for the same reason.
  // Ids sorted by (ascending corner triple, id). Corners lie in [-1, n), so three stable
  // counting-sort passes (last corner first) give that order in O(count + n), where a
  // comparison sort of the triples was a visible share of the set-up.
  auto sortedBySmallestCorner = [n](std::size_t count, auto corners) {
    std::vector<std::array<int, 3>> sorted(count);
    for (std::size_t i = 0; i < count; ++i) {
      sorted[i] = corners(i);
      std::sort(sorted[i].begin(), sorted[i].end());
    }
    std::vector<int> ids(count), next(count);
    for (std::size_t i = 0; i < count; ++i)
      ids[i] = static_cast<int>(i);
    std::vector<std::size_t> start(static_cast<std::size_t>(n) + 2);
    for (int k = 2; k >= 0; --k) {
      std::fill(start.begin(), start.end(), 0);
      for (std::size_t i = 0; i < count; ++i)
        ++start[sorted[i][k] + 2]; // bucket of corner c starts at start[c + 1]
      for (std::size_t c = 1; c < start.size(); ++c)
        start[c] += start[c - 1];
      for (int id : ids)
        next[start[sorted[id][k] + 1]++] = id;
      ids.swap(next);
    }
    return ids;
  };
  e_orig_ = sortedBySmallestCorner(mat.numEdges(), [&](std::size_t e) {
    return std::array<int, 3>{to_internal[mat.edges()[e][0]], to_internal[mat.edges()[e][1]], -1};
  });
  e_v_.reserve(mat.numEdges());
  for (int orig : e_orig_) {
    const int id = static_cast<int>(e_v_.size());
    const int a = to_internal[mat.edges()[orig][0]], b = to_internal[mat.edges()[orig][1]];
    e_v_.push_back({a, b});
    v_edges_[a].push_back(id);
    v_edges_[b].push_back(id);
  }
  e_alive_.assign(e_v_.size(), 1);
  e_state_.assign(e_v_.size(), EdgeState());
  e_target_.resize(e_v_.size());
  v_touched_.assign(n, 0);

  f_orig_ = sortedBySmallestCorner(mat.numTriangles(), [&](std::size_t f) {
    const Eigen::Vector3i& t = mat.triangles()[f];
    return std::array<int, 3>{to_internal[t[0]], to_internal[t[1]], to_internal[t[2]]};
  });
  f_v_.reserve(mat.numTriangles());
  for (int orig : f_orig_) {
    const int id = static_cast<int>(f_v_.size());
    const Eigen::Vector3i& t = mat.triangles()[orig];
    f_v_.push_back({to_internal[t[0]], to_internal[t[1]], to_internal[t[2]]});
    for (int k = 0; k < 3; ++k)
      v_faces_[to_internal[t[k]]].push_back(id);
  }
  f_alive_.assign(f_v_.size(), 1);
  for (std::size_t e = 0; e < e_v_.size(); ++e)
    e_state_[e].has_faces = !mat.isPureEdge(e_orig_[e]);
  f_normal_.resize(f_v_.size());
  for (std::size_t f = 0; f < f_v_.size(); ++f)
    f_normal_[f] = faceNormal(static_cast<int>(f));

  buildQuadrics();

  // Every edge's first cost; independent per edge, so threads cannot change the result. Only
  // the keys are buffered (the rest goes straight to the per-edge arrays): a full CollapseChoice
  // per edge was megabytes of fresh pages to fault in.
  const int num_edges = static_cast<int>(e_v_.size());
  std::vector<QueueKey> first_key(num_edges);
  [[maybe_unused]] const int threads = detail::threadCount(settings_.threads);
#pragma omp parallel for schedule(static) num_threads(threads)
  for (int e = 0; e < num_edges; ++e) {
    const CollapseChoice c = evaluate(e, false);
    first_key[e] = keyOf(e, c);
    e_target_[e] = c.sphere;
    e_state_[e].blockers = c.blockers;
    e_state_[e].bound = c.bound;
  }
  heap_.build(first_key);
}

Eigen::Vector3d
EdgeCollapser::faceNormal(int f) const
{
  const auto& t = f_v_[f];
  const Eigen::Vector3d e1 = sphere_[t[1]].head<3>() - sphere_[t[0]].head<3>();
  const Eigen::Vector3d e2 = sphere_[t[2]].head<3>() - sphere_[t[0]].head<3>();
  const Eigen::Vector3d n = e1.cross(e2);
  // A (nearly) degenerate triangle has no orientation to lose: zero disables its flip test.
  return n.squaredNorm() > 1e-14 * e1.squaredNorm() * e2.squaredNorm() ? n
                                                                          : Eigen::Vector3d::Zero();
}

void
EdgeCollapser::buildQuadrics()
{
  // Slab sides: both tangent planes of every triangle, weight 1, on all three corners.
  for (std::size_t f = 0; f < f_v_.size(); ++f) {
    const auto& t = f_v_[f];
    const Eigen::Vector3d c[3] = {sphere_[t[0]].head<3>(), sphere_[t[1]].head<3>(),
                                  sphere_[t[2]].head<3>()};
    const double r[3] = {sphere_[t[0]][3], sphere_[t[1]][3], sphere_[t[2]][3]};
    SlabSides sides;
    if (!computeSlabSides(c, r, f_normal_[f], sides))
      continue;
    // Both planes touch all three spheres, so any corner defines them.
    const SphereQuadric q = SphereQuadric::fromPlane(sides.normal[0], sphere_[t[0]]) +
                            SphereQuadric::fromPlane(sides.normal[1], sphere_[t[0]]);
    for (int k = 0; k < 3; ++k)
      q_[t[k]].face += q;
  }
  for (Quadrics& q : q_)
    q.all = q.face;

  // Q-MAT "PreservBoundaryMethodFour" (§8.3): weight bound_weight · 0.1 · ratio².
  for (std::size_t ue = 0; ue < e_v_.size(); ++ue) {
    const int e = static_cast<int>(ue);
    const int a = e_v_[e][0], b = e_v_[e][1];
    int tri_count = 0;
    for (int f : v_faces_[a])
      tri_count += hasVertex(f, b);
    if (tri_count > 1)
      continue;
    const Eigen::Vector4d& sa = sphere_[a];
    const Eigen::Vector4d& sb = sphere_[b];
    const double ratio = stabilityRatio(sa, sb);
    const double w = settings_.boundary_weight * 0.1 * ratio * ratio;
    const Eigen::Vector3d ab = sa.head<3>() - sb.head<3>();
    if (tri_count == 1) {
      // Sheet border: the plane through the edge perpendicular to the sheet, pointing away from
      // the triangle's third corner. Its normal is deliberately not unit (length = edge length),
      // as in the published code.
      int third = -1;
      Eigen::Vector3d face_normal = Eigen::Vector3d::Zero();
      for (int f : v_faces_[a]) {
        if (!hasVertex(f, b))
          continue;
        const auto& t = f_v_[f];
        third = t[0] != a && t[0] != b ? t[0] : (t[1] != a && t[1] != b ? t[1] : t[2]);
        face_normal = (sphere_[t[1]].head<3>() - sphere_[t[0]].head<3>())
                          .cross(sphere_[t[2]].head<3>() - sphere_[t[0]].head<3>());
        break;
      }
      const double len = face_normal.norm();
      if (third < 0 || !(len > 0.0))
        continue;
      Eigen::Vector3d t = (face_normal / len).cross(ab);
      if (t.dot(sphere_[third].head<3>() - sa.head<3>()) > 0.0)
        t = -t;
      q_[a].all += SphereQuadric::fromPlane(t, sa, w);
      q_[b].all += SphereQuadric::fromPlane(t, sb, w);
      continue;
    }
    // Pure edge (a medial cone). The published code took the tangent planes of the spheres a, b
    // and (c_a + c_b, (r_a + r_b)/2) — a sum where the midpoint was meant, so the planes depended
    // on the origin. With the midpoint the three spheres are collinear and every plane tangent
    // to the cone qualifies; four planes 90° apart, weight ½ each (the published code used two,
    // weight 1), give the rotation-symmetric quadric whatever the first plane's angle. Each comes
    // with its companion plane of normal (c_a − c_b) × n, as in the published code.
    for (int i = 0; i < 4; ++i) {
      Eigen::Vector3d n;
      if (!coneTangentPlane(sa, sb, i * kHalfPi, n))
        break;
      const Eigen::Vector3d companion = ab.cross(n);
      for (int v : {a, b}) {
        q_[v].all += SphereQuadric::fromPlane(n, sphere_[v], 0.5);
        q_[v].all += SphereQuadric::fromPlane(companion, sphere_[v], 0.5);
      }
    }
    // Branch tips (a sphere with this one edge) are held by a plane across the axis.
    if (v_edges_[a].size() == 1)
      q_[a].all += SphereQuadric::fromPlane(ab, sa, w);
    if (v_edges_[b].size() == 1)
      q_[b].all += SphereQuadric::fromPlane(-ab, sb, w);
  }
}

CollapseChoice
EdgeCollapser::evaluate(int e, bool check_flips) const
{
  const int a = e_v_[e][0], b = e_v_[e][1];
  const Eigen::Vector4d& sa = sphere_[a];
  const Eigen::Vector4d& sb = sphere_[b];
  const SphereQuadric q = q_[a].all + q_[b].all;

  // Triangles that survive the collapse, each as a half-space test: moving the corner v of a
  // triangle (v, q1, q2) to x flips it iff (q1 − x)·w < 0 with w = (q2 − q1) × n, n its normal.
  // Making it (nearly) degenerate counts as a flip — new sin(angle at q1)² <= 1e-14, the same
  // test as faceNormal(): a degenerate triangle has no orientation left to protect, and later
  // collapses would fold it over unnoticed.
  struct FlipTest
  {
    Eigen::Vector3d q1;
    Eigen::Vector3d w;
    double w_norm2;
    int face;
  };
  // Most vertices carry a few dozen triangles; a rare hub spills to the heap.
  constexpr std::size_t kInline = 64;
  FlipTest inline_tests[kInline];
  std::vector<FlipTest> spilled;
  std::size_t num_tests = 0;
  auto addTest = [&](const FlipTest& t) {
    if (num_tests < kInline)
      inline_tests[num_tests] = t;
    else {
      if (spilled.empty())
        spilled.assign(inline_tests, inline_tests + kInline);
      spilled.push_back(t);
    }
    ++num_tests;
  };
  // A triangle on ab (it disappears with the collapse). Kept per edge: scanning a's triangles
  // for it was a cache miss per triangle on the most frequent call (every edge of a merged
  // sphere, after every collapse).
  const bool has_faces = e_state_[e].has_faces;
  if (check_flips && settings_.prevent_inversion) {
    for (int v : {a, b})
      for (int f : v_faces_[v]) {
        const auto& t = f_v_[f];
        const int k = t[0] == v ? 0 : (t[1] == v ? 1 : 2);
        const int q1 = t[(k + 1) % 3], q2 = t[(k + 2) % 3];
        if (q1 == a || q1 == b || q2 == a || q2 == b || f_normal_[f].isZero())
          continue;
        const Eigen::Vector3d p1 = sphere_[q1].head<3>();
        const Eigen::Vector3d w = (sphere_[q2].head<3>() - p1).cross(f_normal_[f]);
        addTest({p1, w, w.squaredNorm(), f});
      }
  }
  // The first triangle that m would flip, or -1.
  const FlipTest* tests = spilled.empty() ? inline_tests : spilled.data();
  auto flipped = [&](const Eigen::Vector4d& m) {
    const Eigen::Vector3d x = m.head<3>();
    for (std::size_t i = 0; i < num_tests; ++i) {
      const FlipTest& ft = tests[i];
      const Eigen::Vector3d d = ft.q1 - x;
      const double side = d.dot(ft.w);
      if (side <= 0.0 || side * side <= 1e-14 * ft.w_norm2 * d.squaredNorm())
        return ft.face;
    }
    return -1;
  };

  const Eigen::Vector4d mid = 0.5 * (sa + sb);
  const Eigen::Vector4d* fallback[3] = {&sa, &sb, &mid};
  const std::uint8_t fallback_id[3] = {kFirstEnd, kSecondEnd, kMidpoint};
  // A midpoint found outside the surface is no candidate (the ends are inside by induction).
  const int num_fallbacks = (e_state_[e].outside & kMidpointOutside) ? 2 : 3;
  double fallback_cost[3] = {-1.0, -1.0, -1.0}; // filled when needed
  auto fillFallbackCosts = [&] {
    if (fallback_cost[0] < 0.0)
      for (int i = 0; i < 3; ++i)
        fallback_cost[i] = std::max(0.0, q(*fallback[i]));
  };
  auto takeFallback = [&](CollapseChoice& c, int i) {
    c.sphere = *fallback[i];
    c.cost = fallback_cost[i];
    c.candidate = fallback_id[i];
  };
  auto cheapestFallback = [&] {
    fillFallbackCosts();
    int best = 0;
    for (int i = 1; i < num_fallbacks; ++i)
      if (fallback_cost[i] < fallback_cost[best])
        best = i;
    return best;
  };

  CollapseChoice choice;
  if (!has_faces || (q_[a].face + q_[b].face).invertible()) {
    // §8.4 case 1: the optimal sphere m* = A⁻¹b; the midpoint when singular or r < 0 (or, with
    // a surface, outside it).
    if ((e_state_[e].outside & kOptimumOutside) || !q.minimiser(choice.sphere) ||
        !(choice.sphere[3] >= 0.0)) {
      if (num_fallbacks == 3) {
        choice.sphere = mid;
        choice.candidate = kMidpoint;
      }
      else
        takeFallback(choice, cheapestFallback());
    }
    choice.cost = q(choice.sphere);
  }
  else {
    // §8.4 case 2 (flat or degenerate slabs): the cheapest of the endpoints and the midpoint,
    // scored with the border terms (the published code dropped them here).
    takeFallback(choice, cheapestFallback());
  }

  const double ratio = stabilityRatio(sa, sb);
  choice.bound = (std::max(0.0, choice.cost) + settings_.k) * ratio * ratio;
  if (num_tests > 0 && (choice.blockers[0] = flipped(choice.sphere)) >= 0) {
    // The intended rule (the published code inverted it, §8.4): the cheapest candidate that
    // flips nothing, else keep m* but defer the collapse to the penalty tier.
    fillFallbackCosts();
    int order[3] = {0, 1, 2};
    std::stable_sort(order, order + num_fallbacks,
                     [&](int i, int j) { return fallback_cost[i] < fallback_cost[j]; });
    bool found = false;
    for (int k = 0; k < num_fallbacks && !found; ++k) {
      const int i = order[k];
      choice.blockers[k + 1] = flipped(*fallback[i]);
      if (choice.blockers[k + 1] < 0) {
        takeFallback(choice, i);
        found = true;
      }
    }
    if (!found)
      choice.tier = 1;
  }
  choice.cost = (std::max(0.0, choice.cost) + settings_.k) * ratio * ratio;
  return choice;
}

bool
EdgeCollapser::insideSurface(int from, const Eigen::Vector4d& sphere) const
{
  // Sphere centres are inside (the input's by assumption, merged ones by this test), so for a
  // closed surface counting the faces crossed on the way from one is enough: O(log F).
  const Eigen::Vector3d start = sphere_[from].head<3>() * scale_ + origin_;
  const Eigen::Vector3d end = sphere.head<3>() * scale_ + origin_;
  int change = 0;
  if (inside_->windingNumberChange(start, end, change))
    return 1 + change > 0;
  return inside_->inside(end);
}

void
EdgeCollapser::removeFrom(std::vector<int>& list, int value)
{
  auto it = std::find(list.begin(), list.end(), value);
  if (it != list.end()) {
    *it = list.back();
    list.pop_back();
  }
}

std::vector<int>
EdgeCollapser::recycledList()
{
  if (spare_lists_.empty())
    return {};
  std::vector<int> list = std::move(spare_lists_.back());
  spare_lists_.pop_back();
  return list;
}

void
EdgeCollapser::recycleList(std::vector<int>& list)
{
  constexpr std::size_t kMaxSpareLists = 64;
  if (spare_lists_.size() < kMaxSpareLists && list.capacity() > 0) {
    list.clear();
    spare_lists_.push_back(std::move(list));
  }
  std::vector<int>().swap(list); // dead vertices hold no memory
}

void
EdgeCollapser::collapse(int e, const Eigen::Vector4d& target)
{
  const int a = e_v_[e][0], b = e_v_[e][1];
  const int m = a; // the merged sphere's slot (see the class comment)
  sphere_[m] = target; // the re-pointed triangles' normals below need it
  const Quadrics merged_q{q_[a].face + q_[b].face, q_[a].all + q_[b].all};
  // m's lists are built beside a's (which the loops below still read), then take their place.
  std::vector<int> m_faces = recycledList();
  std::vector<int> m_edges = recycledList();
  m_faces.reserve(v_faces_[a].size() + v_faces_[b].size());
  m_edges.reserve(v_edges_[a].size() + v_edges_[b].size());

  // Triangles: those on ab vanish, the others are re-pointed to m. Two of them become one only
  // when axy and bxy both exist (a cavity closing, see linkCondition); both x and y are then
  // neighbours of a, marked here.
  ++stamp_;
  for (int ea : v_edges_[a])
    mark_[other(ea, a)] = stamp_;
  const std::size_t faces_from_a = [&] {
    std::size_t count = 0;
    for (int f : v_faces_[a])
      count += f_alive_[f] && !hasVertex(f, b);
    return count;
  }();
  for (int v : {a, b})
    for (int f : v_faces_[v]) {
      if (!f_alive_[f])
        continue;
      auto& t = f_v_[f];
      if (hasVertex(f, a) && hasVertex(f, b)) {
        f_alive_[f] = 0;
        const int third = t[0] != a && t[0] != b ? t[0] : (t[1] != a && t[1] != b ? t[1] : t[2]);
        removeFrom(v_faces_[third], f);
        continue;
      }
      const int k_v = t[0] == v ? 0 : (t[1] == v ? 1 : 2);
      const int x = t[(k_v + 1) % 3], y = t[(k_v + 2) % 3];
      if (v == b && mark_[x] == stamp_ && mark_[y] == stamp_) {
        bool duplicate = false;
        for (std::size_t i = 0; i < faces_from_a && !duplicate; ++i)
          duplicate = hasVertex(m_faces[i], x) && hasVertex(m_faces[i], y);
        if (duplicate) {
          f_alive_[f] = 0;
          removeFrom(v_faces_[x], f);
          removeFrom(v_faces_[y], f);
          continue;
        }
      }
      t[k_v] = m;
      f_normal_[f] = faceNormal(f);
      m_faces.push_back(f);
    }

  // Edges: ab vanishes; ax and bx for a common neighbour x become one edge mx.
  ++stamp_;
  e_alive_[e] = 0;
  for (int v : {a, b})
    for (int e2 : v_edges_[v]) {
      if (!e_alive_[e2])
        continue;
      const int x = other(e2, v);
      if (mark_[x] == stamp_) {
        e_alive_[e2] = 0;
        heap_.erase(e2);
        removeFrom(v_edges_[x], e2);
        continue;
      }
      mark_[x] = stamp_;
      e_v_[e2] = {x, m};
      e_state_[e2].blocked = 0;
      e_state_[e2].outside = 0;
      m_edges.push_back(e2);
    }

  v_alive_[b] = 0;
  for (std::vector<int>* list : {&v_edges_[a], &v_edges_[b], &v_faces_[a], &v_faces_[b]})
    recycleList(*list);
  v_faces_[m] = std::move(m_faces);
  v_edges_[m] = std::move(m_edges);
  q_[m] = merged_q;
  // Only m's edges can gain or lose a triangle (a killed duplicate bxy leaves mxy on xy).
  ++stamp_;
  for (int e2 : v_edges_[m]) {
    const int x = other(e2, m);
    mark_[x] = stamp_;
    edge_to_[x] = e2;
    e_state_[e2].has_faces = 0;
  }
  for (int f : v_faces_[m]) {
    const auto& t = f_v_[f];
    for (int x : t)
      if (x != m && mark_[x] == stamp_)
        e_state_[edge_to_[x]].has_faces = 1;
  }
  // Merges follow the survivors in the output, in merge order.
  output_rank_[m] = num_kept_ + static_cast<int>(collapses_);
  --alive_count_;
  ++collapses_;

  // Every triangle around a neighbour of m may have changed: their edges' keys are stale.
  v_touched_[m] = collapses_;
  for (int e2 : v_edges_[m])
    v_touched_[other(e2, m)] = collapses_;
  for (int e2 : v_edges_[m])
    pushBound(e2);
  // Around m: blocked edges get another chance (their link may have changed). Every other key
  // there is stale (its triangles changed: v_touched_) and re-validated when it reaches the top.
  // That is exact for keys that can only have risen (an edge's preferred sphere depends on its
  // own quadrics alone). A key that may have dropped — a triangle that made a cheaper
  // candidate flip has changed — is lowered to its bound (the cost were nothing to flip), so it
  // cannot reach the top too late.
  auto changed = [&](int f) { return f >= 0 && (!f_alive_[f] || hasVertex(f, m)); };
  // The two-ring is gathered first, each record prefetched, so that its cache misses overlap
  // instead of following one another (they were most of this loop's time). Same order.
  std::vector<int>& ring = scratch_; // linkCondition()'s buffer, free here
  ring.clear();
  for (int e2 : v_edges_[m]) {
    const int x = other(e2, m);
    for (int e3 : v_edges_[x]) {
#if defined(__GNUC__)
      __builtin_prefetch(&e_state_[e3]);
#endif
      ring.push_back(e3);
    }
  }
  for (int e3 : ring) {
    if (e_state_[e3].evaluated == static_cast<std::uint32_t>(collapses_))
      continue; // just evaluated
    if (e_state_[e3].blocked) {
      e_state_[e3].blocked = 0;
      pushBound(e3);
      continue;
    }
    const auto& bl = e_state_[e3].blockers;
    if (changed(bl[0]) || changed(bl[1]) || changed(bl[2]) || changed(bl[3])) {
      const int ra = output_rank_[e_v_[e3][0]], rb = output_rank_[e_v_[e3][1]];
      heap_.set(e3, {e_state_[e3].bound, std::min(ra, rb), std::max(ra, rb), 0});
      e_state_[e3].blockers = {-1, -1, -1, -1};
      e_state_[e3].verified = 0;
    }
  }
}

void
EdgeCollapser::push(int e)
{
  const CollapseChoice c = evaluate(e);
  heap_.set(e, keyOf(e, c));
  e_target_[e] = c.sphere;
  e_state_[e].candidate = c.candidate;
  e_state_[e].blockers = c.blockers;
  e_state_[e].bound = c.bound;
  e_state_[e].verified = 1;
  e_state_[e].evaluated = static_cast<std::uint32_t>(collapses_);
}

void
EdgeCollapser::pushBound(int e)
{
  // The flip tests are most of an evaluation and most keys never reach the top: queue the
  // bound (the cost were nothing to flip) and run them only when it does.
  const CollapseChoice c = evaluate(e, false);
  heap_.set(e, keyOf(e, c));
  e_state_[e].bound = c.bound;
  e_state_[e].blockers = {-1, -1, -1, -1};
  e_state_[e].verified = 0;
  e_state_[e].evaluated = static_cast<std::uint32_t>(collapses_);
}

std::size_t
EdgeCollapser::run(std::size_t target)
{
  while (alive_count_ > target) {
    if (heap_.empty()) {
      if (unblockByHomology())
        continue;
      break;
    }
    const int e = heap_.topEdge();
    const int a = e_v_[e][0], b = e_v_[e][1];
    // A bound is checked for flips now; keys near a collapse go stale: re-validate those.
    const EdgeState& state = e_state_[e];
    if (!state.verified || std::max(v_touched_[a], v_touched_[b]) > state.evaluated) {
      const QueueKey old = heap_.topKey();
      push(e);
      if (old < heap_.topKey() || heap_.topKey() < old || heap_.topEdge() != e)
        continue;
    }
    // With a surface: a new centre (m* or the midpoint) must stay inside it; if not, that
    // candidate is dropped for this edge and the key recomputed.
    const std::uint8_t candidate = e_state_[e].candidate;
    if (inside_ && (candidate == kOptimum || candidate == kMidpoint) &&
        !insideSurface(a, e_target_[e])) {
      e_state_[e].outside |= candidate == kOptimum ? kOptimumOutside : kMidpointOutside;
      push(e);
      continue;
    }
    // Topology last: it is the dearest test, and only a collapse about to happen needs it.
    if (!linkCondition(e) && !killedCyclesAreBoundaries(e, kPopPatchRings)) {
      heap_.erase(e);
      e_state_[e].blocked = 1; // retried when its neighbourhood changes
      continue;
    }
    penalised_ += heap_.topKey().tier;
    heap_.erase(e);
    collapse(e, e_target_[e]);
  }
  return alive_count_;
}

MedialMesh
EdgeCollapser::extract() const
{
  // Survivors in input order, then merged spheres in merge order; edges and triangles in input
  // order (all of them are input elements, re-pointed).
  std::vector<int> by_rank(num_kept_ + collapses_, -1);
  for (std::size_t v = 0; v < sphere_.size(); ++v)
    if (v_alive_[v])
      by_rank[output_rank_[v]] = static_cast<int>(v);
  std::vector<int> index(sphere_.size(), -1);
  std::vector<Eigen::Vector3d> centers;
  std::vector<double> radii;
  centers.reserve(alive_count_);
  radii.reserve(alive_count_);
  for (int v : by_rank) {
    if (v < 0)
      continue;
    index[v] = static_cast<int>(centers.size());
    centers.push_back(sphere_[v].head<3>() * scale_ + origin_);
    radii.push_back(std::max(0.0, sphere_[v][3] * scale_));
  }
  std::vector<std::pair<int, Eigen::Vector2i>> edges;
  for (std::size_t e = 0; e < e_v_.size(); ++e)
    if (e_alive_[e])
      edges.push_back({e_orig_[e], Eigen::Vector2i(index[e_v_[e][0]], index[e_v_[e][1]])});
  std::sort(edges.begin(), edges.end(),
            [](const auto& x, const auto& y) { return x.first < y.first; });
  std::vector<std::pair<int, Eigen::Vector3i>> triangles;
  for (std::size_t f = 0; f < f_v_.size(); ++f)
    if (f_alive_[f]) {
      std::array<int, 3> t = {index[f_v_[f][0]], index[f_v_[f][1]], index[f_v_[f][2]]};
      std::sort(t.begin(), t.end()); // Q-MAT writes ascending corners; winding means nothing
      triangles.push_back({f_orig_[f], Eigen::Vector3i(t[0], t[1], t[2])});
    }
  std::sort(triangles.begin(), triangles.end(),
            [](const auto& x, const auto& y) { return x.first < y.first; });
  std::vector<Eigen::Vector2i> edge_list;
  edge_list.reserve(edges.size());
  for (const auto& e : edges)
    edge_list.push_back(e.second);
  std::vector<Eigen::Vector3i> triangle_list;
  triangle_list.reserve(triangles.size());
  for (const auto& t : triangles)
    triangle_list.push_back(t.second);
  return MedialMesh(std::move(centers), std::move(radii), edge_list, triangle_list);
}

} // namespace qmat
} // namespace segmat
