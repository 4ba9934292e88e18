/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include "local_fit.h"

#include <Eigen/QR>

#include <cmath>

namespace segmat {
namespace detail {
namespace {

/// Weighted least-squares fit of values_a ≈ c·basis_a, evaluated at basis_at_point. The basis
/// is ordered constant, linear, quadratic terms (1, t, t² or 1, u, v, u², uv, v²): the full
/// quadratic is tried first, then the linear and constant heads, as long as there are fewer
/// points than terms + 2 or the system is rank-deficient. Robust: two reweighting passes with
/// Cauchy weights 1 / (1 + (residual/scale)²), so that where two branches meet (the corner of
/// a bent tube) the fit follows the branch the point is on instead of bending between both.
template <int Dim>
Eigen::Matrix<double, Dim, 1>
fitAndEvaluate(const std::vector<Eigen::VectorXd>& basis, const std::vector<double>& weights,
               const std::vector<Eigen::Matrix<double, Dim, 1>>& values,
               const Eigen::VectorXd& basis_at_point, double scale)
{
  const int terms = static_cast<int>(basis_at_point.size());
  const int linear = terms == 6 ? 3 : 2;
  for (int used : {terms, linear, 1}) {
    if (used > 1 && static_cast<int>(basis.size()) < used + 2)
      continue;
    std::vector<double> robust(basis.size(), 1.0);
    Eigen::MatrixXd coefficients;
    bool solved = true;
    for (int pass = 0; pass < 3 && solved; ++pass) {
      Eigen::MatrixXd gram = Eigen::MatrixXd::Zero(used, used);
      Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(used, Dim);
      for (std::size_t a = 0; a < basis.size(); ++a) {
        const Eigen::VectorXd phi = basis[a].head(used);
        const double w = weights[a] * robust[a];
        gram += w * phi * phi.transpose();
        rhs += w * phi * values[a].transpose();
      }
      const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(gram);
      solved = qr.rank() == used;
      if (!solved)
        break;
      coefficients = qr.solve(rhs);
      for (std::size_t a = 0; a < basis.size(); ++a) {
        const double residual =
            (values[a] - coefficients.transpose() * basis[a].head(used)).norm() / scale;
        robust[a] = 1.0 / (1.0 + residual * residual);
      }
    }
    if (solved)
      return coefficients.transpose() * basis_at_point.head(used);
  }
  return Eigen::Matrix<double, Dim, 1>::Zero();
}

} // namespace

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
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for (int j : nn) {
    const Eigen::Vector3d d = points[j].cast<double>() - mean;
    cov += d * d.transpose();
  }
  return Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(cov / double(nn.size()));
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
  if (shape == LocalShape::Unknown)
    shape = classifyShape(pca.eigenvalues());
  const Eigen::Matrix3d& frame = pca.eigenvectors(); // columns: smallest .. largest
  const Eigen::Vector3d own = points[self].cast<double>() - mean;
  const double scale = residual_scale;
  std::vector<Eigen::VectorXd> basis(nn.size());
  if (shape == LocalShape::Curve) {
    // across(t) in the (e0, e1) plane, t along e2.
    std::vector<Eigen::Vector2d> across(nn.size());
    for (std::size_t a = 0; a < nn.size(); ++a) {
      const Eigen::Vector3d d = points[nn[a]].cast<double>() - mean;
      const double t = d.dot(frame.col(2));
      basis[a] = Eigen::Vector3d(1.0, t, t * t);
      across[a] = Eigen::Vector2d(d.dot(frame.col(0)), d.dot(frame.col(1)));
    }
    const double t = own.dot(frame.col(2));
    const Eigen::Vector2d fit =
        fitAndEvaluate<2>(basis, weights, across, Eigen::Vector3d(1.0, t, t * t), scale);
    return mean + t * frame.col(2) + fit[0] * frame.col(0) + fit[1] * frame.col(1);
  }
  if (shape == LocalShape::Sheet) {
    // height(u, v) along e0 over the (e1, e2) plane.
    std::vector<Eigen::Matrix<double, 1, 1>> height(nn.size());
    auto phi = [](double u, double v) {
      Eigen::VectorXd b(6);
      b << 1.0, u, v, u * u, u * v, v * v;
      return b;
    };
    for (std::size_t a = 0; a < nn.size(); ++a) {
      const Eigen::Vector3d d = points[nn[a]].cast<double>() - mean;
      basis[a] = phi(d.dot(frame.col(1)), d.dot(frame.col(2)));
      height[a](0) = d.dot(frame.col(0));
    }
    const double u = own.dot(frame.col(1)), v = own.dot(frame.col(2));
    const double h = fitAndEvaluate<1>(basis, weights, height, phi(u, v), scale)(0);
    return mean + u * frame.col(1) + v * frame.col(2) + h * frame.col(0);
  }
  return mean; // blob
}

} // namespace detail
} // namespace segmat
