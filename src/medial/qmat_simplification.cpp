/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include <segmat/geometry/cone_tangent_plane.h>
#include <segmat/geometry/medial_primitives.h>
#include <segmat/geometry/winding_number.h>
#include <segmat/medial/qmat_simplification.h>
#include <segmat/medial/sphere_quadric.h>

#include <Eigen/Geometry>
#include <pcl/console/print.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <memory>
#include <vector>

#include "../common/thread_count.h"

namespace segmat {
namespace {

constexpr double kHalfPi = 1.57079632679489661923;
/// Neighbourhood searched for a disk bounding a cycle a collapse would kill: at every pop, and
/// once the queue has run dry.
constexpr int kPopPatchRings = 2;
constexpr int kStuckPatchRings = 4;

/** A collapse candidate's place in the queue: tier, then cost, then the edge's endpoint indices
 * (deterministic ties). */
struct QueueKey
{
  double cost = 0.0;
  int lo = 0, hi = 0;
  std::uint8_t tier = 0; ///< 0: normal; 1: every candidate flips a triangle (deferred)

  bool
  operator<(const QueueKey& o) const
  {
    if (tier != o.tier)
      return tier < o.tier;
    if (cost != o.cost)
      return cost < o.cost;
    if (lo != o.lo)
      return lo < o.lo;
    return hi < o.hi;
  }
};

/** Indexed 4-ary min-heap of edges: one entry per edge, keys updated in place, so the heap never
 * holds stale entries and stays no larger than the number of live edges. */
class EdgeHeap
{
public:
  /** Builds the heap of edges 0..keys.size()−1 at once (Floyd: O(n), where inserting one by
   * one sifted each key up). Keys are distinct (they end in the edge's ends), so the order of
   * pops is that of the keys whatever the layout. */
  void
  build(const std::vector<QueueKey>& keys)
  {
    const int n = static_cast<int>(keys.size());
    pos_.assign(keys.size(), -1);
    nodes_.resize(keys.size());
    for (int e = 0; e < n; ++e) {
      nodes_[e] = {keys[e], e};
      pos_[e] = e;
    }
    for (int i = n / 4; i >= 0; --i)
      if (i < n)
        siftDown(i);
  }

  bool empty() const { return nodes_.empty(); }
  int topEdge() const { return nodes_.front().edge; }
  const QueueKey& topKey() const { return nodes_.front().key; }

  /** Inserts edge e or changes its key. */
  void
  set(int e, const QueueKey& key)
  {
    if (pos_[e] < 0) {
      pos_[e] = static_cast<int>(nodes_.size());
      nodes_.push_back({key, e});
      siftUp(pos_[e]);
      return;
    }
    const int i = pos_[e];
    const bool up = key < nodes_[i].key;
    nodes_[i].key = key;
    if (up)
      siftUp(i);
    else
      siftDown(i);
  }

  /** Removes edge e if present. */
  void
  erase(int e)
  {
    const int i = pos_[e];
    if (i < 0)
      return;
    pos_[e] = -1;
    const Node last = nodes_.back();
    nodes_.pop_back();
    if (i == static_cast<int>(nodes_.size()))
      return;
    nodes_[i] = last;
    pos_[last.edge] = i;
    if (i > 0 && last.key < nodes_[(i - 1) / 4].key)
      siftUp(i);
    else
      siftDown(i);
  }

private:
  struct Node
  {
    QueueKey key;
    int edge;
  };

  void
  siftUp(int i)
  {
    const Node n = nodes_[i];
    while (i > 0) {
      const int parent = (i - 1) / 4;
      if (!(n.key < nodes_[parent].key))
        break;
      nodes_[i] = nodes_[parent];
      pos_[nodes_[i].edge] = i;
      i = parent;
    }
    nodes_[i] = n;
    pos_[n.edge] = i;
  }

  void
  siftDown(int i)
  {
    const Node n = nodes_[i];
    const int size = static_cast<int>(nodes_.size());
    for (;;) {
      const int first = 4 * i + 1;
      if (first >= size)
        break;
      int best = first;
      const int last = std::min(first + 4, size);
      for (int c = first + 1; c < last; ++c)
        if (nodes_[c].key < nodes_[best].key)
          best = c;
      if (!(nodes_[best].key < n.key))
        break;
      nodes_[i] = nodes_[best];
      pos_[nodes_[i].edge] = i;
      i = best;
    }
    nodes_[i] = n;
    pos_[n.edge] = i;
  }

