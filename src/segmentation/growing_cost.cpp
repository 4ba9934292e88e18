/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include <segmat/geometry/medial_primitives.h>
#include "growing_cost.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>

namespace segmat {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kInf = std::numeric_limits<double>::infinity();

/** First sphere of a (in its slot order) that b also has, or -1 (the reference's joints[0]). */
int
firstSharedSphere(const MatNode& a, const MatNode& b)
{
  for (int k = 0; k < a.size(); ++k)
    for (int l = 0; l < b.size(); ++l)
      if (a.v[k] == b.v[l])
        return a.v[k];
  return -1;
}

/** Unit direction of a cone (zero for a zero-length cone). */
Eigen::Vector3d
coneDirection(const MatNode& cone, const std::vector<Eigen::Vector3d>& centers)
{
  const Eigen::Vector3d d = centers[cone.v[1]] - centers[cone.v[0]];
  const double len = d.norm();
  return len > 0.0 ? Eigen::Vector3d(d / len) : Eigen::Vector3d::Zero();
}

/** Exactly zero (a NaN vector is not zero: its NaN must reach the cost, see combineGrowingCost). */
bool
isZero(const Eigen::Vector3d& v)
{
  return v.squaredNorm() == 0.0;
}

/** Normals of two sheet-like nodes turned towards the same side (compute_face_consistent_normal):
 * each towards the midpoint of the two centroids as seen from the first shared sphere. When a
 * normal is (nearly) perpendicular to that reference vector — coplanar nodes — its sign is noise,
 * so the two normals are simply made to agree (fix, see angleCost).
 */
void
orientNormals(const MatNode& a, const MatNode& b, const std::vector<Eigen::Vector3d>& centers,
              Eigen::Vector3d& na, Eigen::Vector3d& nb)
{
  na = a.normal;
  nb = b.normal;
  const int shared = firstSharedSphere(a, b);
  const Eigen::Vector3d pivot = shared >= 0 ? centers[shared] : a.centroid;
  const Eigen::Vector3d ref = 0.5 * (a.centroid + b.centroid) - pivot;
  const double tol = 1e-9 * ref.norm();
  const double sa = na.dot(ref), sb = nb.dot(ref);
  if (std::abs(sa) <= tol || std::abs(sb) <= tol) {
    if (na.dot(nb) < 0.0)
      na = -na;
    return;
  }
  if (sa < 0.0)
    na = -na;
  if (sb < 0.0)
    nb = -nb;
}

/** 180° − acos(|d·n|) in radians: a line against a sheet normal. */
double
lineSheetBend(const Eigen::Vector3d& d, const Eigen::Vector3d& n)
{
  if (isZero(d) || isZero(n))
    return 0.5 * kPi;
  return kPi - clampedAcos(std::abs(d.dot(n)));
}

/** Bend in radians between two cones. */
double
coneConeBend(const MatNode& a, const MatNode& b, const std::vector<Eigen::Vector3d>& centers)
{
  const int shared = firstSharedSphere(a, b);
  if (shared < 0) {
    const Eigen::Vector3d da = coneDirection(a, centers), db = coneDirection(b, centers);
    if (isZero(da) || isZero(db))
      return 0.5 * kPi;
    return clampedAcos(std::abs(da.dot(db)));
  }
  // From the joint to each cone's midpoint (MatNode::centroid of a cone is its midpoint).
  const Eigen::Vector3d ua = a.centroid - centers[shared], ub = b.centroid - centers[shared];
  if (isZero(ua) || isZero(ub))
    return 0.5 * kPi;
  return kPi - clampedAcos(ua.normalized().dot(ub.normalized()));
}

/** Bend in radians between two nodes (C_θ · π). */
double
bendAngle(const MatNode& a, const MatNode& b, const std::vector<Eigen::Vector3d>& centers)
{
  using K = MatNodeKind;
  if (a.kind == K::Cone && b.kind == K::Cone)
    return coneConeBend(a, b, centers);
  if (a.kind == K::Cone)
    return lineSheetBend(coneDirection(a, centers), b.normal);
  if (b.kind == K::Cone)
    return lineSheetBend(coneDirection(b, centers), a.normal);
  // Sheet-like pairs: slab/point normals.
  if (isZero(a.normal) || isZero(b.normal))
    return 0.5 * kPi;
  if (a.kind == K::Slab && b.kind == K::Slab) {
    Eigen::Vector3d na, nb;
    orientNormals(a, b, centers, na, nb);
    return clampedAcos(na.dot(nb));
  }
  // Point normals are unoriented (PCA): the undirected angle (checkPointCloudGrowing).
  return clampedAcos(std::abs(a.normal.dot(b.normal)));
}

double
slabSlabPrimitiveCost(const MatNode& a, const MatNode& b,
                      const std::vector<Eigen::Vector3d>& centers,
                      const std::vector<double>& radii)
{
  if (isZero(a.normal) || isZero(b.normal))
    return 1.0;
  Eigen::Vector3d na, nb;
  orientNormals(a, b, centers, na, nb);
  SlabSides sides_a, sides_b;
  const Eigen::Vector3d ca[3] = {centers[a.v[0]], centers[a.v[1]], centers[a.v[2]]};
  const Eigen::Vector3d cb[3] = {centers[b.v[0]], centers[b.v[1]], centers[b.v[2]]};
  const double ra[3] = {radii[a.v[0]], radii[a.v[1]], radii[a.v[2]]};
  const double rb[3] = {radii[b.v[0]], radii[b.v[1]], radii[b.v[2]]};
  if (!computeSlabSides(ca, ra, na, sides_a) || !computeSlabSides(cb, rb, nb, sides_b))
    return 1.0;
  return (clampedAcos(sides_a.normal[0].dot(sides_b.normal[0])) +
          clampedAcos(sides_a.normal[1].dot(sides_b.normal[1]))) /
         (2.0 * kPi);
}

double
coneConePrimitiveCost(const MatNode& a, const MatNode& b,
                      const std::vector<Eigen::Vector3d>& centers,
                      const std::vector<double>& radii)
{
  const int joint = firstSharedSphere(a, b);
  if (joint < 0)
    return 1.0;
  const int end0 = a.v[0] == joint ? a.v[1] : a.v[0];
  const int end1 = b.v[0] == joint ? b.v[1] : b.v[0];
  const Eigen::Vector3d& pc = centers[joint];
  const Eigen::Vector3d v0 = centers[end0] - pc, v1 = centers[end1] - pc;
  if (isZero(v0) || isZero(v1))
    return 1.0;
  const double beta = clampedAcos(v0.normalized().dot(v1.normalized()));
  const double phi = coneSlopeAngle(pc, radii[joint], centers[end0], radii[end0]) +
                     coneSlopeAngle(pc, radii[joint], centers[end1], radii[end1]);
  const double side_a = (beta + phi) / kPi;
  const double side_b = (2.0 * kPi - beta + phi) / kPi;
  // A side below 1 bends inwards; within 1e-9 of 1 it is flat (robustness fix, see header).
  constexpr double kFlat = 1.0 - 1e-9;
  const int inward = (side_a < kFlat ? 1 : 0) + (side_b < kFlat ? 1 : 0);
  return std::max(0.0, (side_a + side_b - 2.0 + inward) / 2.0);
}

} // namespace

