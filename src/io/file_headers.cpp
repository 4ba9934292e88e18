/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include "file_headers.h"

#include "text_file.h"

#include <segmat/common/error.h>

#include <algorithm>
#include <charconv>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <vector>

namespace segmat {
namespace io {
namespace detail {
namespace {
// The text header of a binary-capable format, read line by line with 1-based line numbers.
class HeaderLines
{
public:
  HeaderLines(const std::string& path, const char* format) : path_(path), format_(format)
  {
    in_.open(path, std::ios::binary);
    if (!in_)
      throw Error(path, 0, "cannot open the file (missing or unreadable)");
    in_.seekg(0, std::ios::end);
    file_size_ = static_cast<std::uint64_t>(in_.tellg());
    in_.seekg(0);
    if (file_size_ == 0)
      throw Error(path, 0, std::string("empty file: not a ") + format + " file");
  }

  // Next header line without its CR; fails at the end of the file, on binary bytes and when the
  // header runs past a megabyte (a binary file without line breaks).
  std::string_view
  next(const char* missing_end)
  {
    if (!std::getline(in_, line_))
      fail(std::string("the header has no '") + missing_end + "' line");
    ++number_;
    header_bytes_ += line_.size() + 1;
    if (header_bytes_ > (1u << 20))
      fail(std::string("no header end within the first megabyte: not a ") + format_ + " file");
    if (!line_.empty() && line_.back() == '\r')
      line_.pop_back();
    for (char c : line_)
      if ((static_cast<unsigned char>(c) < 0x20 && c != '\t') ||
          static_cast<unsigned char>(c) >= 0x7f)
        fail(std::string("binary data in the ") + format_ + " header");
    return line_;
  }

  [[noreturn]] void
  fail(const std::string& message) const
  {
    throw Error(path_, number_, message);
  }

  long
  number() const
  {
    return number_;
  }

  // Bytes after the header; the header's last line break may be missing at the end of a file.
  std::uint64_t
  bytesAfterHeader() const
  {
    return file_size_ > header_bytes_ ? file_size_ - header_bytes_ : 0;
  }

  // Offset of the first byte after the header.
  std::uint64_t
  headerBytes() const
  {
    return header_bytes_;
  }

