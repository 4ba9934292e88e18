/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once

#include <segmat/segmentation/label_transfer.h>
#include <segmat/segmentation/mat_region_growing.h>

namespace segmat {

/** \brief The paper's five parameters (SEG-MAT, Lin et al. 2022: δ0, η, α, λ for the grower, ω for
 * the graph cut), shared by the front classes MeshSegmentation and CloudSegmentation so that both
 * paths expose one parameter set with one set of defaults.
 * \tparam TransferT the label transfer (MeshLabelTransfer or CloudLabelTransfer)
 */
template <typename TransferT>
class MatSegmentationParameters
{
public:
  /** \brief δ0, the growing threshold (default 0.015). */
  void
  setGrowingThreshold(double delta0)
  {
    grower_.setGrowingThreshold(delta0);
  }

  /** \brief δ0. */
  double
  getGrowingThreshold() const
  {
    return grower_.getGrowingThreshold();
  }

  /** \brief η, the minimal region size as a fraction of the medial spheres (default 0.002). */
  void
  setMinRegionFraction(double eta)
  {
    grower_.setMinRegionFraction(eta);
  }

  /** \brief η. */
  double
  getMinRegionFraction() const
  {
    return grower_.getMinRegionFraction();
  }

  /** \brief α, weight of the angle term of the growing cost (default 0.05). */
  void
  setAngleWeight(double alpha)
  {
    grower_.setAngleWeight(alpha);
  }

  /** \brief α. */
  double
  getAngleWeight() const
  {
    return grower_.getAngleWeight();
  }

  /** \brief λ, weight of the medial-primitive term (default 1.5; without effect on
   * medial points, which have no primitives: one parameter set serves both paths).
   */
  void
  setPrimitiveWeight(double lambda)
  {
    grower_.setPrimitiveWeight(lambda);
  }

  /** \brief λ. */
  double
  getPrimitiveWeight() const
  {
    return grower_.getPrimitiveWeight();
  }

  /** \brief Largest turn of a bulky tube inside one grown region, in degrees (default 60; 90
   * disables it, as in SEG-MAT; MatRegionGrowing::setMaxBendAngle).
   */
  void
  setMaxBendAngle(double degrees)
  {
    grower_.setMaxBendAngle(degrees);
  }

  /** \brief Largest turn of a bulky tube inside one grown region, in degrees. */
  double
  getMaxBendAngle() const
  {
    return grower_.getMaxBendAngle();
  }

  /** \brief How the cut to faces or points prices a concave crease
   * (LabelTransferBase::setCreaseModel; default CreaseModel::SharpConcave;
   * CreaseModel::Reference reproduces SEG-MAT's transfer).
   */
  void
  setCreaseModel(CreaseModel model)
  {
    transfer_.setCreaseModel(model);
  }

  /** \brief How the cut prices a concave crease. */
  CreaseModel
  getCreaseModel() const
  {
    return transfer_.getCreaseModel();
  }

  /** \brief Join parts whose boundary on the surface crosses flat surface after the cut
   * (LabelTransferBase::setJoinFlatBoundaries; default true; false reproduces SEG-MAT).
   */
  void
  setJoinFlatBoundaries(bool join)
  {
    transfer_.setJoinFlatBoundaries(join);
  }

  /** \brief Whether parts with a flat boundary are joined after the cut. */
  bool
  getJoinFlatBoundaries() const
  {
    return transfer_.getJoinFlatBoundaries();
  }

  /** \brief ω, weight of the graph cut's smoothness term (default 0.3). */
  void
  setSmoothnessWeight(double omega)
  {
    transfer_.setSmoothnessWeight(omega);
  }

  /** \brief ω. */
  double
  getSmoothnessWeight() const
  {
    return transfer_.getSmoothnessWeight();
  }

  /** \brief Smallest share of the surface a part may keep after the cut (default 0.002;
   * LabelTransferBase::setMinPartFraction). 0 keeps every part that wins a face or point.
   */
  void
  setMinPartFraction(double fraction)
  {
    transfer_.setMinPartFraction(fraction);
  }

  /** \brief Smallest share of the surface a part may keep after the cut. */
  double
  getMinPartFraction() const
  {
    return transfer_.getMinPartFraction();
  }

  /** \brief Largest number of faces or points cut at full resolution in one α-expansion
   * (default 65536; 0: no limit; LabelTransferBase::setMaxFullCutElements). A larger surface is
   * cut coarse to fine.
   */
  void
  setMaxFullCutElements(std::size_t count)
  {
    transfer_.setMaxFullCutElements(count);
  }

  /** \brief Largest number of faces or points cut at full resolution in one α-expansion. */
  std::size_t
  getMaxFullCutElements() const
  {
    return transfer_.getMaxFullCutElements();
  }

  /** \brief Seed of the merging's visibility sampling (default 0x5e6a7; not one of the paper's
   * parameters: for checking that a result does not hinge on one random draw).
   */
  void
  setRandomSeed(unsigned seed)
  {
    grower_.setRandomSeed(seed);
  }

  /** \brief Seed of the merging's visibility sampling. */
  unsigned
  getRandomSeed() const
  {
    return grower_.getRandomSeed();
  }

protected:
  MatRegionGrowing grower_; ///< the one region grower of both paths
  TransferT transfer_;      ///< parts → faces or points
};

} // namespace segmat
