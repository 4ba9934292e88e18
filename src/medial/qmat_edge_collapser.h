/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once
// Private to src/medial: the edge collapser behind QmatSimplification (Q-MAT, Li et al. 2015,
// as SEG-MAT uses it): the dynamic simplicial 2-complex, its quadric costs and topology tests.

#include <segmat/geometry/medial_mesh.h>
#include <segmat/medial/sphere_quadric.h>

#include <Eigen/Core>

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "qmat_cycle_span.h"
#include "qmat_heap.h"

namespace segmat {

class WindingNumber;

namespace qmat {

/// Neighbourhood searched for a disk bounding a cycle a collapse would kill: at every pop, and
/// once the queue has run dry.
constexpr int kPopPatchRings = 2;
constexpr int kStuckPatchRings = 4;

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
  std::vector<std::uint64_t> scratch_keys_;     // hash table of edge keys
  std::vector<std::uint32_t> scratch_numbers_;  // their local edge numbers
  std::vector<std::uint32_t> scratch_bits_;     // listed edge → local edge number
  Gf2Span scratch_span_;
  /// Buffers of dead vertices' lists: each collapse frees four lists and needs two, and
  /// malloc/free of them was a visible share of the collapse loop.
  std::vector<std::vector<int>> spare_lists_;
};

} // namespace qmat
} // namespace segmat
