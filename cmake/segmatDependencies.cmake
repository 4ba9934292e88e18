# Everything segmat needs; Debian 12 packages only (scripts/install_deps.sh installs them).
find_package(PCL 1.13 REQUIRED COMPONENTS common kdtree search features filters io)
find_package(Eigen3 3.3 REQUIRED NO_MODULE)
find_package(Boost 1.74 REQUIRED)
find_package(Qhull CONFIG REQUIRED)
find_package(OpenMP)
# FLANN's kd-tree, used directly by src/common/point_kd_tree.cpp, serialises with LZ4 (a
# dependency of libflann-dev): its headers need the library on the link line.
find_library(SEGMAT_LZ4_LIBRARY NAMES lz4)
if(NOT SEGMAT_LZ4_LIBRARY)
  message(FATAL_ERROR "liblz4 not found (Debian: liblz4-dev, installed with libpcl-dev)")
endif()