  // Reads \a size bytes right after the header (false when the file is shorter).
  bool
  peekData(char* out, std::size_t size)
  {
    return static_cast<bool>(in_.read(out, static_cast<std::streamsize>(size)));
  }

private:
  std::string path_;
  const char* format_;
  std::ifstream in_;
  std::string line_;
  std::uint64_t file_size_ = 0;
  std::uint64_t header_bytes_ = 0;
  long number_ = 0;
};

// A whole token as an unsigned integer; false otherwise.
bool
parseCount(std::string_view token, std::uint64_t& value)
{
  const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
  return ec == std::errc() && end == token.data() + token.size();
}

// Bytes of one value of a PLY scalar type; 0 for an unknown type.
std::size_t
plyScalarBytes(std::string_view type)
{
  static const std::map<std::string_view, std::size_t> sizes = {
      {"char", 1},  {"uchar", 1},   {"int8", 1},   {"uint8", 1},   {"short", 2}, {"ushort", 2},
      {"int16", 2}, {"uint16", 2},  {"int", 4},    {"uint", 4},    {"int32", 4}, {"uint32", 4},
      {"float", 4}, {"float32", 4}, {"double", 8}, {"float64", 8}, {"int64", 8}, {"uint64", 8}};
  const auto it = sizes.find(type);
  return it == sizes.end() ? 0 : it->second;
}

struct PlyElement
{
  std::string name;
  std::uint64_t count = 0;
  std::uint64_t least_bytes = 0; // smallest possible size of one item
  long line = 0;
};

// A PCD data token as PCL splits lines: at spaces, tabs and carriage returns only.
std::vector<std::string_view>
pcdTokens(std::string_view line)
{
  std::vector<std::string_view> tokens;
  std::size_t i = 0;
  while (i < line.size()) {
    const std::size_t end = std::min(line.find_first_of(" \t\r", i), line.size());
    if (end > i)
      tokens.push_back(line.substr(i, end - i));
    i = end + 1;
  }
  return tokens;
}

// PCL's header parser does not stop at DATA: it goes on taking lines for header lines while they
// start with a header keyword, and a "FIELDS" line in the data empties the field list, after which
// PCL writes past its buffers. Refuses data whose first lines PCL would take for header lines and,
// for ASCII data, any of the first \a points lines that does not hold \a values numbers (PCL
// would read a point of zeros, or crash).
void
checkPcdData(const std::string& path, std::uint64_t offset, long line_number, bool ascii,
             std::uint64_t values, std::uint64_t points)
{
  static const char* const keywords[] = {"FIELDS", "COLUMNS", "SIZE",      "TYPE",   "COUNT",
                                         "WIDTH",  "HEIGHT",  "VIEWPOINT", "POINTS", "DATA"};
  std::ifstream in(path, std::ios::binary);
  in.seekg(static_cast<std::streamoff>(offset));
  std::string line;
  bool header_like = true; // PCL still takes lines for header lines
  std::uint64_t read = 0;
  while ((header_like || (ascii && read < points)) && std::getline(in, line)) {
    ++line_number;
    if (line.empty())
      continue; // PCL skips empty lines, in the header and in ASCII data
    if (header_like) {
      const std::string_view first(line.data(), std::min(line.find_first_of(" \t\r"), line.size()));
      for (const char* keyword : keywords)
        if (first.substr(0, std::strlen(keyword)) == keyword)
          throw Error(path, line_number,
                      "the data starts with the header keyword " + quoted(keyword) +
                          ", which PCL's reader would take for a header line");
      header_like = first.substr(0, 1) == "#" || first.substr(0, 7) == "VERSION";
    }
    if (!ascii)
      continue;
    if (line == "\r")
      continue;
    const std::vector<std::string_view> tokens = pcdTokens(line);
    if (tokens.size() != values)
      throw Error(path, line_number,
                  "point " + std::to_string(read + 1) + " has " + std::to_string(tokens.size()) +
                      " values, the fields need " + std::to_string(values));
    for (std::string_view token : tokens)
      if (!isNumber(token))
        throw Error(path, line_number, "value " + quoted(token) + " is not a number");
    ++read;
  }
  if (ascii && read < points)
    throw Error(path, line_number,
                "the data holds " + std::to_string(read) + " points, the header announces " +
                    std::to_string(points) + " (truncated file or wrong count)");
}
} // namespace

void
requireRegularFile(const std::string& path)
{
  std::error_code ec;
  const auto status = std::filesystem::status(path, ec);
  if (ec || !std::filesystem::exists(status))
    throw Error(path, 0, "cannot open the file (missing or unreadable)");
  if (std::filesystem::is_directory(status))
    throw Error(path, 0, "is a directory, not a file");
}

void
checkPlyHeader(const std::string& path)
{
  HeaderLines header(path, "PLY");
  std::string_view line = header.next("end_header");
  if (line != "ply")
    header.fail("not a PLY file: it does not start with the line 'ply'");
  bool ascii = true;
  std::vector<PlyElement> elements;
  while ((line = header.next("end_header")) != "end_header") {
    Tokens tokens(line);
    std::string_view keyword;
    tokens.next(keyword);
    if (keyword == "format") {
      std::string_view format;
      tokens.next(format);
      if (format != "ascii" && format != "binary_little_endian" && format != "binary_big_endian")
        header.fail("unknown PLY format " + quoted(format));
      ascii = format == "ascii";
    } else if (keyword == "element") {
      std::string_view name, count;
      PlyElement element;
      if (!tokens.next(name) || !tokens.next(count) || tokens.remaining() != 0)
        header.fail("'element' needs a name and a count: " + quoted(line));
      if (!parseCount(count, element.count))
        header.fail("element count " + quoted(count) + " is not a non-negative integer");
      element.name = std::string(name);
      element.line = header.number();
      elements.push_back(element);
    } else if (keyword == "property") {
      if (elements.empty())
        header.fail("'property' before any 'element'");
      std::string_view type, count_type, item_type;
      tokens.next(type);
      std::size_t bytes = 0;
      if (type == "list") {
        tokens.next(count_type);
        tokens.next(item_type);
        // An empty list still stores its length.
        bytes = plyScalarBytes(item_type) == 0 ? 0 : plyScalarBytes(count_type);
        // PCL's reader aborts (assert) on a vertex list whose lengths vary; real files have none.
        if (elements.back().name == "vertex")
          header.fail("list property on the 'vertex' element is not supported");
      } else {
        bytes = plyScalarBytes(type);
      }
      if (bytes == 0)
        header.fail("unknown PLY property type in " + quoted(line));
      if (tokens.remaining() != 1)
        header.fail("malformed property line " + quoted(line));
      // ASCII: at least one digit and one separator per value.
      elements.back().least_bytes += ascii ? 2 : bytes;
    } else if (keyword == "obj_info") {
      // PCL's reader aborts (assert) on an 'obj_info' line that does not start with it.
      if (line.substr(0, 8) != "obj_info")
        header.fail("blank before 'obj_info' in " + quoted(line));
    } else if (keyword != "comment" && !keyword.empty()) {
      header.fail("unexpected " + quoted(keyword) + " in the PLY header");
    }
  }

  const std::uint64_t data_bytes = header.bytesAfterHeader() + (ascii ? 1 : 0);
  std::uint64_t needed = 0;
  for (const PlyElement& e : elements) {
    const std::uint64_t item = std::max<std::uint64_t>(e.least_bytes, 1);
    if (e.count > data_bytes / item || needed + e.count * item > data_bytes)
      throw Error(path, e.line,
                  "element '" + e.name + "' announces " + std::to_string(e.count) +
                      " items, more than the " + std::to_string(header.bytesAfterHeader()) +
                      " bytes after the header can hold (truncated file or wrong count)");
    needed += e.count * item;
  }
}

void
checkPcdHeader(const std::string& path)
{
  HeaderLines header(path, "PCD");
  std::vector<std::string> fields;
  std::vector<std::uint64_t> sizes, counts;
  std::vector<char> types;
  std::uint64_t width = 0, height = 1, points = 0;
  bool has_width = false, has_points = false;
  std::string data;
  std::vector<std::string> seen;
  // Each keyword's values, checked as they come; DATA ends the header.
  while (data.empty()) {
    const std::string_view line = header.next("DATA");
    Tokens tokens(line);
    std::string_view keyword, token;
    // PCL's header parser loses its place on a line of blanks (then reads no points and
    // crashes on the data): refuse blank lines, which PCL never writes.
    if (!tokens.next(keyword))
      header.fail("blank line in the PCD header");
    if (keyword.front() == '#')
      continue;
    // PCL sizes the point data at the POINTS line from the layout read so far (FIELDS, SIZE,
    // TYPE, COUNT) and takes any later layout line as given: the points are then read past the
    // end of their buffer. PCL writes each keyword once, the layout before POINTS.
    const std::string name = keyword == "COLUMNS" ? "FIELDS" : std::string(keyword);
    if (std::find(seen.begin(), seen.end(), name) != seen.end())
      header.fail("the PCD header repeats " + name);
    const bool layout = name == "FIELDS" || name == "SIZE" || name == "TYPE" || name == "COUNT";
    if (layout && has_points)
      header.fail(name + " after POINTS in the PCD header");
    seen.push_back(name);
    std::vector<std::string_view> values;
    while (tokens.next(token))
      values.push_back(token);
    const auto single = [&](std::uint64_t& out) {
      if (values.size() != 1 || !parseCount(values[0], out))
        header.fail(std::string(keyword) + " needs one non-negative integer");
    };
    const auto list = [&](std::vector<std::uint64_t>& out) {
      out.resize(values.size());
      for (std::size_t i = 0; i < values.size(); ++i)
        if (!parseCount(values[i], out[i]) || out[i] == 0)
          header.fail(std::string(keyword) + " value " + quoted(values[i]) +
                      " is not a positive integer");
    };
    if (keyword == "VERSION" || keyword == "VIEWPOINT") {
      continue;
    } else if (keyword == "FIELDS" || keyword == "COLUMNS") {
      fields.assign(values.begin(), values.end());
      if (fields.empty())
        header.fail("FIELDS lists no field");
    } else if (keyword == "SIZE") {
      list(sizes);
      for (std::uint64_t s : sizes)
        if (s != 1 && s != 2 && s != 4 && s != 8)
          header.fail("SIZE " + std::to_string(s) + " is not 1, 2, 4 or 8");
    } else if (keyword == "TYPE") {
      types.clear();
      for (std::string_view t : values) {
        if (t != "I" && t != "U" && t != "F")
          header.fail("TYPE " + quoted(t) + " is not I, U or F");
        types.push_back(t.front());
      }
    } else if (keyword == "COUNT") {
      list(counts);
    } else if (keyword == "WIDTH") {
      single(width);
      has_width = true;
    } else if (keyword == "HEIGHT") {
      single(height);
    } else if (keyword == "POINTS") {
      single(points);
      has_points = true;
    } else if (keyword == "DATA") {
      if (values.size() != 1 ||
          (values[0] != "ascii" && values[0] != "binary" && values[0] != "binary_compressed"))
        header.fail("DATA must be ascii, binary or binary_compressed");
      data = std::string(values[0]);
    } else {
      header.fail("unknown PCD header keyword " + quoted(keyword));
    }
  }

  if (fields.empty())
    header.fail("the header has no FIELDS line");
  if (counts.empty())
    counts.assign(fields.size(), 1);
  if (sizes.size() != fields.size() || types.size() != fields.size() ||
      counts.size() != fields.size())
    header.fail("FIELDS, SIZE, TYPE and COUNT list different numbers of entries");
  for (std::size_t i = 0; i < fields.size(); ++i)
    if (types[i] == 'F' && sizes[i] != 4 && sizes[i] != 8)
      header.fail("field '" + fields[i] + "' is a float of " + std::to_string(sizes[i]) + " bytes");
  if (!has_width)
    header.fail("the header has no WIDTH line");
  if (height != 0 && width > (std::uint64_t(1) << 40) / height)
    header.fail("WIDTH x HEIGHT is absurdly large");
  if (!has_points)
    points = width * height;
  if (points != width * height)
    header.fail("POINTS " + std::to_string(points) +
                " is not WIDTH x HEIGHT = " + std::to_string(width * height));

  std::uint64_t point_bytes = 0, values_per_point = 0;
  for (std::size_t i = 0; i < fields.size(); ++i) {
    point_bytes += sizes[i] * counts[i];
    values_per_point += counts[i];
  }
  const std::uint64_t available = header.bytesAfterHeader();
  std::uint64_t needed = 0;
  if (data == "ascii")
    needed = points * values_per_point * 2 > 0 ? points * values_per_point * 2 - 1 : 0;
  else if (data == "binary")
    needed = points * point_bytes;
  else { // binary_compressed: two uint32 sizes, then the compressed block
    std::uint32_t compressed = 0, uncompressed = 0;
    char sizes_bytes[8];
    if (points > 0) {
      if (!header.peekData(sizes_bytes, 8))
        header.fail("the compressed data block is missing (truncated file)");
      std::memcpy(&compressed, sizes_bytes, 4);
      std::memcpy(&uncompressed, sizes_bytes + 4, 4);
      if (uncompressed != points * point_bytes)
        header.fail("the compressed block unpacks to " + std::to_string(uncompressed) +
                    " bytes, not the " + std::to_string(points * point_bytes) +
                    " the header needs");
      needed = 8 + static_cast<std::uint64_t>(compressed);
    }
  }
  if (needed > available)
    header.fail(std::to_string(points) + " points need at least " + std::to_string(needed) +
                " bytes of data, the file has " + std::to_string(available) +
                " after the header (truncated file or wrong count)");
  checkPcdData(path, header.headerBytes(), header.number(), data == "ascii", values_per_point,
               points);
}

void
checkStlSize(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw Error(path, 0, "cannot open the file (missing or unreadable)");
  in.seekg(0, std::ios::end);
  const std::uint64_t size = static_cast<std::uint64_t>(in.tellg());
  in.seekg(0);
  char head[84] = {};
  in.read(head, sizeof head);
  std::uint32_t triangles = 0;
  std::memcpy(&triangles, head + 80, 4);
  // Binary when the size fits the count: binary files may also start with "solid".
  if (size >= 84 && size == 84 + 50 * static_cast<std::uint64_t>(triangles))
    return;
  const std::string_view start(head, static_cast<std::size_t>(std::min<std::uint64_t>(size, 84)));
  const std::size_t first = start.find_first_not_of(" \t\r\n");
  // VTK reads a file as binary, trusting its triangle count, when at least 5 % of its first 256
  // bytes are not text (text: 0x20-0x7f, tab, line feed, carriage return; kwsys's
  // DetectFileType): a "solid" file is ASCII only below that share (a 237-byte file with vertical
  // tabs allocated gigabytes).
  char sniff[256] = {};
  in.clear();
  in.seekg(0);
  in.read(sniff, sizeof sniff);
  const std::streamsize sniffed = in.gcount();
  std::streamsize non_text = 0;
  for (std::streamsize i = 0; i < sniffed; ++i) {
    const unsigned char c = static_cast<unsigned char>(sniff[i]);
    non_text += (c >= 0x20 && c <= 0x7f) || c == '\t' || c == '\n' || c == '\r' ? 0 : 1;
  }
  const bool binary_bytes =
      sniffed > 0 && static_cast<double>(non_text) / static_cast<double>(sniffed) >= 0.05;
  const bool solid = first != std::string_view::npos && start.substr(first, 5) == "solid";
  if (solid && !binary_bytes)
    return;
  if (size == 0)
    throw Error(path, 0, "empty file: not an STL file");
  if (size < 84)
    throw Error(path, 0,
                "not an STL file: " + std::to_string(size) +
                    " bytes, too short for a binary STL and no 'solid' line");
  const std::string why_binary =
      solid ? "starts with 'solid' but " + std::to_string(non_text) + " of its first " +
                  std::to_string(sniffed) + " bytes are not text, so it is read as binary: "
            : "";
  throw Error(path, 0,
              why_binary + "binary STL announces " + std::to_string(triangles) + " triangles, which take " +
                  std::to_string(84 + 50 * static_cast<std::uint64_t>(triangles)) +
                  " bytes; the file has " + std::to_string(size) +
                  " (truncated, or not an STL file)");
}

} // namespace detail
} // namespace io
} // namespace segmat
