/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include "local_fit.h"

#include <Eigen/Cholesky>

#include <algorithm>
#include <cmath>

namespace segmat {
namespace detail {
namespace {

/// Weighted least-squares fit of values_a ≈ c·basis_a, evaluated at basis_at_point. The basis
/// is ordered constant, linear, quadratic terms (1, t, t² or 1, u, v, u², uv, v²): the full
/// quadratic is tried first, then the linear and constant heads, as long as there are fewer
/// points than terms + 2 or the system is rank-deficient. Robust: two reweighting passes with
/// Cauchy weights 1 / (1 + (residual/scale)²), so that where two branches meet (the corner of
/// a bent tube) the fit leans towards the branch the point is on.
using Basis = Eigen::Matrix<double, 6, 1>; ///< up to 6 terms; the unused tail is ignored
/// Small systems with a fixed maximum size: no heap allocation in the inner loop.
using SmallMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 6, 6>;

template <int Dim>
Eigen::Matrix<double, Dim, 1>
fitAndEvaluate(const std::vector<Basis>& basis, int terms, const std::vector<double>& weights,
               const std::vector<Eigen::Matrix<double, Dim, 1>>& values, const Basis& at,
               double scale)
{
  using SmallRhs = Eigen::Matrix<double, Eigen::Dynamic, Dim, 0, 6, Dim>;
  const int linear = terms == 6 ? 3 : 2;
  for (int used : {terms, linear, 1}) {
    if (used > 1 && static_cast<int>(basis.size()) < used + 2)
      continue;
    std::vector<double> robust(basis.size(), 1.0);
    SmallRhs coefficients;
    bool solved = true;
    for (int pass = 0; pass < 3 && solved; ++pass) {
      SmallMatrix gram = SmallMatrix::Zero(used, used);
      SmallRhs rhs = SmallRhs::Zero(used, Dim);
      for (std::size_t a = 0; a < basis.size(); ++a) {
        const auto phi = basis[a].head(used);
        const double w = weights[a] * robust[a];
        gram.noalias() += w * phi * phi.transpose();
        rhs.noalias() += w * phi * values[a].transpose();
      }
      const Eigen::LDLT<SmallMatrix> ldlt(gram);
      const auto d = ldlt.vectorD();
      solved =
          ldlt.info() == Eigen::Success && d.minCoeff() > 1e-10 * std::max(d.maxCoeff(), 1e-300);
      if (!solved)
        break;
      coefficients = ldlt.solve(rhs);
      for (std::size_t a = 0; a < basis.size(); ++a) {
        const double residual =
            (values[a] - coefficients.transpose() * basis[a].head(used)).norm() / scale;
        robust[a] = 1.0 / (1.0 + residual * residual);
      }
    }
    if (solved)
      return coefficients.transpose() * at.head(used);
  }
  return Eigen::Matrix<double, Dim, 1>::Zero();
}

} // namespace

double
angleBetween(const Eigen::Vector3d& a, const Eigen::Vector3d& b)
{
  const double la = a.norm(), lb = b.norm();
  if (la == 0.0 || lb == 0.0)
    return 0.0;
  return std::acos(std::clamp(a.dot(b) / (la * lb), -1.0, 1.0));
}

pcl::PointCloud<pcl::PointXYZ>::Ptr
toXYZ(const std::vector<Eigen::Vector3f>& points)
{
  pcl::PointCloud<pcl::PointXYZ>::Ptr cloud(new pcl::PointCloud<pcl::PointXYZ>);
  cloud->resize(points.size());
  for (std::size_t i = 0; i < points.size(); ++i)
    (*cloud)[i].getVector3fMap() = points[i];
  return cloud;
}

Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>
neighbourhoodPca(const std::vector<Eigen::Vector3f>& points, const pcl::Indices& nn)
{
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (int j : nn)
    mean += points[j].cast<double>();
  mean /= double(nn.size());
  // The six distinct entries only: this runs for every sample of every smoothing pass.
  double xx = 0.0, xy = 0.0, xz = 0.0, yy = 0.0, yz = 0.0, zz = 0.0;
  for (int j : nn) {
    const Eigen::Vector3d d = points[j].cast<double>() - mean;
    xx += d.x() * d.x();
    xy += d.x() * d.y();
    xz += d.x() * d.z();
    yy += d.y() * d.y();
    yz += d.y() * d.z();
    zz += d.z() * d.z();
  }
  Eigen::Matrix3d cov;
  cov << xx, xy, xz, xy, yy, yz, xz, yz, zz;
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver;
  solver.computeDirect(cov / double(nn.size()));
  return solver;
}

LocalShape
classifyShape(const Eigen::Vector3d& ascending_eigenvalues)
{
  constexpr double kThin = 0.1;
  const Eigen::Vector3d& e = ascending_eigenvalues;
  if (e[1] < kThin * e[2])
    return LocalShape::Curve;
  if (e[0] < kThin * e[1])
    return LocalShape::Sheet;
  return LocalShape::Blob;
}

Eigen::Vector3d
robustLineThrough(const std::vector<Eigen::Vector3f>& points, int self, const pcl::Indices& nn,
                  std::vector<double>* weights)
{
  const Eigen::Vector3d c = points[self].cast<double>();
  std::vector<Eigen::Vector3d> offsets(nn.size());
  std::vector<double> lengths;
  for (std::size_t a = 0; a < nn.size(); ++a) {
    offsets[a] = points[nn[a]].cast<double>() - c;
    if (nn[a] != self)
      lengths.push_back(offsets[a].norm());
  }
  if (weights)
    weights->assign(nn.size(), 1.0);
  if (lengths.size() < 3)
    return Eigen::Vector3d::Zero();
  std::nth_element(lengths.begin(), lengths.begin() + lengths.size() / 2, lengths.end());
  const double scale = 0.1 * lengths[lengths.size() / 2];
  if (!(scale > 0.0))
    return Eigen::Vector3d::Zero();
  auto inliers = [&](const Eigen::Vector3d& dir) {
    std::size_t count = 0;
    for (std::size_t a = 0; a < offsets.size(); ++a)
      if (nn[a] != self)
        count += (offsets[a] - offsets[a].dot(dir) * dir).norm() < 2.0 * scale;
    return count;
  };
  // Start from the best line through the point and one neighbour (most neighbours within two
  // scales; ties: the first), not from the PCA axis, which at a corner is the diagonal.
  Eigen::Vector3d t = Eigen::Vector3d::Zero();
  std::size_t best = 0;
  for (std::size_t a = 0; a < offsets.size(); ++a) {
    const double len = offsets[a].norm();
    if (nn[a] == self || !(len > 0.0))
      continue;
    const Eigen::Vector3d dir = offsets[a] / len;
    const std::size_t count = inliers(dir);
    if (count > best) {
      best = count;
      t = dir;
    }
  }
  if (best == 0)
    return Eigen::Vector3d::Zero();
  std::vector<double> w(nn.size(), 1.0);
  for (int pass = 0; pass < 3; ++pass) {
    for (std::size_t a = 0; a < offsets.size(); ++a) {
      const double r = (offsets[a] - offsets[a].dot(t) * t).norm() / scale;
      w[a] = 1.0 / (1.0 + r * r);
    }
    Eigen::Matrix3d moment = Eigen::Matrix3d::Zero();
    for (std::size_t a = 0; a < offsets.size(); ++a)
      moment += w[a] * offsets[a] * offsets[a].transpose();
    t = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(moment).eigenvectors().col(2);
  }
  for (std::size_t a = 0; a < offsets.size(); ++a) {
    const double r = (offsets[a] - offsets[a].dot(t) * t).norm() / scale;
    w[a] = 1.0 / (1.0 + r * r);
  }
  if (weights)
    weights->swap(w);
  return inliers(t) * 100 >= lengths.size() * 45 ? t : Eigen::Vector3d::Zero();
}

Eigen::Vector3d
medialDirection(const std::vector<Eigen::Vector3f>& points, int self, const pcl::Indices& nn)
{
  const auto pca = neighbourhoodPca(points, nn);
  if (pca.info() != Eigen::Success || !(pca.eigenvalues()[2] > 0.0))
    return Eigen::Vector3d::Zero();
  const LocalShape shape = classifyShape(pca.eigenvalues());
  if (shape == LocalShape::Curve)
    return pca.eigenvectors().col(2);
  const Eigen::Vector3d line =
      shape == LocalShape::Sheet ? robustLineThrough(points, self, nn) : Eigen::Vector3d::Zero();
  // (A PCA curve keeps its axis here: only the direction is wanted, and it is unbiased.)
  return line.isZero() ? Eigen::Vector3d(pca.eigenvectors().col(0)) : line;
}

Eigen::Vector3d
fitLocalStructure(const std::vector<Eigen::Vector3f>& points, int self, const pcl::Indices& nn,
                  const std::vector<float>& d2, double support, LocalShape shape,
                  double residual_scale)
{
  std::vector<double> weights(nn.size());
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  double weight = 0.0;
  for (std::size_t a = 0; a < nn.size(); ++a) {
    weights[a] = std::exp(-double(d2[a]) / (support * support));
    mean += weights[a] * points[nn[a]].cast<double>();
    weight += weights[a];
  }
  mean /= weight;
  const auto pca = neighbourhoodPca(points, nn);
  const Eigen::Matrix3d& frame = pca.eigenvectors(); // columns: smallest .. largest
  const Eigen::Vector3d own = points[self].cast<double>() - mean;
  const double scale = residual_scale;
  std::vector<Basis> basis(nn.size(), Basis::Zero());
  std::vector<double> line_weights;
  Eigen::Vector3d line = Eigen::Vector3d::Zero();
  if (shape == LocalShape::Unknown) {
    shape = classifyShape(pca.eigenvalues());
    // A curve, or a planar L (the corner of a bent tube, which PCA calls a sheet): fit along
    // the robust line through the point, so that the other branch does not tilt the axis.
    if (shape != LocalShape::Blob) {
      line = robustLineThrough(points, self, nn, &line_weights);
      if (!line.isZero())
        shape = LocalShape::Curve;
    }
  }
  if (shape == LocalShape::Curve) {
    // across(t) in the plane normal to the curve, t along it; about the point itself, with the
    // robust line's weights when it came from robustLineThrough (a corner), the PCA axis else.
    const Eigen::Vector3d t = line.isZero() ? Eigen::Vector3d(frame.col(2)) : line;
    const Eigen::Vector3d e0 = t.unitOrthogonal(), e1 = t.cross(e0);
    const Eigen::Vector3d origin =
        line.isZero() ? mean : Eigen::Vector3d(points[self].cast<double>());
    std::vector<Eigen::Vector2d> across(nn.size());
    for (std::size_t a = 0; a < nn.size(); ++a) {
      const Eigen::Vector3d d = points[nn[a]].cast<double>() - origin;
      const double s = d.dot(t) / support; // unit-free coordinates keep the system well posed
      basis[a].head<3>() << 1.0, s, s * s;
      across[a] = Eigen::Vector2d(d.dot(e0), d.dot(e1));
      if (!line_weights.empty())
        weights[a] *= line_weights[a];
    }
    const double s = (points[self].cast<double>() - origin).dot(t) / support;
    Basis at = Basis::Zero();
    at.head<3>() << 1.0, s, s * s;
    const Eigen::Vector2d fit = fitAndEvaluate<2>(basis, 3, weights, across, at, scale);
    return origin + s * support * t + fit[0] * e0 + fit[1] * e1;
  }
  if (shape == LocalShape::Sheet) {
    // height(u, v) along e0 over the (e1, e2) plane.
    std::vector<Eigen::Matrix<double, 1, 1>> height(nn.size());
    auto phi = [support](double u, double v) {
      u /= support; // unit-free coordinates keep the system well posed
      v /= support;
      Basis b;
      b << 1.0, u, v, u * u, u * v, v * v;
      return b;
    };
    for (std::size_t a = 0; a < nn.size(); ++a) {
      const Eigen::Vector3d d = points[nn[a]].cast<double>() - mean;
      basis[a] = phi(d.dot(frame.col(1)), d.dot(frame.col(2)));
      height[a](0) = d.dot(frame.col(0));
    }
    const double u = own.dot(frame.col(1)), v = own.dot(frame.col(2));
    const double h = fitAndEvaluate<1>(basis, 6, weights, height, phi(u, v), scale)(0);
    return mean + u * frame.col(1) + v * frame.col(2) + h * frame.col(0);
  }
  return mean; // blob
}

} // namespace detail
} // namespace segmat
