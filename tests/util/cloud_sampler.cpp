/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include "cloud_sampler.h"
#include "../../bench/shape_variants.h"

#include <segmat/segmentation/cloud_segmentation.h>


#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace segmat {
namespace test {
namespace {

constexpr double kPi = 3.14159265358979323846;

Eigen::Vector3d
uniformOnSphere(std::mt19937& rng)
{
  const double z = 2.0 * uniform01(rng) - 1.0;
  const double phi = 2.0 * kPi * uniform01(rng);
  const double s = std::sqrt(std::max(0.0, 1.0 - z * z));
  return {s * std::cos(phi), s * std::sin(phi), z};
}

/// Distance from x to the segment [a, b].
double
segmentDistance(const Eigen::Vector3d& x, const Eigen::Vector3d& a, const Eigen::Vector3d& b)
{
  const Eigen::Vector3d ab = b - a;
  const double t = std::clamp((x - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
  return (x - (a + t * ab)).norm();
}

/// A point on the capsule around [a, b] with radius r, area-uniform; returns the normal too.
void
sampleCapsule(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double r, std::mt19937& rng,
              Eigen::Vector3d& point, Eigen::Vector3d& normal)
{
  const Eigen::Vector3d axis = (b - a).normalized();
  const double length = (b - a).norm();
  const double cylinder = 2.0 * kPi * r * length, caps = 4.0 * kPi * r * r;
  if (uniform01(rng) * (cylinder + caps) < cylinder) {
    const Eigen::Vector3d u = axis.unitOrthogonal(), v = axis.cross(u);
    const double phi = 2.0 * kPi * uniform01(rng);
    normal = std::cos(phi) * u + std::sin(phi) * v;
    point = a + uniform01(rng) * length * axis + r * normal;
  }
  else {
    normal = uniformOnSphere(rng);
    point = (normal.dot(axis) < 0.0 ? a : b) + r * normal;
  }
}

void
push(SampledCloud& cloud, const Eigen::Vector3d& p, const Eigen::Vector3d& n, int source)
{
  cloud.points.push_back(p.cast<float>());
  cloud.normals.push_back(n.cast<float>());
  cloud.source.push_back(source);
}

} // namespace

pcl::PointCloud<pcl::PointNormal>::Ptr
SampledCloud::toPointNormal() const
{
  return toCloud<pcl::PointNormal>();
}

pcl::PointCloud<pcl::PointXYZ>::Ptr
SampledCloud::toPointXYZ() const
{
  return toCloud<pcl::PointXYZ>();
}

std::vector<int>
SampledCloud::pointLabels(const std::vector<int>& source_labels) const
{
  std::vector<int> labels(source.size());
  for (std::size_t i = 0; i < source.size(); ++i)
    labels[i] = source_labels.at(source[i]);
  return labels;
}

double
uniform01(std::mt19937& rng)
{
  const std::uint64_t hi = rng() >> 5, lo = rng() >> 6; // 27 + 26 bits
  return double((hi << 26) | lo) * (1.0 / 9007199254740992.0);
}

double
standardNormal(std::mt19937& rng)
{
  const double u = 1.0 - uniform01(rng); // (0, 1]
  const double v = uniform01(rng);
  return std::sqrt(-2.0 * std::log(u)) * std::cos(2.0 * kPi * v);
}

SampledCloud
sampleMesh(const TriangleMesh& mesh, std::size_t count, std::uint32_t seed)
{
  SampledCloud cloud;
  std::vector<double> cumulative(mesh.numFaces());
  double total = 0.0;
  for (std::size_t f = 0; f < mesh.numFaces(); ++f) {
    total += mesh.faceArea(static_cast<int>(f));
    cumulative[f] = total;
  }
  if (!(total > 0.0))
    return cloud;
  std::mt19937 rng(seed);
  cloud.points.reserve(count);
  cloud.normals.reserve(count);
  cloud.source.reserve(count);
  while (cloud.size() < count) {
    const double u = uniform01(rng) * total;
    const int f = static_cast<int>(
        std::min<std::ptrdiff_t>(std::upper_bound(cumulative.begin(), cumulative.end(), u) -
                                     cumulative.begin(),
                                 std::ptrdiff_t(cumulative.size()) - 1));
    if (mesh.faceArea(f) <= 0.0)
      continue;
    const Eigen::Vector3i& t = mesh.faces[f];
    const double s = std::sqrt(uniform01(rng)), r2 = uniform01(rng);
    const Eigen::Vector3d p = (1.0 - s) * mesh.vertices[t[0]] + s * (1.0 - r2) * mesh.vertices[t[1]] +
                              s * r2 * mesh.vertices[t[2]];
    push(cloud, p, mesh.faceNormal(f), f);
  }
  return cloud;
}

/// Moves every point by Gaussian noise of sigma = fraction × the points' bounding-box diagonal.
template <typename Vector3>
void
addGaussianNoiseTo(std::vector<Vector3>& points, double fraction, std::uint32_t seed)
{
  if (points.empty())
    return;
  Vector3 lo = points.front(), hi = lo;
  for (const Vector3& p : points) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  const double sigma = fraction * (hi - lo).template cast<double>().norm();
  std::mt19937 rng(seed);
  for (Vector3& p : points)
    for (int k = 0; k < 3; ++k)
      p[k] += static_cast<typename Vector3::Scalar>(sigma * standardNormal(rng));
}

void
addGaussianNoise(SampledCloud& cloud, double fraction, std::uint32_t seed)
{
  addGaussianNoiseTo(cloud.points, fraction, seed);
}

void
addGaussianNoise(TriangleMesh& mesh, double fraction, std::uint32_t seed)
{
  addGaussianNoiseTo(mesh.vertices, fraction, seed);
}

SampledCloud
dumbbellCloud(std::size_t count, std::uint32_t seed)
{
  const double R = 1.0, rho = 0.3, c = 3.0;
  const double inner = c - std::sqrt(R * R - rho * rho); // tube spans [-inner, inner]
  const double sphere_area = 4.0 * kPi * R * R, tube_area = 2.0 * kPi * rho * 2.0 * inner;
  std::mt19937 rng(seed);
  SampledCloud cloud;
  while (cloud.size() < count) {
    const double u = uniform01(rng) * (2.0 * sphere_area + tube_area);
    if (u < 2.0 * sphere_area) {
      const double side = u < sphere_area ? -1.0 : 1.0;
      const Eigen::Vector3d n = uniformOnSphere(rng);
      // Drop the cap hidden inside the tube.
      if (n.x() * side < 0.0 && n.y() * n.y() + n.z() * n.z() < rho * rho / (R * R))
        continue;
      push(cloud, Eigen::Vector3d(side * c, 0.0, 0.0) + R * n, n, side < 0.0 ? 0 : 2);
    }
    else {
      const double phi = 2.0 * kPi * uniform01(rng);
      const Eigen::Vector3d n(0.0, std::cos(phi), std::sin(phi));
      push(cloud, Eigen::Vector3d(-inner + 2.0 * inner * uniform01(rng), 0.0, 0.0) + rho * n, n,
           1);
    }
  }
  return cloud;
}

SampledCloud
lTubeCloud(std::size_t count, std::uint32_t seed)
{
  const double r = 0.5;
  const Eigen::Vector3d o(0, 0, 0), ex(4, 0, 0), ey(0, 4, 0);
  std::mt19937 rng(seed);
  SampledCloud cloud;
  while (cloud.size() < count) {
    const int arm = uniform01(rng) < 0.5 ? 0 : 1;
    Eigen::Vector3d p, n;
    sampleCapsule(o, arm == 0 ? ex : ey, r, rng, p, n);
    if (segmentDistance(p, o, arm == 0 ? ey : ex) < r * (1.0 - 1e-9))
      continue; // inside the other arm
    push(cloud, p, n, arm);
  }
  return cloud;
}

SampledCloud
sphereCloud(std::size_t count, std::uint32_t seed)
{
  std::mt19937 rng(seed);
  SampledCloud cloud;
  while (cloud.size() < count) {
    const Eigen::Vector3d n = uniformOnSphere(rng);
    push(cloud, n, n, 0);
  }
  return cloud;
}

SampledCloud
torusCloud(std::size_t count, std::uint32_t seed)
{
  const double R = 2.0, r = 0.5;
  std::mt19937 rng(seed);
  SampledCloud cloud;
  while (cloud.size() < count) {
    const double u = 2.0 * kPi * uniform01(rng), v = 2.0 * kPi * uniform01(rng);
    // Area element ∝ R + r cos v: rejection keeps the sampling area-uniform.
    if (uniform01(rng) * (R + r) > R + r * std::cos(v))
      continue;
    const Eigen::Vector3d n(std::cos(v) * std::cos(u), std::cos(v) * std::sin(u), std::sin(v));
    push(cloud, Eigen::Vector3d(R * std::cos(u), R * std::sin(u), 0.0) + r * n, n, 0);
  }
  return cloud;
}

SampledCloud
discCloud(std::size_t count, std::uint32_t seed)
{
  std::mt19937 rng(seed);
  SampledCloud cloud;
  while (cloud.size() < count) {
    const double rad = std::sqrt(uniform01(rng)), phi = 2.0 * kPi * uniform01(rng);
    push(cloud, Eigen::Vector3d(rad * std::cos(phi), rad * std::sin(phi), 0.0),
         Eigen::Vector3d::UnitZ(), 0);
  }
  return cloud;
}

double
randIndexError(const std::vector<int>& a, const std::vector<int>& b)
{
  if (b.size() != a.size())
    throw std::invalid_argument("randIndexError: labelings of different sizes");
  return bench::randDistance(a, b);
}

} // namespace test
} // namespace segmat
