/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include "surface_denoising.h"

#include "../geometry/bilateral_normal_filter.h"
#include "../geometry/tangential_relaxation.h"
#include "local_fit.h"

#include <Eigen/Cholesky>

#include <algorithm>
#include <cmath>
#include <tuple>

namespace segmat {
namespace detail {
namespace {

/// The rows of sidedHeightFit's table: 15 monomials u^a v^b (a + b <= 4), then the height
/// times each of the basis 1, u, v, u², uv, v²; one row of padding makes each column whole
/// SIMD packets of doubles, so that the weighted column sums vectorise without a remainder.
constexpr int kMoments = 21;
constexpr int kTableRows = 22;
using TableColumn = Eigen::Matrix<double, kTableRows, 1>;

/// A fit to dense samples takes at most this many times the working fit's neighbours.
constexpr int kDenseFitCap = 8;

/// kProduct[i][j]: the monomial of the table that is basis i times basis j.
constexpr int kProduct[6][6] = {{0, 1, 2, 3, 4, 5},    {1, 3, 4, 6, 7, 8},
                                {2, 4, 5, 7, 8, 9},    {3, 6, 7, 10, 11, 12},
                                {4, 7, 8, 11, 12, 13}, {5, 8, 9, 12, 13, 14}};

/// Solves normal · x = rhs in place (x returned in \a rhs) for a symmetric positive definite
/// 6 × 6 \a normal, by a Cholesky factorisation written out: every refit solves one, and
/// Eigen's LLT runs its general loops out of line even at this fixed size. False when
/// \a normal is not positive definite.
bool
solveSmallCholesky(Eigen::Matrix<double, 6, 6>& normal, Eigen::Matrix<double, 6, 1>& rhs)
{
  Eigen::Matrix<double, 6, 6>& l = normal; // the lower triangle becomes the factor
  for (int j = 0; j < 6; ++j) {
    double d = l(j, j);
    for (int k = 0; k < j; ++k)
      d -= l(j, k) * l(j, k);
    if (!(d > 0.0))
      return false;
    const double root = std::sqrt(d);
    l(j, j) = root;
    for (int i = j + 1; i < 6; ++i) {
      double v = l(i, j);
      for (int k = 0; k < j; ++k)
        v -= l(i, k) * l(j, k);
      l(i, j) = v / root;
    }
  }
  for (int i = 0; i < 6; ++i) { // L y = rhs
    for (int k = 0; k < i; ++k)
      rhs[i] -= l(i, k) * rhs[k];
    rhs[i] /= l(i, i);
  }
  for (int i = 5; i >= 0; --i) { // Lᵀ x = y
    for (int k = i + 1; k < 6; ++k)
      rhs[i] -= l(k, i) * rhs[k];
    rhs[i] /= l(i, i);
  }
  return true;
}

/// Where point \a at lies on its own side of the surface: a quadratic height field over the
/// neighbourhood's PCA tangent plane, fitted with spatial weights exp(−d²/support²) times
/// Gaussian weights (bandwidth \a band) on each neighbour's residual, refitted a few times
/// from the plane through the point itself. \a nn (with squared distances \a d2 from \a at) index
/// \a points, which need not hold \a at. The residual weights are what keep the two sides of
/// a thin wall apart: a plain fit over neighbours from both sides lands in the middle of the
/// wall and flattens the wall into one sheet (the winding number then sees no volume there).
Eigen::Vector3f
sidedHeightFit(const Eigen::Vector3f& at, const std::vector<Eigen::Vector3f>& points,
               const pcl::Indices& nn, const std::vector<float>& d2, double support, double band)
{
  const auto pca = neighbourhoodPca(points, nn);
  const Eigen::Vector3d n = pca.eigenvectors().col(0),
                        e1 = pca.eigenvectors().col(1) / support,
                        e2 = pca.eigenvectors().col(2) / support;
  const Eigen::Vector3d origin = at.cast<double>();
  const Eigen::Index m = static_cast<Eigen::Index>(nn.size());
  // The fit runs for every sample in every pass. Each refit is a weighted sum over the
  // neighbours of their monomials u^a v^b (a + b <= 4: the normal matrix) and of their heights
  // times the basis (the right-hand side), so the monomials are tabulated once per sample and
  // every refit is one vectorised exp and one pass of fixed-size column sums. The weights need
  // no more than float precision; the sums are in double. Per-thread buffers.
  thread_local Eigen::Matrix<double, kTableRows, Eigen::Dynamic> table;
  thread_local Eigen::ArrayXd height;
  thread_local Eigen::ArrayXf spatial, exponent;
  if (table.cols() < m) { // grown, never shrunk: no allocation per sample
    table.resize(kTableRows, m);
    height.resize(m);
    spatial.resize(m);
    exponent.resize(m);
  }
  for (Eigen::Index a = 0; a < m; ++a) {
    const Eigen::Vector3d d = points[nn[std::size_t(a)]].cast<double>() - origin;
    const double u = d.dot(e1), v = d.dot(e2); // unit-free: well posed
    const double h = d.dot(n);
    const double uu = u * u, uv = u * v, vv = v * v;
    table.col(a) << 1.0, u, v, uu, uv, vv,           // the basis
        uu * u, uu * v, u * vv, vv * v,              // degree 3
        uu * uu, uu * uv, uu * vv, uv * vv, vv * vv, // degree 4
        h, h * u, h * v, h * uu, h * uv, h * vv,     // the height times the basis
        0.0;                                         // padding
    height[a] = h;
    spatial[a] = float(-double(d2[std::size_t(a)]) / (support * support));
  }
  spatial.head(m) = spatial.head(m).exp();
  // From the plane through the point, with a wide residual band that narrows: a narrow band at
  // once would leave too few neighbours on a curved surface to fix six coefficients. A small
  // ridge on the curvature terms keeps the fit posed where few neighbours remain.
  Eigen::Matrix<double, 6, 1> coef = Eigen::Matrix<double, 6, 1>::Zero();
  const double bands[] = {4.0 * band, 2.0 * band, band, band};
  for (int round = 0; round < 4; ++round) {
    const double inv_band2 = 1.0 / (2.0 * bands[round] * bands[round]);
    for (Eigen::Index a = 0; a < m; ++a) { // residual from the fit (round 0: the plane)
      const double r = height[a] - table.col(a).head<6>().dot(coef);
      exponent[a] = float(-r * r * inv_band2);
    }
    exponent.head(m) = exponent.head(m).exp(); // on its own, so that Eigen vectorises it
    TableColumn column_sum = TableColumn::Zero();
    for (Eigen::Index a = 0; a < m; ++a)
      column_sum.noalias() += double(spatial[a] * exponent[a]) * table.col(a);
    const Eigen::Matrix<double, kMoments, 1> sum = column_sum.head<kMoments>();
    const double total = sum[0];
    if (!(total > 1e-6))
      break;
    Eigen::Matrix<double, 6, 6> normal;
    for (int i = 0; i < 6; ++i)
      for (int j = 0; j < 6; ++j)
        normal(i, j) = sum[kProduct[i][j]];
    for (int k = 3; k < 6; ++k)
      normal(k, k) += 1e-3 * total;
    // The ridge keeps the curvature terms posed; Cholesky fails only where the neighbours fix
    // no plane.
    Eigen::Matrix<double, 6, 1> next = sum.tail<6>();
    if (!solveSmallCholesky(normal, next) || !next.allFinite())
      break;
    coef = next;
  }
  return (origin + coef[0] * n).cast<float>();
}

} // namespace

double
median(std::vector<float> values)
{
  if (values.empty())
    return 0.0;
  std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
  return double(values[values.size() / 2]);
}

namespace {

/// Offset of near[0] from the PCA plane through the mean of \a near (itself included). With
/// few neighbours a plane is all that can be fitted; it takes the curvature for noise.
double
planeOffset(const std::vector<Eigen::Vector3f>& positions, const pcl::Indices& near)
{
  const auto pca = neighbourhoodPca(positions, near);
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (int j : near)
    mean += positions[j].cast<double>();
  mean /= double(near.size());
  return std::abs((positions[near[0]].cast<double>() - mean).dot(pca.eigenvectors().col(0)));
}

/// Offset of near[0] from the quadratic height field fitted to the other samples of \a near
/// over their PCA plane, divided by sqrt(1 + h) (h the fit's variance at the sample in units of
/// σ²), so that for pure noise it is a draw of N(0, σ²): the quadratic absorbs the curvature
/// that a plane would count as noise.
double
quadraticOffset(const std::vector<Eigen::Vector3f>& positions, const pcl::Indices& near,
                const std::vector<float>& d2)
{
  const auto pca = neighbourhoodPca(positions, near);
  const Eigen::Vector3d n = pca.eigenvectors().col(0), e1 = pca.eigenvectors().col(1),
                        e2 = pca.eigenvectors().col(2);
  const Eigen::Vector3d origin = positions[near[0]].cast<double>();
  const double support = std::sqrt(double(d2.back()));
  if (!(support > 0.0))
    return 0.0;
  Eigen::Matrix<double, 6, 6> normal = Eigen::Matrix<double, 6, 6>::Zero();
  Eigen::Matrix<double, 6, 1> rhs = Eigen::Matrix<double, 6, 1>::Zero();
  for (std::size_t a = 1; a < near.size(); ++a) {
    const Eigen::Vector3d d = positions[near[a]].cast<double>() - origin;
    const double u = d.dot(e1) / support, v = d.dot(e2) / support;
    Eigen::Matrix<double, 6, 1> b;
    b << 1.0, u, v, u * u, u * v, v * v;
    normal += b * b.transpose();
    rhs += d.dot(n) * b;
  }
  const Eigen::LDLT<Eigen::Matrix<double, 6, 6>> solver(normal);
  if (solver.info() != Eigen::Success || !(solver.rcond() > 1e-9))
    return planeOffset(positions, near);
  const Eigen::Matrix<double, 6, 1> coef = solver.solve(rhs);
  const Eigen::Matrix<double, 6, 1> unit = Eigen::Matrix<double, 6, 1>::Unit(0);
  const double h = unit.dot(solver.solve(unit));
  return std::abs(coef[0]) / std::sqrt(1.0 + h);
}

} // namespace

SurfaceNoise
estimateSurfaceNoise(const std::vector<Eigen::Vector3f>& positions,
                     const SampleNeighbourhoods& neighbourhoods, int stride, int threads)
{
  const int n = static_cast<int>(positions.size());
  const int count = (n + stride - 1) / stride;
  std::vector<float> noise(count, 0.0f), spacing(count, 0.0f);
#pragma omp parallel num_threads(threads)
  {
    pcl::Indices near;
    std::vector<float> d2;
#pragma omp for schedule(static)
    for (int s = 0; s < count; ++s) {
      const int i = s * stride;
      neighbourhoods.close(i, near, d2);
      if (near.size() < 4)
        continue;
      noise[s] = float(near.size() >= 12 ? quadraticOffset(positions, near, d2)
                                         : planeOffset(positions, near));
      spacing[s] = std::sqrt(d2[1]); // [0] is the sample itself
    }
  }
  return {median(noise) / 0.6745, median(spacing)};
}

namespace {

/// Every stride-th sample is enough for the estimates' medians: at most ~5000 samples.
int
estimateStride(std::size_t samples)
{
  return std::max<int>(4, static_cast<int>(samples / 5000));
}

/// σ̂ of the samples as they are after denoising: what the grower may take as noise.
double
remainingNoise(const std::vector<Eigen::Vector3f>& positions, SampleNeighbourhoods& neighbourhoods,
               int threads)
{
  neighbourhoods.update(positions);
  return estimateSurfaceNoise(positions, neighbourhoods, estimateStride(positions.size()), threads)
      .sigma;
}

/// The input's samples before they were thinned to the working samples: every pass fits a
/// working sample to the dense samples around it, which hold several times the information
/// of its working neighbours over the same area. Their noise stays as it was, so the fits keep
/// the band of the input's noise.
struct DenseSamples
{
  const std::vector<Eigen::Vector3f>* points = nullptr;
  pcl::PointCloud<pcl::PointXYZ>::Ptr cloud;
  PointKdTree tree;
  int k = 0;                      ///< dense neighbours of a fit
  std::vector<pcl::Indices> near; ///< per working sample, its dense neighbours
  double band = 0.0;              ///< 0 until the noise of the input is estimated

