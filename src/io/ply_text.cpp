/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include "ply_text.h"

#include "text_file.h"

namespace segmat {
namespace io {
namespace detail {
namespace {
// One element line, with the element's colour at its end when there are colours.
template <typename Values>
void
appendRow(std::string& text, std::string_view first, const Values& values,
          const std::vector<Rgb>* colors, std::size_t i)
{
  appendLine(text, first, values);
  if (colors) {
    text.pop_back();
    for (std::uint8_t channel : (*colors)[i]) {
      text += ' ';
      appendInt(text, channel);
    }
    text += '\n';
  }
}
} // namespace

std::string
plyText(const std::vector<Eigen::Vector3d>& vertices, const std::vector<Rgb>* vertex_colors,
        const std::vector<Eigen::Vector3i>* faces, const std::vector<Rgb>* face_colors)
{
  const char* const color_properties =
      "property uchar red\nproperty uchar green\nproperty uchar blue\n";
  std::string text = "ply\nformat ascii 1.0\ncomment written by segmat\nelement vertex ";
  appendInt(text, static_cast<long>(vertices.size()));
  text += "\nproperty double x\nproperty double y\nproperty double z\n";
  if (vertex_colors)
    text += color_properties;
  if (faces) {
    text += "element face ";
    appendInt(text, static_cast<long>(faces->size()));
    text += "\nproperty list uchar int vertex_indices\n";
    if (face_colors)
      text += color_properties;
  }
  text += "end_header\n";
  for (std::size_t v = 0; v < vertices.size(); ++v)
    appendRow(text, "", vertices[v], vertex_colors, v);
  if (faces)
    for (std::size_t f = 0; f < faces->size(); ++f)
      appendRow(text, "3", (*faces)[f], face_colors, f);
  return text;
}

} // namespace detail
} // namespace io
} // namespace segmat
