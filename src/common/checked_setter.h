/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#pragma once

#include <pcl/console/print.h>

#include <iostream>

namespace segmat {
namespace detail {

/** \brief PCL-style setter validation (as MinCutSegmentation): assign \a value when \a valid,
 * otherwise warn "[segmat::<where>] <value> is not <rule>; keeping <old>." and keep the old value.
 * \return whether the value was taken
 */
template <typename Field, typename Value>
bool
assignChecked(Field& field, const Value& value, bool valid, const char* where, const char* rule)
{
  if (!valid) {
    PCL_WARN_STREAM("[segmat::" << where << "] " << value << " is not " << rule << "; keeping "
                                << field << ".\n");
    return false;
  }
  field = value;
  return true;
}

} // namespace detail
} // namespace segmat