  /// Finds the neighbours of every working sample where it is now (the kd-tree of the dense
  /// samples is built on the first call: a clean cloud never needs it).
  void
  search(const std::vector<Eigen::Vector3f>& positions, int threads)
  {
    if (!cloud) {
      cloud = toXYZ(*points);
      tree.setInputCloud(cloud);
    }
    near.resize(positions.size());
    const int n = static_cast<int>(positions.size());
#pragma omp parallel num_threads(threads)
    {
      std::vector<float> d2;
#pragma omp for schedule(static)
      for (int i = 0; i < n; ++i) {
        const pcl::PointXYZ at(positions[i].x(), positions[i].y(), positions[i].z());
        if (tree.nearestKSearch(at, k, near[std::size_t(i)], d2) <= 0)
          near[std::size_t(i)].clear();
      }
    }
  }
};

/// One pass of sided quadratic (MLS-like) smoothing: every sample moves onto the height field
/// of its own side fitted to its wide neighbourhood (sidedHeightFit), or to its \a dense
/// neighbours when given. A plane fit would pull thin tubes inwards by about a²/(4R) (a the
/// neighbourhood's size); a quadratic does not. The residual bandwidth is 1.5 × the samples'
/// noise (floored at a tenth of the spacing), or the dense samples' band. Nothing moves when
/// that noise is below \a min_noise_ratio × the spacing. The estimate goes to \a estimate when
/// given. Returns the median move divided by the median spacing (0 when nothing moved).
double
smoothSurface(std::vector<Eigen::Vector3f>& positions, SampleNeighbourhoods& neighbourhoods,
              int threads, double min_noise_ratio, SurfaceNoise* estimate,
              DenseSamples* dense = nullptr)
{
  const int n = static_cast<int>(positions.size());
  if (n < 6)
    return 0.0;
  neighbourhoods.update(positions);
  // A quarter of the samples tells the noise as well as all of them, at a quarter of the cost
  // that a clean input pays for finding out it is clean.
  const SurfaceNoise found =
      estimateSurfaceNoise(positions, neighbourhoods, estimateStride(positions.size()), threads);
  if (estimate)
    *estimate = found;
  const double noise = found.sigma, spacing = found.spacing;
  const double band =
      dense && dense->band > 0.0 ? dense->band : std::max(1.5 * noise, 0.1 * spacing);
  if (!(spacing > 0.0) || noise < min_noise_ratio * spacing)
    return 0.0;
  if (dense && dense->near.empty())
    dense->search(positions, threads);
  std::vector<Eigen::Vector3f> moved(positions);
  std::vector<float> moves(n, 0.0f);
  const std::vector<Eigen::Vector3f>& source = dense ? *dense->points : positions;
#pragma omp parallel num_threads(threads)
  {
    pcl::Indices nn;
    std::vector<float> d2;
#pragma omp for schedule(static)
    for (int i = 0; i < n; ++i) {
      if (dense) {
        // Later passes move the samples by far less than the neighbourhood's size, so the
        // neighbours found after the opening pass serve them all; only the distances change.
        nn = dense->near[std::size_t(i)];
        d2.resize(nn.size());
        for (std::size_t a = 0; a < nn.size(); ++a)
          d2[a] = ((*dense->points)[nn[a]] - positions[i]).squaredNorm();
        if (!nn.empty()) { // the farthest last, as the fit reads its support there
          const auto far = std::max_element(d2.begin(), d2.end()) - d2.begin();
          std::swap(nn[std::size_t(far)], nn.back());
          std::swap(d2[std::size_t(far)], d2.back());
        }
      }
      else
        neighbourhoods.wide(i, nn, d2);
      if (nn.size() < 6 || !(d2.back() > 0.0f))
        continue;
      moved[i] = sidedHeightFit(positions[i], source, nn, d2, std::sqrt(double(d2.back())), band);
      moves[i] = (moved[i] - positions[i]).norm();
    }
  }
  positions.swap(moved);
  return median(moves) / spacing;
}

/// Nearest samples in space, from a kd-tree rebuilt on every update.
class NearestNeighbourhoods : public SampleNeighbourhoods
{
public:
  explicit NearestNeighbourhoods(int k)
  : k_(k)
  {}

