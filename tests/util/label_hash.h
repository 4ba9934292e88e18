// A compact golden value for a whole labelling (tests compare it with a recorded constant).
#pragma once

#include <cstdint>
#include <vector>

namespace segmat {
namespace test {

/** \brief FNV-1a over the labels (each label + 1, as one 64-bit word). */
std::uint64_t
labelHash(const std::vector<int>& labels);

} // namespace test
} // namespace segmat
