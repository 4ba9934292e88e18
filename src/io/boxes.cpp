/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
#include "text_file.h"

#include <segmat/io/boxes.h>
#include <segmat/io/colored_ply.h>

namespace segmat {
namespace io {
namespace {
void
checkBoxes(const std::string& path, const std::vector<PartBox>& boxes)
{
  for (const PartBox& b : boxes)
    if (!b.box.center.allFinite() || !b.box.axes.allFinite() || !b.box.extents.allFinite())
      throw Error(path, 0, "not written: the box of part " + std::to_string(b.part) +
                               " has a non-finite coordinate");
}

void
appendVector(std::string& out, const Eigen::Vector3d& v)
{
  out += '[';
  for (int k = 0; k < 3; ++k) {
    if (k)
      out += ", ";
    detail::appendDouble(out, v[k]);
  }
  out += ']';
}
} // namespace

void
saveBoxesJson(const std::string& path, const std::vector<PartBox>& boxes)
{
  checkBoxes(path, boxes);
  std::string out = "{\"boxes\": [";
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    const OrientedBox& box = boxes[i].box;
    out += i ? ",\n  " : "\n  ";
    out += "{\"part\": ";
    detail::appendInt(out, boxes[i].part);
    out += ", \"center\": ";
    appendVector(out, box.center);
    out += ", \"axes\": [";
    for (int k = 0; k < 3; ++k) {
      if (k)
        out += ", ";
      appendVector(out, box.axes.row(k).transpose());
    }
    out += "], \"extents\": ";
    appendVector(out, box.extents);
    out += ", \"volume\": ";
    detail::appendDouble(out, box.volume());
    out += '}';
  }
  out += boxes.empty() ? "]}\n" : "\n]}\n";
  detail::writeTextAtomically(path, out);
}

void
saveBoxesPly(const std::string& path, const std::vector<PartBox>& boxes)
{
  checkBoxes(path, boxes);
  std::vector<OrientedBox> shapes;
  std::vector<int> face_labels;
  for (const PartBox& b : boxes) {
    shapes.push_back(b.box);
    face_labels.insert(face_labels.end(), 12, b.part);
  }
  saveColoredMeshPly(path, boxesToMesh(shapes), face_labels);
}

} // namespace io
} // namespace segmat
