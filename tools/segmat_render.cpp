/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 *
 * segmat_render: a picture of a segmented mesh or cloud, shaded and coloured by part with the
 * colours of the coloured PLY output (segmat::io::labelColor), rendered by VTK without a screen.
 * Debian's VTK draws through X (GLX) only, so with no DISPLAY the program starts its own virtual
 * X server (Xvfb, drawing with Mesa's software OpenGL) for the picture.
 */
#include <segmat/common/error.h>
#include <segmat/io/atomic_file.h>
#include <segmat/io/cloud.h>
#include <segmat/io/colored_ply.h>
#include <segmat/io/mesh.h>
#include <segmat/io/seg.h>

#include "option_parser.h"
#include "x_display.h"

#include <pcl/console/print.h>

#include <pcl/io/pcd_io.h>

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkNew.h>
#include <vtkPNGWriter.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkPolyDataNormals.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>
#include <vtkUnsignedCharArray.h>
#include <vtkWindowToImageFilter.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <limits>
#include <map>
#include <ostream>
#include <string>
#include <vector>

namespace {

/// The shape as drawn: triangles (mesh) or none (cloud), one label per face or point.
struct Shape
{
  std::vector<Eigen::Vector3d> points;
  std::vector<std::array<int, 3>> faces;
  std::vector<int> labels;
  bool
  isCloud() const
  {
    return faces.empty();
  }
};

bool
isCloudExtension(const std::string& ext)
{
  return ext == "pcd" || ext == "xyz" || ext == "txt";
}

std::vector<int>
loadLabels(const std::string& path, std::size_t count)
{
  if (segmat::io::extensionOf(path) != "pcd")
    return segmat::io::loadSeg(path, static_cast<long>(count));
  pcl::PointCloud<pcl::PointXYZL> labelled;
  if (pcl::io::loadPCDFile(path, labelled) < 0)
    throw segmat::Error(path, 0, "cannot read the labelled PCD (x y z label)");
  if (labelled.size() != count)
    throw segmat::Error(path, 0,
                        std::to_string(labelled.size()) + " labelled points for a shape of " +
                            std::to_string(count) + " points");
  std::vector<int> labels(count);
  for (std::size_t i = 0; i < count; ++i)
    labels[i] = static_cast<int>(labelled[i].label);
  return labels;
}

Shape
loadShape(const std::string& shape_path, const std::string& labels_path)
{
  Shape shape;
  const std::string ext = segmat::io::extensionOf(shape_path);
  bool cloud = isCloudExtension(ext);
  if (!cloud) {
    try {
      const segmat::TriangleMesh mesh = segmat::io::loadMesh(shape_path);
      shape.points = mesh.vertices;
      for (const auto& f : mesh.faces)
        shape.faces.push_back(
            {static_cast<int>(f[0]), static_cast<int>(f[1]), static_cast<int>(f[2])});
    } catch (const segmat::Error&) {
      if (ext != "ply") // a PLY may hold a cloud: read it as one below
        throw;
    }
    cloud = shape.faces.empty();
    if (cloud && ext != "ply")
      throw segmat::Error(shape_path, 0, "the mesh has no faces");
  }
  if (cloud) {
    const segmat::io::LoadedCloud loaded = segmat::io::loadCloud(shape_path);
    shape.points.clear();
    for (const auto& p : *loaded.cloud)
      shape.points.emplace_back(p.x, p.y, p.z);
  }
  const std::size_t count = cloud ? shape.points.size() : shape.faces.size();
  if (count == 0)
    throw segmat::Error(shape_path, 0, "nothing to draw (no face and no point)");
  shape.labels = loadLabels(labels_path, count);
  if (cloud) { // NaN points (organised PCD) have no place in the picture
    std::size_t kept = 0;
    for (std::size_t i = 0; i < shape.points.size(); ++i)
      if (shape.points[i].allFinite()) {
        shape.points[kept] = shape.points[i];
        shape.labels[kept++] = shape.labels[i];
      }
    shape.points.resize(kept);
    shape.labels.resize(kept);
    if (kept == 0)
      throw segmat::Error(shape_path, 0, "no point has finite coordinates");
  }
  return shape;
}

vtkSmartPointer<vtkPolyData>
toPolyData(const Shape& shape)
{
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  for (const Eigen::Vector3d& p : shape.points)
    points->InsertNextPoint(p.x(), p.y(), p.z());
  vtkNew<vtkCellArray> cells;
  if (shape.isCloud())
    for (vtkIdType i = 0; i < static_cast<vtkIdType>(shape.points.size()); ++i)
      cells->InsertNextCell(1, &i);
  else
    for (const auto& f : shape.faces) {
      const vtkIdType ids[3] = {f[0], f[1], f[2]};
      cells->InsertNextCell(3, ids);
    }
  vtkNew<vtkUnsignedCharArray> colors;
  colors->SetName("part colors");
  colors->SetNumberOfComponents(3);
  for (int label : shape.labels) {
    const segmat::io::Rgb c = segmat::io::labelColor(label);
    colors->InsertNextTuple3(c[0], c[1], c[2]);
  }
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  poly->SetPoints(points);
  if (shape.isCloud()) {
    poly->SetVerts(cells);
    poly->GetPointData()->SetScalars(colors);
  } else {
    poly->SetPolys(cells);
    poly->GetCellData()->SetScalars(colors);
  }
  return poly;
}

vtkSmartPointer<vtkActor>
makeActor(const Shape& shape, int point_size)
{
  vtkSmartPointer<vtkPolyData> poly = toPolyData(shape);
  vtkNew<vtkPolyDataMapper> mapper;
  if (shape.isCloud())
    mapper->SetInputData(poly);
  else {
    // Smooth shading within a part, hard edges at creases; PSB meshes are not all consistently
    // oriented, so normals are made consistent and both sides are lit.
    vtkNew<vtkPolyDataNormals> normals;
    normals->SetInputData(poly);
    normals->SetFeatureAngle(50.0);
    normals->ConsistencyOn();
    normals->Update();
    mapper->SetInputConnection(normals->GetOutputPort());
    mapper->SetScalarModeToUseCellData();
  }
  mapper->SetColorModeToDirectScalars();
  mapper->ScalarVisibilityOn();
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  vtkProperty* property = actor->GetProperty();
  // White headlight, no specular: every pixel is its part's colour times a shade in [0.25, 1],
  // so a picture shows the exact hues of the coloured PLY.
  property->SetAmbient(0.25);
  property->SetDiffuse(0.75);
  property->SetSpecular(0.0);
  if (shape.isCloud()) {
    property->SetPointSize(static_cast<float>(point_size));
    property->RenderPointsAsSpheresOn();
  }
  return actor;
}

/// The edges of \a boxes (a triangulated box mesh, PREFIX_boxes.ply): every quad of a box is two
/// triangles, so only edges with a crease (the box's own edges) are drawn, in dark grey over the
/// shape.
vtkSmartPointer<vtkActor>
makeBoxesActor(const segmat::TriangleMesh& boxes)
{
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  for (const Eigen::Vector3d& p : boxes.vertices)
    points->InsertNextPoint(p.x(), p.y(), p.z());
  // An edge is drawn when its two faces are not coplanar (the quads' diagonals are).
  std::map<std::pair<int, int>, std::vector<int>> edge_faces;
  for (std::size_t f = 0; f < boxes.faces.size(); ++f)
    for (int c = 0; c < 3; ++c) {
      const int a = boxes.faces[f][c], b = boxes.faces[f][(c + 1) % 3];
      edge_faces[{std::min(a, b), std::max(a, b)}].push_back(static_cast<int>(f));
    }
  vtkNew<vtkCellArray> lines;
  for (const auto& [edge, faces] : edge_faces) {
    const bool crease =
        faces.size() != 2 || boxes.faceNormal(faces[0]).dot(boxes.faceNormal(faces[1])) < 0.999;
    if (!crease)
      continue;
    const vtkIdType ids[2] = {edge.first, edge.second};
    lines->InsertNextCell(2, ids);
  }
  vtkNew<vtkPolyData> poly;
  poly->SetPoints(points);
  poly->SetLines(lines);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(poly);
  mapper->ScalarVisibilityOff();
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(0.15, 0.15, 0.15);
  actor->GetProperty()->SetLineWidth(2.0f);
  actor->GetProperty()->SetLighting(false);
  return actor;
}

/// Looks at \a points from direction \a toward_eye with \a up, in parallel projection, their
/// projection centred and fitted to the viewport with a 5 % margin.
void
placeCamera(vtkRenderer* renderer, const std::vector<Eigen::Vector3d>& points,
            const Eigen::Vector3d& toward_eye, const Eigen::Vector3d& up, double aspect)
{
  const Eigen::Vector3d back = toward_eye.normalized();
  const Eigen::Vector3d right = up.cross(back).normalized(), top = back.cross(right);
  Eigen::Vector3d low = Eigen::Vector3d::Constant(std::numeric_limits<double>::max());
  Eigen::Vector3d high = -low;
  for (const Eigen::Vector3d& p : points) { // extents along right, top and back
    const Eigen::Vector3d q(p.dot(right), p.dot(top), p.dot(back));
    low = low.cwiseMin(q);
    high = high.cwiseMax(q);
  }
  const Eigen::Vector3d mid = (low + high) / 2, half = (high - low) / 2;
  const Eigen::Vector3d centre = mid.x() * right + mid.y() * top + mid.z() * back;
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->ParallelProjectionOn();
  camera->SetFocalPoint(centre.data());
  const Eigen::Vector3d eye = centre + back * (2.0 * half.norm() + 1e-9);
  camera->SetPosition(eye.data());
  camera->SetViewUp(top.data());
  camera->SetParallelScale(1.05 * std::max({half.y(), half.x() / aspect, 1e-9}));
  renderer->ResetCameraClippingRange();
}

/// The label of every part and the mean of its points (cloud) or face centres (mesh).
std::map<int, Eigen::Vector3d>
partCentres(const Shape& shape)
{
  std::map<int, std::pair<Eigen::Vector3d, double>> sums;
  for (std::size_t i = 0; i < shape.labels.size(); ++i) {
    if (shape.labels[i] < 0)
      continue;
    Eigen::Vector3d p = shape.isCloud() ? shape.points[i] : Eigen::Vector3d::Zero();
    if (!shape.isCloud())
      for (int v : shape.faces[i])
        p += shape.points[v] / 3.0;
    auto& sum = sums.try_emplace(shape.labels[i], Eigen::Vector3d::Zero(), 0.0).first->second;
    sum.first += p;
    sum.second += 1.0;
  }
  std::map<int, Eigen::Vector3d> centres;
  for (const auto& [label, sum] : sums)
    centres[label] = sum.first / sum.second;
  return centres;
}

void
addPartIds(vtkRenderer* renderer, const std::map<int, Eigen::Vector3d>& centres, int font_size)
{
  for (const auto& [label, centre] : centres) {
    renderer->SetWorldPoint(centre.x(), centre.y(), centre.z(), 1.0);
    renderer->WorldToDisplay();
    double display[3];
    renderer->GetDisplayPoint(display);
    vtkNew<vtkTextActor> text;
    text->SetInput(std::to_string(label).c_str());
    vtkTextProperty* tp = text->GetTextProperty();
    tp->SetFontSize(font_size);
    tp->SetColor(0.0, 0.0, 0.0);
    tp->SetBackgroundColor(1.0, 1.0, 1.0);
    tp->SetBackgroundOpacity(0.75);
    tp->SetJustificationToCentered();
    tp->SetVerticalJustificationToCentered();
    text->SetDisplayPosition(static_cast<int>(display[0]), static_cast<int>(display[1]));
    renderer->AddActor2D(text);
  }
}

struct View
{
  const char* name;
  Eigen::Vector3d toward_eye;
  Eigen::Vector3d up;
};

const std::vector<View>&
views()
{
  static const double c30 = std::cos(M_PI / 6), s30 = std::sin(M_PI / 6), s45 = std::sqrt(0.5);
  static const std::vector<View> all{{"front", {0, 0, 1}, {0, 1, 0}},
                                     {"three-quarter", {s45 * c30, s30, s45 * c30}, {0, 1, 0}},
                                     {"top", {0, 1, 0}, {0, 0, -1}}};
  return all;
}

/// Renders \a shape and writes the PNG (atomically).
void
render(const Shape& shape, const std::string& view_name, int width, int height, bool part_ids,
       const segmat::TriangleMesh* boxes, const std::string& out_path)
{
  std::vector<View> chosen;
  for (const View& v : views())
    if (view_name == "all" || view_name == v.name)
      chosen.push_back(v);
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetSize(width, height);
  window->SetMultiSamples(0); // Mesa's software GL under Xvfb: keep the picture deterministic
  const int panel_height = height, panel_width = width / static_cast<int>(chosen.size());
  // Points about as wide as their spacing on screen (a third of the panel covered, half of the
  // points facing the camera), so a sparse cloud still reads as a surface.
  const double spacing = std::sqrt(0.3 * panel_width * panel_height /
                                   (0.5 * std::max<std::size_t>(1, shape.points.size())));
  const int point_size = static_cast<int>(std::clamp(1.2 * spacing, 2.0, 12.0));
  const std::map<int, Eigen::Vector3d> centres =
      part_ids ? partCentres(shape) : std::map<int, Eigen::Vector3d>{};
  for (std::size_t k = 0; k < chosen.size(); ++k) {
    vtkNew<vtkRenderer> renderer;
    renderer->SetViewport(double(k) / chosen.size(), 0.0, double(k + 1) / chosen.size(), 1.0);
    renderer->SetBackground(1.0, 1.0, 1.0);
    renderer->AddActor(makeActor(shape, point_size));
    if (boxes)
      renderer->AddActor(makeBoxesActor(*boxes));
    renderer->TwoSidedLightingOn();
    window->AddRenderer(renderer);
    placeCamera(renderer, shape.points, chosen[k].toward_eye, chosen[k].up,
                double(panel_width) / panel_height);
    if (part_ids)
      addPartIds(renderer, centres, std::max(12, std::min(panel_width, panel_height) / 30));
  }
  window->Render();

  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->SetInputBufferTypeToRGB();
  grab->ReadFrontBufferOff();
  grab->Update();
  vtkNew<vtkPNGWriter> png;
  png->SetInputConnection(grab->GetOutputPort());
  png->WriteToMemoryOn();
  png->Write();
  vtkUnsignedCharArray* bytes = png->GetResult();
  if (!bytes || bytes->GetNumberOfTuples() == 0)
    throw std::runtime_error("VTK produced no picture");
  segmat::io::writeFileAtomically(
      out_path,
      [&](std::ostream& out) {
        out.write(reinterpret_cast<const char*>(bytes->GetPointer(0)),
                  bytes->GetNumberOfTuples() * bytes->GetNumberOfComponents());
      },
      true);
}

/// "800x600" → width and height in [16, 8192]; false otherwise.
bool
parseSize(const std::string& text, int& width, int& height)
{
  const std::size_t x = text.find('x');
  if (x == std::string::npos)
    return false;
  try {
    width = static_cast<int>(segmat::cli::parseInteger(text.substr(0, x), 16, 16384));
    height = static_cast<int>(segmat::cli::parseInteger(text.substr(x + 1), 16, 16384));
  } catch (const segmat::Error&) {
    return false;
  }
  return width <= 8192 && height <= 8192;
}

int
run(int argc, char** argv)
{
  using namespace segmat::cli;
  std::string shape_path, labels_path, out_path, boxes_path, view = "three-quarter";
  int width = 0, height = 0;
  bool part_ids = false;
  OptionParser parser(
      "segmat_render", "SHAPE LABELS -o PICTURE.png [options]",
      "Draws a mesh or a point cloud coloured by part, with the colours of segmat_mesh's and\n"
      "segmat_cloud's coloured PLY (unlabelled, -1, is grey). Without DISPLAY the program\n"
      "starts its own Xvfb (Debian: xvfb).",
      "segmat_render data/teddy/teddy.off teddy.seg -o teddy.png");
  parser.positional("SHAPE",
                    "mesh (.off, .obj, .stl, .ply with faces) or point cloud (.pcd, .xyz,\n"
                    ".txt, .ply without faces)",
                    shape_path);
  parser.positional("LABELS",
                    "one label per face (mesh) or per point (cloud), one per line\n"
                    "(.seg, .labels), or a labelled PCD (x y z label)",
                    labels_path);
  parser.add(kOutput, "-o", "FILE", "the PNG to write (whole or not at all)",
             [&](const std::string& v) { out_path = v; });
  parser.add(kOutput, "--view", "V",
             "camera: front (along -z, y up), three-quarter (45 deg around y, 30 deg\n"
             "above), top (along -y), or all three side by side (default three-quarter)",
             [&](const std::string& v) {
               if (v != "all" && std::none_of(views().begin(), views().end(),
                                              [&](const View& w) { return v == w.name; }))
                 throw segmat::Error("unknown view '" + v + "'");
               view = v;
             });
  parser.add(kOutput, "--size", "WxH",
             "picture size in pixels, 16 to 8192 each (default 800x600; 1800x600\n"
             "with --view all)",
             [&](const std::string& v) {
               if (!parseSize(v, width, height))
                 throw segmat::Error("wants WxH, 16 to 8192 each (e.g. 800x600), not '" + v + "'");
             });
  parser.flag(kOutput, "--part-ids", "write each part's label at its centre", part_ids);
  parser.add(kInput, "--boxes", "FILE",
             "also draw the part boxes (PREFIX_boxes.ply of --boxes) as dark edges",
             [&](const std::string& v) { boxes_path = v; });
  if (!parser.parse(argc, argv))
    return kExitOk;
  if (shape_path.empty() || labels_path.empty() || out_path.empty())
    throw UsageError("SHAPE, LABELS and -o are required");
  if (width == 0) {
    width = view == "all" ? 1800 : 800;
    height = 600;
  }

  Shape shape;
  segmat::TriangleMesh boxes;
  asInput([&] {
    shape = loadShape(shape_path, labels_path);
    if (!boxes_path.empty()) {
      // The boxes' face colours are PLY properties PCL's mesh reader does not take: not a fault.
      pcl::console::setVerbosityLevel(pcl::console::L_ERROR);
      boxes = segmat::io::loadMesh(boxes_path);
      if (boxes.empty())
        throw segmat::Error(boxes_path, 0, "no box faces to draw");
    }
  });
  // X only after the inputs are checked: bad input fails fast.
  try {
    const XDisplay display;
    render(shape, view, width, height, part_ids, boxes_path.empty() ? nullptr : &boxes, out_path);
  } catch (const std::exception& e) {
    throw segmat::Error(out_path + ": " + e.what());
  }
  return kExitOk;
}

} // namespace

int
main(int argc, char** argv)
{
  return segmat::cli::runMain("segmat_render", [&] { return run(argc, argv); });
}
