/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include "../common/checked_setter.h"
#include <segmat/medial/shrinking_ball_estimation.h>

#include "../common/point_kd_tree.h"
#include "../common/thread_count.h"
#include "local_fit.h"

#include <pcl/console/print.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace segmat {
namespace {

constexpr double kPi = 3.14159265358979323846;

struct Ball
{
  double radius = std::numeric_limits<double>::quiet_NaN();
  int contact = -1;
  double separation = std::numeric_limits<double>::quiet_NaN();
};

} // namespace

ShrinkingBallEstimation::ShrinkingBallEstimation()
: initial_radius_(0.0f)
, preserve_angle_(static_cast<float>(20.0 * kPi / 180.0))
, planar_angle_(static_cast<float>(32.0 * kPi / 180.0))
, max_iterations_(30)
, threads_(0)
{}

void
ShrinkingBallEstimation::setInitialRadius(float radius)
{
  detail::assignChecked(initial_radius_, radius, radius >= 0.0f && std::isfinite(radius),
                        "ShrinkingBallEstimation::setInitialRadius", "finite and >= 0");
}

void
ShrinkingBallEstimation::setDenoisePreserveAngle(float angle)
{
  detail::assignChecked(preserve_angle_, angle, angle >= 0.0f && angle <= kPi,
                        "ShrinkingBallEstimation::setDenoisePreserveAngle", "in [0, pi]");
}

void
ShrinkingBallEstimation::setDenoisePlanarAngle(float angle)
{
  detail::assignChecked(planar_angle_, angle, angle >= 0.0f && angle <= kPi,
                        "ShrinkingBallEstimation::setDenoisePlanarAngle", "in [0, pi]");
}

void
ShrinkingBallEstimation::setMaxIterations(int iterations)
{
  detail::assignChecked(max_iterations_, iterations, iterations > 0,
                        "ShrinkingBallEstimation::setMaxIterations", "positive");
}

bool
ShrinkingBallEstimation::compute(pcl::PointCloud<MedialPoint>& balls)
{
  balls.clear();
  separation_angles_.clear();
  if (!input_ || input_->size() < 2) {
    PCL_ERROR("[segmat::ShrinkingBallEstimation::compute] No input cloud, or fewer than 2 "
              "points.\n");
    return false;
  }
  const SurfaceCloud& surface = *input_;
  const int n = static_cast<int>(surface.size());
  std::vector<int> all;
  if (!indices_) {
    all.resize(n);
    for (int i = 0; i < n; ++i)
      all[i] = i;
  }
  const std::vector<int>& selected = indices_ ? *indices_ : all;
  for (int i : selected)
    if (i < 0 || i >= n) {
      PCL_ERROR("[segmat::ShrinkingBallEstimation::compute] Index %d is out of range.\n", i);
      return false;
    }

  pcl::PointCloud<pcl::PointXYZ>::Ptr xyz(new pcl::PointCloud<pcl::PointXYZ>);
  xyz->resize(n);
  Eigen::Vector3f lo = surface[0].getVector3fMap(), hi = lo;
  for (int i = 0; i < n; ++i) {
    (*xyz)[i].getVector3fMap() = surface[i].getVector3fMap();
    lo = lo.cwiseMin(surface[i].getVector3fMap());
    hi = hi.cwiseMax(surface[i].getVector3fMap());
  }
  const double diagonal = (hi - lo).cast<double>().norm();
  const double r_init = initial_radius_ > 0.0f
                            ? double(initial_radius_)
                            : std::max(0.55 * double((hi - lo).minCoeff()), 1e-3 * diagonal);
  const double tolerance = 1e-5 * diagonal;
  detail::PointKdTree tree;
  tree.setInputCloud(xyz);

  const double preserve = preserve_angle_, planar = planar_angle_;
  const int max_iterations = max_iterations_;
  auto shrink = [&](int s, pcl::Indices& nn, std::vector<float>& d2) {
    const Eigen::Vector3d p = surface[s].getVector3fMap().cast<double>();
    const Eigen::Vector3d normal = surface[s].getNormalVector3fMap().cast<double>().normalized();
    Ball ball;
    double r = r_init;
    for (int it = 0; it < max_iterations; ++it) {
      const Eigen::Vector3d c = p - r * normal;
      pcl::PointXYZ query;
      query.getVector3fMap() = c.cast<float>();
      // Nearest sample other than p (duplicates of p were removed upstream; skip them anyway).
      int q = -1;
      for (int k : {2, 8}) {
        tree.nearestKSearch(query, std::min(k, n), nn, d2);
        for (int j : nn)
          if (j != s && (*xyz)[j].getVector3fMap() != (*xyz)[s].getVector3fMap()) {
            q = j;
            break;
          }
        if (q >= 0 || k >= n)
          break;
      }
      if (q < 0)
        break;
      const Eigen::Vector3d x = (*xyz)[q].getVector3fMap().cast<double>();
      // Converged: no sample strictly inside the ball.
      if (q == ball.contact || (x - c).norm() >= r * (1.0 - 1e-9))
        break;
      const Eigen::Vector3d d = p - x;
      const double dn = normal.dot(d);
      if (!(dn > 0.0)) // cannot happen for a sample strictly inside; guards rounding
        break;
      const double r_new = d.squaredNorm() / (2.0 * dn);
      const Eigen::Vector3d c_new = p - r_new * normal;
      const double separation = detail::angleBetween(p - c_new, x - c_new);
      if (ball.contact < 0 && separation < planar)
        return Ball{}; // planar or noisy spot: no interior ball
      if (ball.contact >= 0 && separation < preserve)
        break; // noise next to p: keep the previous ball
      const bool done = std::abs(r - r_new) < tolerance;
      r = r_new;
      ball.radius = r;
      ball.contact = q;
      ball.separation = separation;
      if (done)
        break;
    }
    return ball;
  };

  const int m = static_cast<int>(selected.size());
  std::vector<Ball> result(m);
  const int threads = detail::threadCount(threads_);
#pragma omp parallel num_threads(threads)
  {
    pcl::Indices nn;
    std::vector<float> d2;
#pragma omp for schedule(dynamic, 64)
    for (int i = 0; i < m; ++i)
      result[i] = shrink(selected[i], nn, d2);
  }

  balls.resize(m);
  separation_angles_.assign(m, std::numeric_limits<float>::quiet_NaN());
  balls.is_dense = true;
  const float nan = std::numeric_limits<float>::quiet_NaN();
  for (int i = 0; i < m; ++i) {
    const int s = selected[i];
    MedialPoint& out = balls[i];
    out.getNormalVector3fMap() = surface[s].getNormalVector3fMap();
    out.surface_index = s;
    out.contact_index = result[i].contact;
    if (result[i].contact < 0) {
      out.x = out.y = out.z = out.radius = nan;
      balls.is_dense = false;
      continue;
    }
    const Eigen::Vector3d c = surface[s].getVector3fMap().cast<double>() -
                              result[i].radius *
                                  surface[s].getNormalVector3fMap().cast<double>().normalized();
    out.getVector3fMap() = c.cast<float>();
    out.radius = static_cast<float>(result[i].radius);
    separation_angles_[i] = static_cast<float>(result[i].separation);
  }
  balls.width = static_cast<std::uint32_t>(m);
  balls.height = 1;
  return true;
}

} // namespace segmat
