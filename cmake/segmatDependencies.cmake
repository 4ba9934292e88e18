# Everything segmat needs; Debian 12 packages only (scripts/install_deps.sh installs them).
find_package(PCL 1.13 REQUIRED COMPONENTS common kdtree search features filters io)
find_package(Eigen3 3.3 REQUIRED NO_MODULE)
find_package(Boost 1.74 REQUIRED)
find_package(Qhull CONFIG REQUIRED)
find_package(OpenMP)