double
radiusCost(const MatNode& a, const MatNode& b, double tolerance)
{
  if (std::isnan(a.mean_radius) || std::isnan(b.mean_radius))
    return std::numeric_limits<double>::quiet_NaN(); // std::min/max would drop the NaN
  const double lo = std::min(a.mean_radius, b.mean_radius);
  const double hi = std::max(a.mean_radius, b.mean_radius);
  if (!(lo > 0.0))
    return hi == 0.0 ? 0.0 : kInf; // guard r̄ = 0
  if (tolerance > 0.0)
    return std::max(0.0, hi - lo - tolerance) / lo;
  return hi / lo - 1.0;
}

double
angleCost(const MatNode& a, const MatNode& b, const std::vector<Eigen::Vector3d>& centers)
{
  return bendAngle(a, b, centers) / kPi;
}

double
primitiveCost(const MatNode& a, const MatNode& b, const std::vector<Eigen::Vector3d>& centers,
              const std::vector<double>& radii)
{
  using K = MatNodeKind;
  if (a.kind == K::Slab && b.kind == K::Slab)
    return slabSlabPrimitiveCost(a, b, centers, radii);
  if (a.kind == K::Cone && b.kind == K::Cone)
    return coneConePrimitiveCost(a, b, centers, radii);
  return 1.0; // cone–slab (undefined in the reference) and anything with a point
}

double
combineGrowingCost(double radius_cost, double angle_cost, double primitive_cost,
                   const GrowingCostWeights& weights)
{
  // A NaN term (NaN input data) makes the whole cost +inf: NaN never means "grow" (in
  // the authors' code NaN failed the rejecting comparison and so accepted the node).
  const bool use_primitive = weights.use_primitive_term;
  if (std::isnan(radius_cost) || std::isnan(angle_cost) ||
      (use_primitive && std::isnan(primitive_cost)))
    return kInf;
  const double inner = radius_cost + weights.alpha * angle_cost;
  return use_primitive ? std::min(inner, weights.lambda * primitive_cost) : inner;
}

double
growingCost(const MatGraph& graph, int i, int j, const GrowingCostWeights& weights)
{
  const MatNode& a = graph.node(i);
  const MatNode& b = graph.node(j);
  const double c_r = radiusCost(a, b, weights.radius_tolerance);
  const double c_theta = angleCost(a, b, graph.centers());
  const double c_mp =
      weights.use_primitive_term ? primitiveCost(a, b, graph.centers(), graph.radii()) : 1.0;
  return combineGrowingCost(c_r, c_theta, c_mp, weights);
}

double
growingThreshold(double delta0, int tag_a, int tag_b, const std::vector<double>& tag_ratio)
{
  if (tag_a != tag_b)
    return 0.0; // a topological joint: only a zero-cost step passes
  if (tag_a <= 0 || tag_a >= static_cast<int>(tag_ratio.size()))
    return delta0;
  return delta0 * tag_ratio[tag_a];
}

} // namespace segmat