  std::vector<Node> nodes_;
  std::vector<int> pos_;
};

/** The sphere an edge would collapse to and the cost of doing so. */
struct CollapseChoice
{
  Eigen::Vector4d sphere;
  double cost = 0.0;
  std::uint8_t tier = 0;
  /// Triangles that made cheaper candidates flip (-1: unused). While they stand unchanged the
  /// key cannot drop; once one changes, it may, but not below \a bound.
  std::array<int, 4> blockers = {-1, -1, -1, -1};
  double bound = 0.0; ///< the cost were nothing to flip: a lower bound of every later cost
  std::uint8_t candidate = 0; ///< which sphere: kOptimum, kFirstEnd, kSecondEnd or kMidpoint
};

enum Candidate : std::uint8_t
{
  kOptimum = 0,
  kFirstEnd = 1,
  kSecondEnd = 2,
  kMidpoint = 3,
};
/// Bits of EdgeCollapser::EdgeState::outside: candidates found outside the surface.
constexpr std::uint8_t kOptimumOutside = 1, kMidpointOutside = 2;

/** Incremental span of GF(2) vectors (echelon form keyed by leading bit), flat storage. Used to
 * decide whether a cycle is a sum of triangle boundaries (a mod-2 boundary). */
class Gf2Span
{
public:
  /** Empties the span; vectors have \a bits entries. */
  void
  reset(std::size_t bits)
  {
    words_ = (bits + 63) / 64;
    rows_.clear();
    lead_row_.assign(bits, -1);
    scratch_.assign(words_, 0);
  }

  /** The zeroed working vector to fill with flip(). */
  std::uint64_t*
  scratch()
  {
    std::fill(scratch_.begin(), scratch_.end(), 0);
    return scratch_.data();
  }

  static void
  flip(std::uint64_t* v, std::size_t bit)
  {
    v[bit / 64] ^= std::uint64_t(1) << (bit % 64);
  }

  /** Adds the working vector to the span. */
  void
  insertScratch()
  {
    const long h = reduce();
    if (h < 0)
      return;
    lead_row_[h] = static_cast<long>(rows_.size() / words_);
    rows_.insert(rows_.end(), scratch_.begin(), scratch_.end());
  }

  /** True when the working vector is in the span. */
  bool
  scratchInSpan()
  {
    return reduce() < 0;
  }

private:
  /** Reduces the working vector by the rows; returns its leading bit (-1: zero). */
  long
  reduce()
  {
    for (;;) {
      long h = -1;
      for (std::size_t w = words_; w-- > 0;)
        if (scratch_[w]) {
          h = static_cast<long>(w * 64 + 63 - __builtin_clzll(scratch_[w]));
          break;
        }
      if (h < 0 || lead_row_[h] < 0)
        return h;
      const std::uint64_t* row = rows_.data() + lead_row_[h] * words_;
      for (std::size_t w = 0; w < words_; ++w)
        scratch_[w] ^= row[w];
    }
  }

  std::size_t words_ = 0;
  std::vector<std::uint64_t> rows_;
  std::vector<long> lead_row_;
  std::vector<std::uint64_t> scratch_;
};

struct Settings
{
  double k;
  double boundary_weight;
  bool prevent_inversion;
  bool preserve_cavities;
  unsigned threads;
};

/** The dynamic simplicial 2-complex being simplified. Vertex ids: the input spheres with an edge,
 * in breadth-first order; a merged sphere takes the slot of its edge's first end (output_rank_
 * keeps the output order: survivors in input order, then merges in merge order). */
class EdgeCollapser
{
public:
  /** \a inside: optional surface whose inside merged centres must stay in (not owned). */
  EdgeCollapser(const MedialMesh& mat, const Eigen::Vector3d& origin, double scale,
                const Settings& settings, const WindingNumber* inside);

  std::size_t aliveCount() const { return alive_count_; }
  std::size_t collapses() const { return collapses_; }
  std::size_t penalisedCollapses() const { return penalised_; }

  /** Collapse until \a target spheres remain or nothing can collapse; returns the count. */
  std::size_t run(std::size_t target);

  /** The current complex in input units, compacted. */
  MedialMesh extract() const;

private:
  bool hasVertex(int f, int v) const
  {
    const auto& t = f_v_[f];
    return t[0] == v || t[1] == v || t[2] == v;
  }
  int other(int e, int v) const { return e_v_[e][0] == v ? e_v_[e][1] : e_v_[e][0]; }

