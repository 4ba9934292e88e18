/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include "bilateral_normal_filter.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace segmat {
namespace detail {
namespace {

struct FaceGeometry
{
  std::vector<Eigen::Vector3d> normals, centroids;
  std::vector<double> areas;
};

void
faceGeometry(const std::vector<Eigen::Vector3d>& vertices,
             const std::vector<Eigen::Vector3i>& faces, const std::vector<char>& valid,
             FaceGeometry& g)
{
  const std::size_t nf = faces.size();
  g.normals.assign(nf, Eigen::Vector3d::Zero());
  g.centroids.assign(nf, Eigen::Vector3d::Zero());
  g.areas.assign(nf, 0.0);
  for (std::size_t f = 0; f < nf; ++f) {
    if (!valid[f])
      continue;
    const Eigen::Vector3d& a = vertices[faces[f][0]];
    const Eigen::Vector3d& b = vertices[faces[f][1]];
    const Eigen::Vector3d& c = vertices[faces[f][2]];
    const Eigen::Vector3d n = (b - a).cross(c - a);
    g.centroids[f] = (a + b + c) / 3.0;
    g.areas[f] = 0.5 * n.norm();
    if (g.areas[f] > 0.0)
      g.normals[f] = n.normalized();
  }
}

} // namespace

NormalFiltering
bilateralNormalFilter(std::vector<Eigen::Vector3d>& vertices,
                      const std::vector<Eigen::Vector3i>& faces,
                      const NormalFilterSettings& settings, int threads)
{
  return bilateralNormalFilter(vertices, faces, FaceNeighbourhoods(faces, vertices.size()),
                               settings, threads);
}

NormalFiltering
bilateralNormalFilter(std::vector<Eigen::Vector3d>& vertices,
                      const std::vector<Eigen::Vector3i>& faces, const FaceNeighbourhoods& around,
                      const NormalFilterSettings& settings, int threads)
{
  NormalFiltering result;
  const std::size_t nv = vertices.size(), nf = faces.size();
  const std::vector<char>& valid = around.valid;
  const std::vector<std::size_t>& first = around.first;
  const std::vector<int>& neighbours = around.neighbours;
  const std::vector<std::size_t>& mirror = around.mirror;

  FaceGeometry g;
  faceGeometry(vertices, faces, valid, g);
  // σ_s from the faces that share an edge (two vertices).
  double distance_sum = 0.0;
  std::size_t pairs = 0;
  std::vector<std::pair<int, int>> edge_pairs; // faces sharing an edge, both with a normal
  for (std::size_t f = 0; f < nf; ++f)
    for (std::size_t a = first[f]; a < first[f + 1]; ++a) {
      const int j = neighbours[a];
      if (around.shares_edge[a]) {
        distance_sum += (g.centroids[f] - g.centroids[j]).norm();
        ++pairs;
        if (settings.range_from_normals && !g.normals[f].isZero() && !g.normals[j].isZero())
          edge_pairs.emplace_back(int(f), j);
      }
    }
  if (pairs == 0)
    return result;
  const double sigma_s = distance_sum / double(pairs);
  result.spatial_sigma = sigma_s;
  const double inv_s = 1.0 / (2.0 * sigma_s * sigma_s);
  std::vector<double> chords(edge_pairs.size());
  // σ_r from the normals as they are now: the median |n_i − n_j| over edge_pairs (floored).
  auto rangeSigma = [&](const std::vector<Eigen::Vector3d>& normals) {
    if (edge_pairs.empty())
      return settings.range_sigma;
    // Squared: the square root is monotonic, so it is taken of the median alone.
    const double floor2 = settings.range_sigma * settings.range_sigma;
    std::size_t above = 0;
    for (std::size_t e = 0; e < edge_pairs.size(); ++e) {
      chords[e] = (normals[edge_pairs[e].first] - normals[edge_pairs[e].second]).squaredNorm();
      above += chords[e] > floor2;
    }
    // Once the noise is gone the median lies below the floor: counting tells so without the
    // selection, and the floor is the answer either way.
    const std::size_t middle = chords.size() / 2;
    if (above < chords.size() - middle)
      return settings.range_sigma;
    std::nth_element(chords.begin(), chords.begin() + middle, chords.end());
    return std::max(settings.range_sigma, std::sqrt(chords[middle]));
  };
  const double still = 1.0 - std::cos(settings.still_degrees * M_PI / 180.0);

  // The centroids stay put while the normals are filtered: area × spatial weight once. Both
  // Gaussians are symmetric, so each pair's is computed once, by its lower face.
  std::vector<double> fixed(neighbours.size());
#pragma omp parallel for schedule(static) num_threads(threads)
  for (long f = 0; f < long(nf); ++f)
    for (std::size_t a = first[f]; a < first[f + 1]; ++a) {
      const int j = neighbours[a];
      if (j < f)
        continue;
      const double spatial = std::exp(-(g.centroids[f] - g.centroids[j]).squaredNorm() * inv_s);
      fixed[a] = g.areas[j] * spatial;
      fixed[mirror[a]] = g.areas[f] * spatial;
    }
  std::vector<Eigen::Vector3d> normals = g.normals, next(nf);
  // A face without a normal keeps none and lends none: filtering never makes a normal zero.
  std::vector<char> has_normal(nf);
  for (std::size_t f = 0; f < nf; ++f)
    has_normal[f] = !g.normals[f].isZero();
  // Each pair once, by its lower face (Gaussians are symmetric), so that the range weights of
  // all pairs go through one vectorised exp per iteration; pair[a] is entry a's pair.
  std::vector<int> lower_face, upper_face;
  std::vector<int> pair(neighbours.size());
  for (std::size_t f = 0; f < nf; ++f)
    for (std::size_t a = first[f]; a < first[f + 1]; ++a)
      if (neighbours[a] > int(f)) {
        pair[a] = pair[mirror[a]] = int(lower_face.size());
        lower_face.push_back(int(f));
        upper_face.push_back(neighbours[a]);
      }
  Eigen::ArrayXf exponent(static_cast<Eigen::Index>(lower_face.size()));
  // Per-face turns summed in face order afterwards: a parallel reduction would add them in an
  // order that depends on the thread count, and the stopping test could then differ.
  constexpr double kNone = std::numeric_limits<double>::quiet_NaN(); // a face without normal
  std::vector<double> turn(nf, kNone);
  for (int it = 0; it < settings.max_iterations; ++it) {
    // Re-estimated every iteration: as the noise goes, σ_r falls back to its floor, and the
    // creases that the first, wide iterations spared are kept from then on.
    const double range_sigma = rangeSigma(normals);
    if (it == 0)
      result.range_sigma = range_sigma;
    const double inv_r = 1.0 / (2.0 * range_sigma * range_sigma);
    // (Pairs with a face without normal get a weight that multiplies its zero normal.)
#pragma omp parallel for schedule(static) num_threads(threads)
    for (long p = 0; p < long(lower_face.size()); ++p) {
      const double dr = (normals[lower_face[p]] - normals[upper_face[p]]).squaredNorm();
      exponent[p] = float(-dr * inv_r);
    }
    exponent = exponent.exp();
#pragma omp parallel for schedule(static) num_threads(threads)
    for (long f = 0; f < long(nf); ++f) {
      next[f] = normals[f];
      turn[f] = kNone;
      if (!has_normal[f])
        continue;
      Eigen::Vector3d sum = g.areas[f] * normals[f];
      for (std::size_t a = first[f]; a < first[f + 1]; ++a)
        sum += fixed[a] * exponent[pair[a]] * normals[neighbours[a]];
      if (sum.norm() > 0.0)
        next[f] = sum.normalized();
      turn[f] = 1.0 - next[f].dot(normals[f]);
    }
    double turned = 0.0;
    int counted = 0;
    for (const double t : turn)
      if (!std::isnan(t)) {
        turned += t;
        ++counted;
      }
    normals.swap(next);
    ++result.normal_iterations;
    if (counted == 0 || turned / counted < still)
      break;
  }

  // Vertices onto the planes of their faces (Jacobi steps: the result is independent of order).
  std::vector<Eigen::Vector3d> moved(nv);
  for (int it = 0; it < settings.vertex_iterations; ++it) {
    // Only the centroids move with the vertices; the normals are the filtered ones.
#pragma omp parallel for schedule(static) num_threads(threads)
    for (long f = 0; f < long(nf); ++f)
      if (valid[f])
        g.centroids[f] =
            (vertices[faces[f][0]] + vertices[faces[f][1]] + vertices[faces[f][2]]) / 3.0;
#pragma omp parallel for schedule(static) num_threads(threads)
    for (long v = 0; v < long(nv); ++v) {
      moved[v] = vertices[v];
      const std::size_t begin = around.vertex_first[v], end = around.vertex_first[v + 1];
      if (begin == end)
        continue;
      Eigen::Vector3d step = Eigen::Vector3d::Zero();
      for (std::size_t a = begin; a < end; ++a) {
        const int f = around.vertex_faces[a];
        step += normals[f] * normals[f].dot(g.centroids[f] - vertices[v]);
      }
      moved[v] += step / double(end - begin);
    }
    vertices.swap(moved);
  }
  return result;
}

} // namespace detail
} // namespace segmat
