/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include "ply_header.h"

#include "text_file.h"

#include <segmat/common/error.h>

#include <algorithm>
#include <charconv>
#include <cstdint>
#include <fstream>
#include <map>
#include <vector>

namespace segmat {
namespace io {
namespace detail {
namespace {
// Bytes of one value of a PLY scalar type; 0 for an unknown type.
std::size_t
scalarBytes(std::string_view type)
{
  static const std::map<std::string_view, std::size_t> sizes = {
      {"char", 1},   {"uchar", 1},   {"int8", 1},   {"uint8", 1},   {"short", 2},  {"ushort", 2},
      {"int16", 2},  {"uint16", 2},  {"int", 4},    {"uint", 4},    {"int32", 4},  {"uint32", 4},
      {"float", 4},  {"float32", 4}, {"double", 8}, {"float64", 8}, {"int64", 8},  {"uint64", 8}};
  const auto it = sizes.find(type);
  return it == sizes.end() ? 0 : it->second;
}

struct Element
{
  std::string name;
  std::uint64_t count = 0;
  std::uint64_t least_bytes = 0; // smallest possible size of one item
  long line = 0;
};
} // namespace

void
checkPlyHeader(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw Error(path, 0, "cannot open the file (missing or unreadable)");
  in.seekg(0, std::ios::end);
  const std::uint64_t file_size = static_cast<std::uint64_t>(in.tellg());
  in.seekg(0);

  constexpr std::size_t kMaxHeaderBytes = 1 << 20;
  std::string raw;
  long line_number = 0;
  std::uint64_t header_bytes = 0;
  bool ascii = true;
  std::vector<Element> elements;
  const auto fail = [&](const std::string& message) { throw Error(path, line_number, message); };
  while (true) {
    if (!std::getline(in, raw)) {
      if (line_number == 0)
        throw Error(path, 0, "empty file: not a PLY file");
      fail("the header has no 'end_header' line");
    }
    ++line_number;
    header_bytes += raw.size() + 1;
    if (header_bytes > kMaxHeaderBytes)
      fail("no 'end_header' within the first megabyte: not a PLY file");
    if (!raw.empty() && raw.back() == '\r')
      raw.pop_back();
    for (char c : raw)
      if ((static_cast<unsigned char>(c) < 0x20 && c != '\t') || static_cast<unsigned char>(c) >= 0x7f)
        fail("binary data in the PLY header");
    Tokens tokens(raw);
    std::string_view keyword;
    tokens.next(keyword);
    if (line_number == 1) {
      if (keyword != "ply")
        fail("not a PLY file: it does not start with the line 'ply'");
      continue;
    }
    if (keyword == "end_header")
      break;
    if (keyword == "format") {
      std::string_view format;
      tokens.next(format);
      if (format != "ascii" && format != "binary_little_endian" && format != "binary_big_endian")
        fail("unknown PLY format " + quoted(format));
      ascii = format == "ascii";
    } else if (keyword == "element") {
      std::string_view name, count;
      if (!tokens.next(name) || !tokens.next(count) || tokens.remaining() != 0)
        fail("'element' needs a name and a count: " + quoted(raw));
      const auto [end, ec] = std::from_chars(count.data(), count.data() + count.size(),
                                             elements.emplace_back().count);
      if (ec != std::errc() || end != count.data() + count.size())
        fail("element count " + quoted(count) + " is not a non-negative integer");
      elements.back().name = std::string(name);
      elements.back().line = line_number;
    } else if (keyword == "property") {
      if (elements.empty())
        fail("'property' before any 'element'");
      std::string_view type, count_type, item_type;
      tokens.next(type);
      std::size_t bytes = 0;
      if (type == "list") {
        tokens.next(count_type);
        tokens.next(item_type);
        // An empty list still stores its length.
        bytes = scalarBytes(item_type) == 0 ? 0 : scalarBytes(count_type);
        // PCL's reader aborts (assert) on a vertex list whose lengths vary; real files have none.
        if (elements.back().name == "vertex")
          fail("list property on the 'vertex' element is not supported");
      } else {
        bytes = scalarBytes(type);
      }
      if (bytes == 0)
        fail("unknown PLY property type in " + quoted(raw));
      if (tokens.remaining() != 1)
        fail("malformed property line " + quoted(raw));
      // ASCII: at least one digit and one separator per value.
      elements.back().least_bytes += ascii ? 2 : bytes;
    } else if (keyword != "comment" && keyword != "obj_info" && !keyword.empty()) {
      fail("unexpected " + quoted(keyword) + " in the PLY header");
    }
  }

  // The last separator of an ASCII file may be missing.
  const std::uint64_t after_header = file_size > header_bytes ? file_size - header_bytes : 0;
  const std::uint64_t data_bytes = after_header + (ascii ? 1 : 0);
  std::uint64_t needed = 0;
  for (const Element& e : elements) {
    const std::uint64_t item = std::max<std::uint64_t>(e.least_bytes, 1);
    if (e.count > data_bytes / item || needed + e.count * item > data_bytes)
      throw Error(path, e.line,
                  "element '" + e.name + "' announces " + std::to_string(e.count) +
                      " items, more than the " + std::to_string(after_header) +
                      " bytes after the header can hold (truncated file or wrong count)");
    needed += e.count * item;
  }
}

} // namespace detail
} // namespace io
} // namespace segmat