  void buildQuadrics();
  CollapseChoice evaluate(int e, bool check_flips = true) const;
  QueueKey keyOf(int e, const CollapseChoice& c) const
  {
    const int ra = output_rank_[e_v_[e][0]], rb = output_rank_[e_v_[e][1]];
    return {c.cost, std::min(ra, rb), std::max(ra, rb), c.tier};
  }
  Eigen::Vector3d faceNormal(int f) const;
  bool linkCondition(int e);
  bool unblockByHomology();
  bool killedCyclesAreBoundaries(int e, int rings);
  bool cyclesBoundWithin(int a, int b, int rings);
  bool faceExists(int a, int x, int y) const;
  bool insideSurface(int from, const Eigen::Vector4d& sphere) const;
  void collapse(int e, const Eigen::Vector4d& target);
  void push(int e);
  void pushBound(int e);
  static void removeFrom(std::vector<int>& list, int value);
  /** An empty list, reusing a dead vertex's buffer when one is spare. */
  std::vector<int> recycledList();
  /** Empties \a list, keeping its buffer for recycledList() (a few, not all of them). */
  void recycleList(std::vector<int>& list);

  Settings settings_;
  Eigen::Vector3d origin_;
  double scale_;
  const WindingNumber* inside_; ///< optional surface (input units)

  // vertices
  int num_kept_ = 0;             ///< input spheres with an edge (the slots)
  std::vector<int> output_rank_; ///< position in the output order (input order, then merges)
  std::vector<Eigen::Vector4d> sphere_;
  struct Quadrics
  {
    SphereQuadric face; ///< slab tangent planes only (§8.3)
    SphereQuadric all;  ///< plus sheet borders, pure edges, branch tips (§8.3)
  };
  std::vector<Quadrics> q_; ///< side by side: an evaluation reads both
  std::vector<char> v_alive_;
  std::vector<std::vector<int>> v_edges_, v_faces_;
  std::vector<std::uint32_t> mark_;
  std::vector<int> edge_to_; ///< scratch of collapse(): m's edge to a marked neighbour
  std::uint32_t stamp_ = 0;
  // edges
  std::vector<int> e_orig_; ///< input index of each edge
  std::vector<std::array<int, 2>> e_v_;
  std::vector<char> e_alive_;
  std::vector<Eigen::Vector4d> e_target_; ///< the sphere chosen then
  /** What the queue knows of an edge, in one place: a collapse checks it on every edge two
   * rings around the merged sphere, and one record per edge is one cache miss there, where
   * separate arrays were three (they took a quarter of the collapse's time). */
  struct EdgeState
  {
    EdgeState() : blocked(0), verified(0), has_faces(0) {}
    double bound = 0.0;                             ///< CollapseChoice::bound of the key
    std::array<int, 4> blockers = {-1, -1, -1, -1}; ///< CollapseChoice::blockers of the key
    std::uint32_t evaluated = 0; ///< collapse count when the key was computed
    std::uint8_t blocked : 1;   ///< failed the topology test; retried when its link changes
    std::uint8_t verified : 1;  ///< key checked for flips (else it is the bound)
    std::uint8_t has_faces : 1; ///< a triangle stands on the edge (kept by collapse())
    std::uint8_t candidate = kOptimum; ///< CollapseChoice::candidate of the key
    std::uint8_t outside = 0;          ///< kOptimumOutside | kMidpointOutside
  };
  std::vector<EdgeState> e_state_;
  std::vector<std::size_t> v_touched_;   ///< collapse count when a triangle around it changed
  // faces
  std::vector<int> f_orig_; ///< input index of each triangle
  std::vector<std::array<int, 3>> f_v_;
  std::vector<Eigen::Vector3d> f_normal_; ///< (p1 − p0) × (p2 − p0); zero when degenerate
  std::vector<char> f_alive_;

