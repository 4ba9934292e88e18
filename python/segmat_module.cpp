/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
// The Python module `segmat`: numpy arrays in and out, the GIL released while C++ computes.
#include "bindings.h"

#include <segmat/common/error.h>

PYBIND11_MODULE(segmat, m)
{
  m.doc() = "SEG-MAT part segmentation of meshes and point clouds (Lin et al., IEEE TVCG 2022) "
            "over numpy arrays.";
  m.attr("__version__") = SEGMAT_VERSION;
  // segmat::Error (bad files, failed computations) arrives as segmat.Error with its message.
  pybind11::register_exception<segmat::Error>(m, "Error", PyExc_RuntimeError);
  segmat_python::bindSegmentation(m);
  segmat_python::bindTools(m);
}
