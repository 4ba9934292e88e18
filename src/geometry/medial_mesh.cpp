/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include <segmat/common/error.h>
#include <segmat/geometry/medial_mesh.h>
#include "point_bounds.h"

#include <boost/pending/disjoint_sets.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

namespace segmat {
namespace {
std::uint64_t
edgeKey(int a, int b)
{
  if (a > b)
    std::swap(a, b);
  return (static_cast<std::uint64_t>(a) << 32) | static_cast<std::uint32_t>(b);
}
} // namespace

MedialMesh::MedialMesh(std::vector<Eigen::Vector3d> centers, std::vector<double> radii,
                       const std::vector<Eigen::Vector2i>& edges,
                       const std::vector<Eigen::Vector3i>& triangles)
: centers_(std::move(centers)), radii_(std::move(radii))
{
  if (centers_.size() != radii_.size())
    throw Error("MedialMesh: " + std::to_string(centers_.size()) + " centres but " +
                std::to_string(radii_.size()) + " radii");
  const int n = static_cast<int>(centers_.size());
  for (int v = 0; v < n; ++v) {
    if (!centers_[v].allFinite())
      throw Error("MedialMesh: sphere " + std::to_string(v) + " has a non-finite centre");
    if (!std::isfinite(radii_[v]) || radii_[v] < 0.0)
      throw Error("MedialMesh: sphere " + std::to_string(v) + " has an invalid radius");
  }
  auto check = [n](int idx, const char* what, std::size_t i) {
    if (idx < 0 || idx >= n)
      throw Error(std::string("MedialMesh: ") + what + " " + std::to_string(i) + " refers to vertex " +
                  std::to_string(idx) + " of " + std::to_string(n));
  };

  // Edge ids in order of first appearance (given edges, then triangle sides). The index is a
  // flat open-addressing table (a node-based std::unordered_map spent ~40 % of a Voronoi MAT's
  // assembly in allocation and rehashing), sized for the given edges plus half the triangles'
  // sides — a triangle's sides are mostly shared or given — and doubled when half full. Sizing
  // it for every possible side (3 per triangle) filled 12 MB of fresh pages for a 42 000-sphere
  // Voronoi MAT whose 124 000 edges all came given. Ids do not depend on the table's size.
  constexpr std::uint64_t kEmpty = ~std::uint64_t(0); // no edge has this key (a, b < 2^31)
  std::size_t capacity = 16;
  while (capacity < 2 * (edges.size() + triangles.size() / 2))
    capacity *= 2;
  std::vector<std::uint64_t> slot_key(capacity, kEmpty);
  std::vector<int> slot_edge(capacity);
  auto slotOf = [&](std::uint64_t key) {
    // Fibonacci hashing: the top bits of key × 2^64/φ, then linear probing.
    std::size_t i = static_cast<std::size_t>((key * 0x9E3779B97F4A7C15ull) >> 32) & (capacity - 1);
    while (slot_key[i] != kEmpty && slot_key[i] != key)
      i = (i + 1) & (capacity - 1);
    return i;
  };
  auto addEdge = [&](int a, int b) {
    const std::uint64_t key = edgeKey(a, b);
    std::size_t i = slotOf(key);
    if (slot_key[i] == key)
      return slot_edge[i];
    const int id = static_cast<int>(edges_.size());
    edges_.emplace_back(std::min(a, b), std::max(a, b));
    if (2 * edges_.size() > capacity) {
      const std::vector<std::uint64_t> old_key = std::move(slot_key);
      const std::vector<int> old_edge = std::move(slot_edge);
      capacity *= 2;
      slot_key.assign(capacity, kEmpty);
      slot_edge.assign(capacity, 0);
      for (std::size_t j = 0; j < old_key.size(); ++j)
        if (old_key[j] != kEmpty) {
          const std::size_t k = slotOf(old_key[j]);
          slot_key[k] = old_key[j];
          slot_edge[k] = old_edge[j];
        }
      i = slotOf(key);
    }
    slot_key[i] = key;
    slot_edge[i] = id;
    return id;
  };

  for (std::size_t i = 0; i < edges.size(); ++i) {
    check(edges[i][0], "edge", i);
    check(edges[i][1], "edge", i);
    if (edges[i][0] != edges[i][1])
      addEdge(edges[i][0], edges[i][1]);
  }

  // Triangles are deduplicated on their sorted corner triple.
  std::vector<std::array<int, 3>> seen;
  seen.reserve(triangles.size());
  for (std::size_t i = 0; i < triangles.size(); ++i) {
    const Eigen::Vector3i& t = triangles[i];
    for (int k = 0; k < 3; ++k)
      check(t[k], "triangle", i);
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2])
      continue;
    std::array<int, 3> key{t[0], t[1], t[2]};
    std::sort(key.begin(), key.end());
    seen.push_back(key);
  }
  std::vector<std::size_t> order(seen.size());
  for (std::size_t i = 0; i < order.size(); ++i)
    order[i] = i;
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return seen[a] < seen[b]; });
  std::vector<char> keep(seen.size(), 1);
  for (std::size_t i = 1; i < order.size(); ++i)
    if (seen[order[i]] == seen[order[i - 1]])
      keep[order[i]] = 0;
  std::size_t s = 0;
  for (std::size_t i = 0; i < triangles.size(); ++i) {
    const Eigen::Vector3i& t = triangles[i];
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2])
      continue;
    if (keep[s++])
      triangles_.push_back(t);
  }

  edge_triangle_count_.assign(edges_.size(), 0);
  for (const Eigen::Vector3i& t : triangles_)
    for (int k = 0; k < 3; ++k) {
      const int e = addEdge(t[k], t[(k + 1) % 3]);
      if (e >= static_cast<int>(edge_triangle_count_.size()))
        edge_triangle_count_.resize(e + 1, 0);
      ++edge_triangle_count_[e];
    }

  // Exact reservations: one allocation per list instead of a chain of regrowths.
  std::vector<int> edge_degree(n, 0), triangle_degree(n, 0);
  for (const Eigen::Vector2i& e : edges_) {
    ++edge_degree[e[0]];
    ++edge_degree[e[1]];
  }
  for (const Eigen::Vector3i& t : triangles_)
    for (int k = 0; k < 3; ++k)
      ++triangle_degree[t[k]];
  vertex_edges_.assign(n, {});
  vertex_triangles_.assign(n, {});
  for (int v = 0; v < n; ++v) {
    vertex_edges_[v].reserve(edge_degree[v]);
    vertex_triangles_[v].reserve(triangle_degree[v]);
  }
  for (std::size_t e = 0; e < edges_.size(); ++e) {
    vertex_edges_[edges_[e][0]].push_back(static_cast<int>(e));
    vertex_edges_[edges_[e][1]].push_back(static_cast<int>(e));
  }
  for (std::size_t t = 0; t < triangles_.size(); ++t)
    for (int k = 0; k < 3; ++k)
      vertex_triangles_[triangles_[t][k]].push_back(static_cast<int>(t));
}

int
MedialMesh::findEdge(int a, int b) const
{
  if (a < 0 || b < 0 || a >= static_cast<int>(vertex_edges_.size()))
    return -1;
  const int lo = std::min(a, b), hi = std::max(a, b);
  for (int e : vertex_edges_[a])
    if (edges_[e][0] == lo && edges_[e][1] == hi)
      return e;
  return -1;
}

double
MedialMesh::centerBoundingBoxDiagonal() const
{
  return detail::boundsDiagonal(centers_);
}

double
MedialMesh::maxRadius() const
{
  return radii_.empty() ? 0.0 : *std::max_element(radii_.begin(), radii_.end());
}

std::size_t
MedialMesh::numConnectedComponents() const
{
  // Every triangle's sides are edges of the mesh, so edges alone decide connectivity.
  boost::disjoint_sets_with_storage<> sets(numVertices());
  for (std::size_t v = 0; v < numVertices(); ++v)
    sets.make_set(v);
  for (const Eigen::Vector2i& e : edges_)
    sets.union_set(e[0], e[1]);
  std::size_t count = 0;
  for (std::size_t v = 0; v < numVertices(); ++v)
    count += sets.find_set(v) == v;
  return count;
}

} // namespace segmat
