/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once

#include <Eigen/Core>

namespace segmat {

/** \brief Sphere quadric error metric (SQEM) of Q-MAT (Li et al., "Q-MAT: Computing Medial Axis
 * Transform by Quadratic Error Minimization", ACM TOG 2015, §4).
 *
 * A sphere is the 4-vector m = (x, y, z, r). For a plane with normal n through the tangent point
 * of a sphere C = (c, r_c), with n̂ = (n, 1), the error of m is (n̂·(m − C))² = (n·(x − c) + r −
 * r_c)²: zero when m touches the plane from inside, d² when m pokes through it by d (for a unit
 * n). Sums of such terms are stored as Q(m) = ½·mᵀAm − bᵀm + c with A = 2·n̂n̂ᵀ,
 * b = 2·n̂(n̂·C), c = (n̂·C)² (Q-MAT, Li et al. 2015).
 */
class SphereQuadric
{
public:
  /** \brief The zero quadric. */
  SphereQuadric() = default;

  /** \brief The SQEM of one plane.
   * \param[in] normal plane normal n (unit for a true tangent plane; Q-MAT's boundary planes use
   *            non-unit normals on purpose)
   * \param[in] sphere a sphere C touching the plane (the plane passes through c + r_c·n)
   * \param[in] weight factor on the whole term
   */
  static SphereQuadric
  fromPlane(const Eigen::Vector3d& normal, const Eigen::Vector4d& sphere, double weight = 1.0);

  /** \brief Q(m) = ½·mᵀAm − bᵀm + c (may be a hair below 0 by rounding). */
  double
  operator()(const Eigen::Vector4d& m) const;

  /** \brief The sphere minimising Q: A·m = b.
   * \param[out] m the minimiser
   * \return false when |det A| <= 1e-12 (Q-MAT's Wm4 inverse tolerance); m untouched.
   */
  bool
  minimiser(Eigen::Vector4d& m) const;

  /** \brief True when |det A| > 1e-12 (the tolerance of minimiser()). */
  bool
  invertible() const;

  /** \brief Adds another quadric (the error of both plane sets). */
  SphereQuadric&
  operator+=(const SphereQuadric& o)
  {
    for (int i = 0; i < kSize; ++i)
      v_[i] += o.v_[i];
    return *this;
  }

  /** \brief Sum of two quadrics. */
  friend SphereQuadric
  operator+(SphereQuadric a, const SphereQuadric& o)
  {
    a += o;
    return a;
  }

  /** \brief The symmetric 4×4 matrix A (twice the quadratic form). */
  Eigen::Matrix4d
  A() const;
  /** \brief The linear term b. */
  Eigen::Vector4d
  b() const
  {
    return {v_[10], v_[11], v_[12], v_[13]};
  }
  /** \brief The constant c. */
  double
  c() const
  {
    return v_[14];
  }

private:
  // Packed: A's upper triangle row by row (00 01 02 03 11 12 13 22 23 33), b, c. 120 bytes, so
  // that simplifying a 100k-sphere MAT touches half the memory of a full Matrix4d.
  static constexpr int kSize = 15;
  double v_[kSize] = {};
};

/** \brief Q-MAT's stability ratio of a medial edge (Q-MAT's
 * `GetRatioHyperbolicEuclid`).
 *
 * ratio = max(0, |c0 − c1| − |r0 − r1|) / |c0 − c1| ∈ [0, 1]: 1 for equal radii, 0 when one
 * sphere contains the other (a spike) and for coincident centres.
 */
double
stabilityRatio(const Eigen::Vector4d& s0, const Eigen::Vector4d& s1);

} // namespace segmat