  void
  update(const std::vector<Eigen::Vector3f>& positions) override
  {
    count_ = static_cast<int>(positions.size());
    cloud_ = toXYZ(positions);
    tree_.setInputCloud(cloud_);
  }

  void
  close(int i, pcl::Indices& nn, std::vector<float>& d2) const override
  {
    search(i, std::min(8, count_), nn, d2);
  }

  void
  wide(int i, pcl::Indices& nn, std::vector<float>& d2) const override
  {
    search(i, std::min(k_, count_), nn, d2);
  }

private:
  void
  search(int i, int k, pcl::Indices& nn, std::vector<float>& d2) const
  {
    if (tree_.nearestKSearch((*cloud_)[i], k, nn, d2) <= 0) {
      nn.clear();
      d2.clear();
    }
  }

  int k_;
  int count_ = 0;
  pcl::PointCloud<pcl::PointXYZ>::Ptr cloud_;
  PointKdTree tree_;
};

/// Rings of mesh vertices: fixed lists (the connectivity does not move), distances from the
/// current positions.
class RingNeighbourhoods : public SampleNeighbourhoods
{
public:
  RingNeighbourhoods(std::size_t vertex_count, const std::vector<Eigen::Vector3i>& faces, int k)
  : k_(k)
  {
    std::vector<std::vector<int>> ring(vertex_count);
    for (const Eigen::Vector3i& f : faces)
      for (int c = 0; c < 3; ++c) {
        const int a = f[c], b = f[(c + 1) % 3];
        if (a == b || a < 0 || b < 0 || std::size_t(a) >= vertex_count ||
            std::size_t(b) >= vertex_count)
          continue;
        ring[a].push_back(b);
        ring[b].push_back(a);
      }
    for (auto& r : ring) {
      std::sort(r.begin(), r.end());
      r.erase(std::unique(r.begin(), r.end()), r.end());
    }
    ring_ = std::move(ring);
  }