  EdgeHeap heap_;
  std::size_t alive_count_ = 0;
  std::size_t collapses_ = 0;
  std::size_t penalised_ = 0;
  std::vector<int> scratch_;
  // killedCyclesAreBoundaries() buffers, kept to avoid allocations
  std::vector<int> scratch_bad_, scratch_patch_, scratch_faces_;
  std::vector<std::uint64_t> scratch_keys_;
  Gf2Span scratch_span_;
  /// Buffers of dead vertices' lists: each collapse frees four lists and needs two, and
  /// malloc/free of them was a visible share of the collapse loop.
  std::vector<std::vector<int>> spare_lists_;
};

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

bool
EdgeCollapser::faceExists(int a, int x, int y) const
{
  for (int f : v_faces_[a])
    if (hasVertex(f, x) && hasVertex(f, y))
      return true;
  return false;
}

bool
EdgeCollapser::linkCondition(int e)
{
  const int a = e_v_[e][0], b = e_v_[e][1];
  ++stamp_;
  for (int ea : v_edges_[a])
    mark_[other(ea, a)] = stamp_;
  scratch_.clear(); // common neighbours: the vertex part of Lk(a) ∩ Lk(b)
  for (int eb : v_edges_[b]) {
    const int x = other(eb, b);
    if (x != a && mark_[x] == stamp_)
      scratch_.push_back(x);
  }
  // Lk(ab) = third corners of the triangles on ab. Each is a common neighbour (triangle sides
  // are edges), so equality of the vertex parts is a count comparison.
  std::size_t on_ab = 0;
  for (int f : v_faces_[a])
    if (hasVertex(f, b))
      ++on_ab;
  if (on_ab != scratch_.size())
    return false;
  // Edge part: Lk(ab) has no edges in a 2-complex, so an edge xy carrying both axy and bxy
  // violates the condition: the collapse would flatten the hollow tetrahedron abxy, closing one
  // cavity (b2 − 1) and changing nothing else. Such x, y are common neighbours.
  if (!settings_.preserve_cavities)
    return true;
  for (std::size_t i = 0; i < scratch_.size(); ++i)
    for (std::size_t j = i + 1; j < scratch_.size(); ++j)
      if (faceExists(a, scratch_[i], scratch_[j]) && faceExists(b, scratch_[i], scratch_[j]))
        return false;
  return true;
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

bool
EdgeCollapser::unblockByHomology()
{
  if (settings_.preserve_cavities)
    return false;
  // Every live edge is blocked here (the queue is empty). Try them cheapest first.
  struct Candidate
  {
    QueueKey key;
    int edge;
    CollapseChoice choice;
  };
  std::vector<Candidate> blocked;
  for (std::size_t ue = 0; ue < e_v_.size(); ++ue)
    if (e_alive_[ue]) {
      const int e = static_cast<int>(ue);
      CollapseChoice c = evaluate(e);
      // Same surface rule as in run(): at most two rounds, the ends are inside.
      while (inside_ && (c.candidate == kOptimum || c.candidate == kMidpoint) &&
             !insideSurface(e_v_[e][0], c.sphere)) {
        e_state_[e].outside |= c.candidate == kOptimum ? kOptimumOutside : kMidpointOutside;
        c = evaluate(e);
      }
      blocked.push_back({keyOf(e, c), e, c});
    }
  std::sort(blocked.begin(), blocked.end(),
            [](const Candidate& x, const Candidate& y) { return x.key < y.key; });
  for (const Candidate& candidate : blocked)
    if (killedCyclesAreBoundaries(candidate.edge, kStuckPatchRings)) {
      penalised_ += candidate.choice.tier;
      collapse(candidate.edge, candidate.choice.sphere);
      return true;
    }
  return false;
}

bool
EdgeCollapser::killedCyclesAreBoundaries(int e, int rings)
{
  // Killing a cycle that bounds creates a cavity: not allowed when cavities are kept.
  if (settings_.preserve_cavities)
    return false;
  const int a = e_v_[e][0], b = e_v_[e][1];
  // The common neighbours x without a triangle abx: the collapse kills the cycles ab+bx+xa.
  std::vector<int>& bad = scratch_bad_;
  bad.clear();
  ++stamp_;
  for (int ea : v_edges_[a])
    mark_[other(ea, a)] = stamp_;
  for (int eb : v_edges_[b]) {
    const int x = other(eb, b);
    if (x != a && mark_[x] == stamp_ && !faceExists(a, b, x))
      bad.push_back(x);
  }
  if (bad.empty())
    return true;
  // The usual disk: a cone from a vertex y over the cycle (triangles aby, bxy, axy).
  auto coneBounds = [&](int x) {
    for (int f : v_faces_[a]) {
      if (!hasVertex(f, b))
        continue;
      const auto& t = f_v_[f];
      const int y = t[0] != a && t[0] != b ? t[0] : (t[1] != a && t[1] != b ? t[1] : t[2]);
      if (faceExists(b, x, y) && faceExists(a, x, y))
        return true;
    }
    return false;
  };
  if (std::all_of(bad.begin(), bad.end(), coneBounds))
    return true;
  // Otherwise look for a disk in growing neighbourhoods: small disks are the rule.
  for (int r = 1; r <= rings; ++r)
    if (cyclesBoundWithin(a, b, r))
      return true;
  return false;
}

bool
EdgeCollapser::cyclesBoundWithin(int a, int b, int rings)
{
  const std::vector<int>& bad = scratch_bad_;
  // Local patch: vertices within \a rings edges of a or b, and the triangles among them.
  constexpr std::size_t kMaxPatchFaces = 4096;
  ++stamp_;
  std::vector<int>& patch = scratch_patch_;
  patch.assign({a, b});
  mark_[a] = mark_[b] = stamp_;
  for (int ring = 0, begin = 0; ring < rings; ++ring) {
    const int end = static_cast<int>(patch.size());
    for (int i = begin; i < end; ++i)
      for (int e2 : v_edges_[patch[i]]) {
        const int x = other(e2, patch[i]);
        if (mark_[x] != stamp_) {
          mark_[x] = stamp_;
          patch.push_back(x);
        }
      }
    begin = end;
  }
  // Local edge numbering; the faces as GF(2) vectors over it.
  std::vector<int>& faces = scratch_faces_;
  faces.clear();
  for (int v : patch)
    for (int f : v_faces_[v]) {
      const auto& t = f_v_[f];
      if (mark_[t[0]] == stamp_ && mark_[t[1]] == stamp_ && mark_[t[2]] == stamp_ &&
          std::min({t[0], t[1], t[2]}) == v) // each face once, from its smallest corner
        faces.push_back(f);
    }
  if (faces.size() > kMaxPatchFaces)
    return false; // too big to decide cheaply: stay on the safe side
  std::vector<std::uint64_t>& keys = scratch_keys_;
  keys.clear();
  auto key = [](int p, int q) {
    return (static_cast<std::uint64_t>(std::min(p, q)) << 32) |
           static_cast<std::uint32_t>(std::max(p, q));
  };
  for (int f : faces)
    for (int k = 0; k < 3; ++k)
      keys.push_back(key(f_v_[f][k], f_v_[f][(k + 1) % 3]));
  for (int x : bad) {
    keys.push_back(key(a, x));
    keys.push_back(key(b, x));
  }
  keys.push_back(key(a, b));
  std::sort(keys.begin(), keys.end());
  keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
  auto bitOf = [&](int p, int q) {
    return static_cast<std::size_t>(std::lower_bound(keys.begin(), keys.end(), key(p, q)) -
                                    keys.begin());
  };
  Gf2Span& span = scratch_span_;
  span.reset(keys.size());
  for (int f : faces) {
    std::uint64_t* v = span.scratch();
    for (int k = 0; k < 3; ++k)
      Gf2Span::flip(v, bitOf(f_v_[f][k], f_v_[f][(k + 1) % 3]));
    span.insertScratch();
  }
  for (int x : bad) {
    std::uint64_t* z = span.scratch();
    Gf2Span::flip(z, bitOf(a, b));
    Gf2Span::flip(z, bitOf(b, x));
    Gf2Span::flip(z, bitOf(x, a));
    if (!span.scratchInSpan())
      return false; // not a boundary in the patch: may be a tunnel or hole
  }
  return true;
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

} // namespace

QmatSimplification::QmatSimplification()
: normalisation_scale_(0.0)
, base_target_(2000)
, structured_target_(-1)
, k_(1e-5)
, boundary_weight_(0.1)
, prevent_inversion_(true)
, preserve_cavities_(false)
, threads_(1)
{}

bool
QmatSimplification::compute(MedialMesh& base, MedialMesh& structured)
{
  base = MedialMesh();
  structured = MedialMesh();
  initial_count_ = 0;
  resolved_structured_target_ = 0;
  collapse_count_ = 0;
  penalised_collapse_count_ = 0;
  if (!input_ || input_->empty()) {
    PCL_ERROR("[segmat::QmatSimplification::compute] no input medial mesh (or it is empty)\n");
    return false;
  }
  if (base_target_ < 1 || (structured_target_ < 1 && structured_target_ != -1)) {
    PCL_ERROR("[segmat::QmatSimplification::compute] invalid targets: base %d, structured %d "
              "(need >= 1, structured may be -1)\n",
              base_target_, structured_target_);
    return false;
  }
  if (!(k_ >= 0.0) || !std::isfinite(k_) || !(boundary_weight_ >= 0.0) ||
      !std::isfinite(boundary_weight_)) {
    PCL_ERROR("[segmat::QmatSimplification::compute] k and the boundary weight must be finite "
              "and >= 0\n");
    return false;
  }
  const MedialMesh& mat = *input_;
  const std::size_t input_count = mat.numVertices();
  resolved_structured_target_ =
      structured_target_ > 0
          ? structured_target_
          : std::max(15, static_cast<int>(0.001 * static_cast<double>(input_count)));

  // Normalised coordinates: centred on the centres' bounding box, divided by the scale.
  Eigen::Vector3d lo = mat.centers().front(), hi = lo;
  for (const Eigen::Vector3d& c : mat.centers()) {
    lo = lo.cwiseMin(c);
    hi = hi.cwiseMax(c);
  }
  double scale = normalisation_scale_;
  if ((!(scale > 0.0) || !std::isfinite(scale)) && surface_)
    scale = surface_->boundingBoxDiagonal();
  if (!(scale > 0.0) || !std::isfinite(scale))
    scale = (hi - lo).norm();
  if (!(scale > 0.0))
    scale = 1.0;

  std::shared_ptr<const WindingNumber> inside;
  if (surface_ && !surface_->empty())
    inside = winding_number_ ? winding_number_ : std::make_shared<const WindingNumber>(*surface_);
  const Settings settings{k_, boundary_weight_, prevent_inversion_, preserve_cavities_, threads_};
  EdgeCollapser collapser(mat, 0.5 * (lo + hi), scale, settings, inside.get());
  initial_count_ = collapser.aliveCount();
  if (initial_count_ == 0) {
    PCL_ERROR("[segmat::QmatSimplification::compute] the medial mesh has no edges\n");
    return false;
  }

  const std::size_t base_target = static_cast<std::size_t>(base_target_);
  const bool stuck = collapser.run(base_target) > base_target;
  if (stuck)
    PCL_WARN("[segmat::QmatSimplification::compute] base target %d not reached: every further "
             "collapse changes the topology; %zu spheres kept\n",
             base_target_, collapser.aliveCount());
  base = collapser.extract();

  std::size_t structured_target = static_cast<std::size_t>(resolved_structured_target_);
  if (!stuck && structured_target < collapser.aliveCount()) {
    // With the automatic target, a base MAT whose topology pins many spheres (islands, loops
    // around holes: a noisy plate's medial sheet) is not run down to its minimal wireframe —
    // that collapses every sheet, and thin plates lose the sheets the structure tags need. The
    // target then counts spheres beyond the pinned ones (a deviation from SEG-MAT, which does
    // not say what happens when the target is out of reach): redone from the base MAT, the
    // simplification stops at pinned + target. An explicit target is taken literally.
    // The state at the base MAT is needed again only then. Copying it costs ~15 % of Q-MAT, so
    // it is kept only when the base MAT's islands alone take half the target; otherwise the
    // rare miss replays the run to the base MAT (deterministic: the same state).
    std::unique_ptr<EdgeCollapser> from_base;
    if (structured_target_ < 0 && 2 * base.numConnectedComponents() >= structured_target)
      from_base = std::make_unique<EdgeCollapser>(collapser);
    if (collapser.run(structured_target) > structured_target) {
      if (structured_target_ < 0 && !from_base) {
        from_base = std::make_unique<EdgeCollapser>(mat, 0.5 * (lo + hi), scale, settings,
                                                    inside.get());
        from_base->run(base_target);
      }
      const std::size_t pinned = collapser.aliveCount();
      if (from_base) {
        structured_target += pinned;
        resolved_structured_target_ = static_cast<int>(structured_target);
        collapser = std::move(*from_base);
        collapser.run(structured_target);
        PCL_WARN("[segmat::QmatSimplification::compute] structured target %zu out of reach: "
                 "the topology pins %zu spheres; %zu kept (pinned + target)\n",
                 structured_target - pinned, pinned, collapser.aliveCount());
      }
      else
        PCL_WARN("[segmat::QmatSimplification::compute] structured target %zu not reached: "
                 "every further collapse changes the topology; %zu spheres kept\n",
                 structured_target, pinned);
    }
  }
  structured = collapser.extract();
  collapse_count_ = collapser.collapses();
  penalised_collapse_count_ = collapser.penalisedCollapses();
  return true;
}

} // namespace segmat
