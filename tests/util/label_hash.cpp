#include <util/label_hash.h>

namespace segmat {
namespace test {

std::uint64_t
labelHash(const std::vector<int>& labels)
{
  std::uint64_t h = 1469598103934665603ull;
  for (int l : labels) {
    h ^= static_cast<std::uint64_t>(l) + 1;
    h *= 1099511628211ull;
  }
  return h;
}

} // namespace test
} // namespace segmat