  /// Keeps every vertex's lists, for the smoothing passes that read each of them several times;
  /// without it, each call gathers them anew (a clean mesh's estimate reads a few thousand).
  void
  precompute()
  {
    const std::size_t n = ring_.size();
    close_.resize(n);
    rings_.resize(n);
    for (std::size_t v = 0; v < n; ++v)
      gather(int(v), close_[v], rings_[v]);
  }

  void
  update(const std::vector<Eigen::Vector3f>& positions) override
  {
    positions_ = &positions;
  }

  void
  close(int i, pcl::Indices& nn, std::vector<float>& d2) const override
  {
    list(i, false, nn, d2);
  }

  void
  wide(int i, pcl::Indices& nn, std::vector<float>& d2) const override
  {
    list(i, true, nn, d2);
  }

private:
  void
  list(int i, bool wide, pcl::Indices& nn, std::vector<float>& d2) const
  {
    if (rings_.empty()) {
      thread_local std::vector<int> near, around;
      gather(i, near, around);
      const std::vector<int>& chosen = wide ? around : near;
      nn.assign(chosen.begin(), chosen.end());
    } else {
      const std::vector<int>& chosen = wide ? rings_[i] : close_[i];
      nn.assign(chosen.begin(), chosen.end());
    }
    sortByDistance(i, nn, d2);
  }

