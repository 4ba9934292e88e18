/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include "text_file.h"

#include <segmat/io/seg.h>

#include <algorithm>

namespace segmat {
namespace io {

std::vector<int>
loadSeg(const std::string& path, long expected_count)
{
  // No '#' comments: PSB files have none, and a stray character must not silently vanish.
  detail::TextFile file(path, "SEG", false);
  std::vector<int> labels;
  if (expected_count > 0)
    labels.reserve(static_cast<std::size_t>(std::min<long>(expected_count, file.size() / 2 + 1)));
  std::string_view line;
  while (file.nextLine(line)) {
    detail::Tokens tokens(line);
    std::string_view token;
    tokens.next(token);
    const int label = file.parseInt(token, "label");
    if (tokens.remaining() != 0)
      file.fail(detail::quoted(line) + " holds more than one label");
    labels.push_back(label);
  }
  if (labels.empty() && expected_count != 0)
    file.failFile("empty file: no labels");
  if (expected_count >= 0 && static_cast<long>(labels.size()) != expected_count)
    file.failFile("has " + std::to_string(labels.size()) + " labels, the mesh has " +
                  std::to_string(expected_count) + " faces");
  return labels;
}

void
saveSeg(const std::string& path, const std::vector<int>& labels)
{
  std::string text;
  text.reserve(labels.size() * 3);
  for (int label : labels) {
    detail::appendInt(text, label);
    text += '\n';
  }
  detail::writeTextAtomically(path, text);
}

} // namespace io
} // namespace segmat
