// Reading speed of the readers: median wall time of 21 loads per file.
//   bench_io [FILE.{off,obj,ply,stl,ma} ...]   (default, run from the repository root: the bundled
//   data/teddy/teddy.off and data/teddy/teddy_mat.ma)
#include <segmat/common/error.h>
#include <segmat/io/atomic_file.h>
#include <segmat/io/ma.h>
#include <segmat/io/mesh.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

#ifndef SEGMAT_BENCH_DATA_DIR
#define SEGMAT_BENCH_DATA_DIR "data"
#endif

namespace {
template <typename Load>
double
medianMilliseconds(const Load& load, int repeats)
{
  std::vector<double> ms;
  for (int i = 0; i < repeats; ++i) {
    const auto start = std::chrono::steady_clock::now();
    load();
    ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                     .count());
  }
  std::sort(ms.begin(), ms.end());
  return ms[ms.size() / 2];
}
} // namespace

int
main(int argc, char** argv)
{
  std::vector<std::string> files(argv + 1, argv + argc);
  if (files.empty())
    files = {SEGMAT_BENCH_DATA_DIR "/teddy/teddy.off", SEGMAT_BENCH_DATA_DIR "/teddy/teddy_mat.ma"};
  try {
    for (const std::string& path : files) {
      const std::string ext = segmat::io::extensionOf(path);
      std::size_t size = 0;
      double ms = 0.0;
      if (ext == "ma") {
        ms = medianMilliseconds([&] { size = segmat::io::loadMa(path).numVertices(); }, 21);
        std::printf("%s: %zu spheres, median load %.2f ms\n", path.c_str(), size, ms);
      } else {
        ms = medianMilliseconds([&] { size = segmat::io::loadMesh(path).numFaces(); }, 21);
        std::printf("%s: %zu faces, median load %.2f ms\n", path.c_str(), size, ms);
      }
    }
  } catch (const segmat::Error& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 1;
  }
  return 0;
}