  /// The consumers read only the sample itself (first), its nearest neighbour (second) and the
  /// farthest (last), so those three are put in place and the rest stay in ring order.
  void
  sortByDistance(int i, pcl::Indices& nn, std::vector<float>& d2) const
  {
    const std::vector<Eigen::Vector3f>& p = *positions_;
    d2.resize(nn.size());
    for (std::size_t a = 0; a < nn.size(); ++a)
      d2[a] = nn[a] == i ? -1.0f : (p[nn[a]] - p[i]).squaredNorm();
    auto place = [&](std::size_t to, std::size_t from) {
      std::swap(nn[to], nn[from]);
      std::swap(d2[to], d2[from]);
    };
    // Ties go to the earlier entry, so the arrangement does not depend on anything but the rings.
    auto pick = [&](std::size_t begin, std::size_t end, bool nearest) {
      std::size_t best = begin;
      for (std::size_t a = begin + 1; a < end; ++a)
        if (nearest ? d2[a] < d2[best] : d2[a] > d2[best])
          best = a;
      return best;
    };
    const std::size_t n = nn.size();
    if (n > 0)
      place(0, pick(0, n, true)); // the sample itself (-1)
    if (n > 1)
      place(1, pick(1, n, true));
    if (n > 2)
      place(n - 1, pick(2, n, false));
    d2[0] = 0.0f;
  }

