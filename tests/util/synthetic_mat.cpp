#include "util/synthetic_mat.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

namespace segmat {
namespace test {

int
SyntheticMat::addSheet(const Eigen::Vector3d& origin, const Eigen::Vector3d& u,
                       const Eigen::Vector3d& v, int nu, int nv,
                       const std::function<double(double, double)>& radius)
{
  const int first = static_cast<int>(centers_.size());
  for (int i = 0; i <= nu; ++i)
    for (int j = 0; j <= nv; ++j) {
      const double s = static_cast<double>(i) / nu, t = static_cast<double>(j) / nv;
      centers_.push_back(origin + s * u + t * v);
      radii_.push_back(radius(s, t));
    }
  const auto at = [&](int i, int j) { return first + i * (nv + 1) + j; };
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) {
      triangles_.emplace_back(at(i, j), at(i + 1, j), at(i + 1, j + 1));
      triangles_.emplace_back(at(i, j), at(i + 1, j + 1), at(i, j + 1));
    }
  return first;
}

std::vector<int>
SyntheticMat::addChain(int start, const std::vector<Eigen::Vector3d>& points,
                       const std::vector<double>& radii, int end)
{
  std::vector<int> ids;
  for (std::size_t k = 0; k < points.size(); ++k) {
    if (k == 0 && start >= 0)
      ids.push_back(start);
    else if (k + 1 == points.size() && end >= 0)
      ids.push_back(end);
    else {
      ids.push_back(static_cast<int>(centers_.size()));
      centers_.push_back(points[k]);
      radii_.push_back(radii[k]);
    }
    if (ids.size() > 1)
      edges_.emplace_back(ids[ids.size() - 2], ids.back());
  }
  return ids;
}

namespace {
void
straight(const Eigen::Vector3d& a, const Eigen::Vector3d& b, int segments,
         const std::function<double(double)>& radius, std::vector<Eigen::Vector3d>& points,
         std::vector<double>& radii)
{
  for (int k = 0; k <= segments; ++k) {
    const double t = static_cast<double>(k) / segments;
    points.push_back(a + t * (b - a));
    radii.push_back(radius(t));
  }
}
} // namespace

std::vector<int>
SyntheticMat::connect(int start, int end, int segments,
                      const std::function<double(double)>& radius)
{
  std::vector<Eigen::Vector3d> points;
  std::vector<double> radii;
  straight(centers_[start], centers_[end], segments, radius, points, radii);
  return addChain(start, points, radii, end);
}

std::vector<int>
SyntheticMat::extend(int start, const Eigen::Vector3d& b, int segments,
                     const std::function<double(double)>& radius)
{
  std::vector<Eigen::Vector3d> points;
  std::vector<double> radii;
  straight(centers_[start], b, segments, radius, points, radii);
  return addChain(start, points, radii);
}

MedialMesh
SyntheticMat::build() const
{
  return MedialMesh(centers_, radii_, edges_, triangles_);
}

SegmentVisibility
unionOfBallsVisibility(const MedialMesh& mat, double step)
{
  auto centers = std::make_shared<std::vector<Eigen::Vector3d>>(mat.centers());
  auto radii = std::make_shared<std::vector<double>>(mat.radii());
  if (!(step > 0.0)) {
    double r_min = std::numeric_limits<double>::infinity();
    for (double r : *radii)
      if (r > 0.0)
        r_min = std::min(r_min, r);
    step = std::isfinite(r_min) ? 0.25 * r_min : 1.0;
  }
  return [centers, radii, step](const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
    const int samples = 1 + static_cast<int>(std::ceil((b - a).norm() / step));
    for (int k = 0; k <= samples; ++k) {
      const Eigen::Vector3d p = a + (static_cast<double>(k) / samples) * (b - a);
      bool inside = false;
      for (std::size_t s = 0; s < centers->size() && !inside; ++s)
        inside = ((*centers)[s] - p).norm() <= (*radii)[s];
      if (!inside)
        return false;
    }
    return true;
  };
}

} // namespace test
} // namespace segmat
