/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
// The edge collapser's topology tests: the link condition, and the homology test that lets a
// collapse through when every cycle it kills bounds a disk of triangles nearby.
#include "qmat_edge_collapser.h"

#include <algorithm>

namespace segmat {
namespace qmat {

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
  // Local edge numbers, in order of first appearance (any one-to-one numbering gives the same
  // span), from an open-addressing table in reused buffers (std::unordered_map would allocate
  // a node per edge on every call): three per face, two per bad x, then ab.
  const std::size_t listed = 3 * faces.size() + 2 * bad.size() + 1;
  int shift = 64; // the table has 2^(64 − shift) >= 2 slots, so shift < 64
  std::size_t size = 1;
  while (size < 2 * listed) {
    size <<= 1;
    --shift;
  }
  constexpr std::uint64_t kEmpty = ~std::uint64_t(0); // never a key: vertex ids are below 2^31
  std::vector<std::uint64_t>& table = scratch_keys_;
  std::vector<std::uint32_t>& number = scratch_numbers_;
  table.assign(size, kEmpty);
  number.resize(size);
  std::vector<std::uint32_t>& bit = scratch_bits_;
  bit.clear();
  std::uint32_t edges = 0;
  auto list = [&](int p, int q) {
    const std::uint64_t key = (static_cast<std::uint64_t>(std::min(p, q)) << 32) |
                              static_cast<std::uint32_t>(std::max(p, q));
    std::size_t h = static_cast<std::size_t>((key * 0x9E3779B97F4A7C15ull) >> shift);
    while (table[h] != kEmpty && table[h] != key)
      h = (h + 1) & (size - 1);
    if (table[h] == kEmpty) {
      table[h] = key;
      number[h] = edges++;
    }
    bit.push_back(number[h]);
  };
  for (int f : faces)
    for (int k = 0; k < 3; ++k)
      list(f_v_[f][k], f_v_[f][(k + 1) % 3]);
  for (int x : bad) {
    list(a, x);
    list(b, x);
  }
  list(a, b);
  Gf2Span& span = scratch_span_;
  span.reset(edges);
  std::size_t slot = 0;
  for (std::size_t i = 0; i < faces.size(); ++i, slot += 3) {
    std::uint64_t* v = span.scratch();
    for (int k = 0; k < 3; ++k)
      Gf2Span::flip(v, bit[slot + k]);
    span.insertScratch();
  }
  const std::uint32_t ab = bit.back();
  for (std::size_t i = 0; i < bad.size(); ++i, slot += 2) {
    std::uint64_t* z = span.scratch();
    Gf2Span::flip(z, ab);
    Gf2Span::flip(z, bit[slot + 1]); // b x
    Gf2Span::flip(z, bit[slot]);     // x a
    if (!span.scratchInSpan())
      return false; // not a boundary in the patch: may be a tunnel or hole
  }
  return true;
}

} // namespace qmat
} // namespace segmat