  /// Breadth-first from \a v: \a close gets two rings, \a around the rings until they hold k_
  /// vertices (at most three), each in ring order.
  void
  gather(int v, std::vector<int>& close, std::vector<int>& around) const
  {
    thread_local std::vector<int> mark;
    thread_local int stamp = 0;
    if (mark.size() != ring_.size()) {
      mark.assign(ring_.size(), 0);
      stamp = 0;
    }
    ++stamp;
    close.clear();
    around.assign(1, v);
    mark[v] = stamp;
    std::size_t begin = 0;
    for (int depth = 0; depth < 3 && (depth < 2 || int(around.size()) < k_); ++depth) {
      const std::size_t end = around.size();
      for (std::size_t a = begin; a < end; ++a)
        for (int w : ring_[around[a]])
          if (mark[w] != stamp) {
            mark[w] = stamp;
            around.push_back(w);
          }
      begin = end;
      if (depth == 1)
        close = around;
    }
    if (close.empty())
      close = around;
  }

  int k_;
  std::vector<std::vector<int>> ring_;  // one ring per vertex
  std::vector<std::vector<int>> close_; // two rings (when precomputed)
  std::vector<std::vector<int>> rings_;
  const std::vector<Eigen::Vector3f>* positions_ = nullptr;
};

} // namespace

namespace {

/// The passes of denoiseSurface(), fitting to \a dense when given.
SurfaceDenoising
smoothingPasses(std::vector<Eigen::Vector3f>& positions, SampleNeighbourhoods& neighbourhoods,
                int max_passes, int threads, double min_noise_ratio, DenseSamples* dense)
{
  constexpr double kStillRatio = 0.05;
  SurfaceDenoising result;
  for (int pass = 0; pass < max_passes; ++pass) {
    const double moved =
        smoothSurface(positions, neighbourhoods, threads, pass == 0 ? min_noise_ratio : 0.0,
                      pass == 0 ? &result.noise : nullptr, dense);
    // The opening pass moves the samples across the surface by about the noise; the later
    // passes fit around where they are then, which on a thin wall is the own side.
    if (dense && pass == 0) {
      dense->band = std::max(1.5 * result.noise.sigma, 0.1 * result.noise.spacing);
      if (moved >= kStillRatio)
        dense->search(positions, threads);
    }
    if (moved > 0.0)
      ++result.passes;
    if (moved < kStillRatio)
      break;
  }
  return result;
}

} // namespace

SurfaceDenoising
denoiseSurface(std::vector<Eigen::Vector3f>& positions, SampleNeighbourhoods& neighbourhoods,
               int max_passes, int threads, double min_noise_ratio)
{
  return smoothingPasses(positions, neighbourhoods, max_passes, threads, min_noise_ratio, nullptr);
}

SurfaceDenoising
denoiseCloudSurface(std::vector<Eigen::Vector3f>& positions, int k, int max_passes, int threads,
                    const std::vector<Eigen::Vector3f>* dense_points)
{
  NearestNeighbourhoods neighbourhoods(k);
  DenseSamples dense;
  const bool use_dense = dense_points && dense_points->size() > positions.size();
  if (use_dense) {
    // As many dense neighbours as the k working ones span, at most kDenseFitCap · k: the
    // fit's cost grows with them.
    const double ratio = double(dense_points->size()) / double(positions.size());
    dense.k = int(std::min(double(kDenseFitCap) * k, std::ceil(ratio * k)));
    dense.points = dense_points;
  }
  SurfaceDenoising result = smoothingPasses(positions, neighbourhoods, max_passes, threads, 0.1,
                                            use_dense ? &dense : nullptr);
  if (result.passes > 0)
    result.remaining_sigma = remainingNoise(positions, neighbourhoods, threads);
  return result;
}

double
medianFaceTurn(const std::vector<Eigen::Vector3d>& vertices,
               const std::vector<Eigen::Vector3i>& faces)
{
  const std::size_t nf = faces.size();
  std::vector<Eigen::Vector3d> normals(nf, Eigen::Vector3d::Zero());
  for (std::size_t f = 0; f < nf; ++f) {
    const Eigen::Vector3i& t = faces[f];
    const Eigen::Vector3d n =
        (vertices[t[1]] - vertices[t[0]]).cross(vertices[t[2]] - vertices[t[0]]);
    if (n.norm() > 0.0)
      normals[f] = n.normalized();
  }
  // Faces by undirected edge, sorted: neighbours are consecutive entries with the same edge.
  std::vector<std::tuple<int, int, int>> edges;
  edges.reserve(3 * nf);
  for (std::size_t f = 0; f < nf; ++f)
    for (int c = 0; c < 3; ++c) {
      const int a = faces[f][c], b = faces[f][(c + 1) % 3];
      edges.emplace_back(std::min(a, b), std::max(a, b), int(f));
    }
  std::sort(edges.begin(), edges.end());
  std::vector<float> turn(nf, 180.0f);
  for (std::size_t i = 0; i < edges.size();) {
    std::size_t j = i;
    while (j < edges.size() && std::get<0>(edges[j]) == std::get<0>(edges[i]) &&
           std::get<1>(edges[j]) == std::get<1>(edges[i]))
      ++j;
    for (std::size_t a = i; a < j; ++a)
      for (std::size_t b = a + 1; b < j; ++b) {
        const int fa = std::get<2>(edges[a]), fb = std::get<2>(edges[b]);
        if (normals[fa].isZero() || normals[fb].isZero())
          continue;
        const double cosine = std::clamp(normals[fa].dot(normals[fb]), -1.0, 1.0);
        const float degrees = float(std::acos(cosine) * 180.0 / M_PI);
        turn[fa] = std::min(turn[fa], degrees);
        turn[fb] = std::min(turn[fb], degrees);
      }
    i = j;
  }
  return median(turn);
}

SurfaceDenoising
denoiseMeshSurface(std::vector<Eigen::Vector3d>& vertices,
                   const std::vector<Eigen::Vector3i>& faces, int k, int max_passes, int threads,
                   double noisy_degrees)
{
  SurfaceDenoising result;
  result.face_turn_degrees = medianFaceTurn(vertices, faces);
  std::vector<Eigen::Vector3f> positions(vertices.size());
  for (std::size_t i = 0; i < vertices.size(); ++i)
    positions[i] = vertices[i].cast<float>();
  RingNeighbourhoods neighbourhoods(positions.size(), faces, k);
  neighbourhoods.update(positions);
  const bool noisy = result.face_turn_degrees >= noisy_degrees;
  // A noisy mesh reads every vertex's rings in each pass: gathered once, they serve the
  // estimate too. A clean one reads only the estimate's few thousand.
  if (noisy)
    neighbourhoods.precompute();
  result.noise =
      estimateSurfaceNoise(positions, neighbourhoods, estimateStride(positions.size()), threads);
  if (!noisy)
    return result; // clean: only the estimate, for the report
  const SurfaceDenoising found = result;
  // The passes fit with a residual band of 1.5 σ̂ and round off whatever is smaller. Bilateral
  // normal filtering first, with σ_r as wide as the turn that the noise puts between adjacent
  // faces, removes most of the noise; the passes then fit with the band of what is left, and
  // the surface ends closer to the clean one (docs/noise.md).
  const FaceNeighbourhoods around(faces, vertices.size());
  NormalFilterSettings first;
  first.range_from_normals = true;
  bilateralNormalFilter(vertices, faces, around, first, threads);
  for (std::size_t i = 0; i < vertices.size(); ++i)
    positions[i] = vertices[i].cast<float>();
  result = denoiseSurface(positions, neighbourhoods, max_passes, threads, 0.0);
  result.noise = found.noise; // the input's noise, not what the filter left
  result.face_turn_degrees = found.face_turn_degrees;
  for (std::size_t i = 0; i < vertices.size(); ++i)
    vertices[i] = positions[i].cast<double>();
  // The quadratic passes leave CAD faces and the rims of thin parts wavy and their creases
  // rounded. Bilateral normal filtering with the fixed σ_r flattens what is nearly flat and
  // keeps every turn much larger than 20°, so faces become planes again.
  result.normal_iterations =
      bilateralNormalFilter(vertices, faces, around, {}, threads).normal_iterations;
  // The passes and the filter move vertices across the surface only; the noise along it stays
  // and stretches edges, and the sampler would fill them with samples that make the MAT (and
  // with it the structured MAT's target) grow with the noise. Two σ undoes most of it.
  relaxTangentially(vertices, faces, around, 2.0 * result.noise.sigma, 5, threads);
  for (std::size_t i = 0; i < vertices.size(); ++i)
    positions[i] = vertices[i].cast<float>();
  result.remaining_sigma = remainingNoise(positions, neighbourhoods, threads);
  return result;
}

} // namespace detail
} // namespace segmat
