/*
 * segmat — 3D shape segmentation with the medial axis transform.
 * SPDX-License-Identifier: BSD-3-Clause
 */
// segment_mesh, segment_cloud, MeshSegmenter, CloudSegmenter. The free functions are a segmenter
// used once, so both share one code path.
#include "adapter.h"
#include "arrays.h"
#include "bindings.h"

#include <segmat/common/error.h>

#include <pybind11/stl.h>

#include <chrono>
#include <cmath>
#include <memory>
#include <mutex>
#include <sstream>
#include <string>

namespace segmat_python {

namespace {

/** Which keywords a call takes. */
enum class Accepts
{
  Any,     ///< segment_mesh(), segment_cloud()
  Medial,  ///< a segmenter's constructor: what changes the medial step
  Cheap    ///< a segmenter's segment(): what leaves the medial step as it is
};

template <typename S>
struct Setting
{
  const Parameter<S>* parameter;
  double value;
};

std::string
formatNumber(double value)
{
  std::ostringstream out;
  out.precision(17);
  out << value;
  return out.str();
}

/** The keyword arguments as settings; unknown or misplaced names raise TypeError, values of the
 * wrong type TypeError, values the C++ type cannot hold ValueError. */
template <typename S>
std::vector<Setting<S>>
parseKeywords(const std::vector<Parameter<S>>& table, const py::kwargs& kwargs,
              const std::string& function, Accepts accepts)
{
  std::vector<Setting<S>> settings;
  for (const auto& item : kwargs) {
    const std::string name = py::str(item.first);
    const Parameter<S>* parameter = nullptr;
    for (const Parameter<S>& p : table)
      if (name == p.name)
        parameter = &p;
    if (parameter == nullptr) {
      std::string known;
      for (const Parameter<S>& p : table)
        known += (known.empty() ? "" : ", ") + std::string(p.name);
      throw py::type_error(function + "() got an unexpected keyword argument '" + name +
                           "' (known: " + known + ")");
    }
    if (accepts == Accepts::Cheap && parameter->medial)
      throw py::type_error(function + "(): '" + name +
                           "' changes the medial step: give it to the constructor");
    if (accepts == Accepts::Medial && !parameter->medial)
      throw py::type_error(function + "(): '" + name + "' is a segment() argument");
    const py::handle value = item.second;
    double number = 0.0;
    const bool is_bool = PyBool_Check(value.ptr());
    if (parameter->kind == ParameterKind::Flag) {
      if (!is_bool)
        throw py::type_error(function + "(): '" + name + "' must be True or False");
      number = value.ptr() == Py_True ? 1.0 : 0.0;
    }
    else if (parameter->kind == ParameterKind::Whole) {
      if (is_bool || !PyIndex_Check(value.ptr()))
        throw py::type_error(function + "(): '" + name + "' must be an integer");
      const py::object index = py::reinterpret_steal<py::object>(PyNumber_Index(value.ptr()));
      if (!index)
        throw py::error_already_set();
      int overflow = 0;
      const long long whole = PyLong_AsLongLongAndOverflow(index.ptr(), &overflow);
      // beyond long long: out of every range below
      number = overflow != 0 ? overflow * HUGE_VAL : static_cast<double>(whole);
    }
    else {
      if (is_bool || !PyNumber_Check(value.ptr()) || PyComplex_Check(value.ptr()))
        throw py::type_error(function + "(): '" + name + "' must be a real number");
      number = py::cast<double>(py::float_(py::reinterpret_borrow<py::object>(value)));
    }
    if (!std::isfinite(number) || number < parameter->lowest || number > parameter->highest)
      throw py::value_error(function + "(): " + name + "=" + std::string(py::repr(value)) +
                            " is out of range");
    settings.push_back({parameter, number});
  }
  return settings;
}

/** Sets \a settings on \a s; a value the setter refuses (it warns and keeps the old one) gives
 * the message for a ValueError, so the library's own rules decide. */
template <typename S>
std::string
applySettings(S& s, const std::vector<Setting<S>>& settings, const std::string& function)
{
  for (const Setting<S>& setting : settings) {
    setting.parameter->set(s, setting.value);
    const double taken = setting.parameter->get(s);
    if (taken != setting.value)
      return function + "(): " + setting.parameter->name + "=" + formatNumber(setting.value) +
             " is not accepted (" + setting.parameter->doc + "; see the warning above)";
  }
  return {};
}

/** Computes the medial step once per input and segments with any parameters (the C++ split of
 * medial step and segmentation). One segment() at a time per object; others wait without the
 * GIL. */
template <typename S>
class Segmenter
{
public:
  Segmenter(const std::vector<Parameter<S>>& table, std::string name, std::string counts_key)
    : table_(table), name_(std::move(name)), counts_key_(std::move(counts_key))
  {
    for (const Parameter<S>& p : table_)
      defaults_.push_back(p.get(s_));
  }

  S&
  segmentation()
  {
    return s_;
  }

  void
  configure(const py::kwargs& kwargs, Accepts accepts)
  {
    const std::string error = applySettings(s_, parseKeywords(table_, kwargs, name_, accepts), name_);
    if (!error.empty())
      throw py::value_error(error);
  }

  /** Labels with the library defaults for every segment() parameter not in \a kwargs. */
  py::array_t<int>
  segment(const py::kwargs& kwargs, const std::string& function)
  {
    const std::vector<Setting<S>> settings = parseKeywords(table_, kwargs, function, Accepts::Cheap);
    std::vector<int> labels;
    std::string error;
    bool ok = false;
    {
      py::gil_scoped_release release;
      std::lock_guard<std::mutex> lock(mutex_);
      for (std::size_t i = 0; i < table_.size(); ++i)
        if (!table_[i].medial)
          table_[i].set(s_, defaults_[i]);
      error = applySettings(s_, settings, function);
      if (error.empty()) {
        RunInfo info;
        const auto start = std::chrono::steady_clock::now();
        ok = segmat_python::segment(s_, labels, info);
        info.cpp_seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        if (ok) {
          const auto mats = medialMeshes(s_);
          if (mats.first != base_) {
            ++mat_computations_;
            base_ = mats.first;
            structured_ = mats.second;
          }
          counts_.clear();
          for (int l : labels)
            if (l >= 0) {
              if (static_cast<std::size_t>(l) >= counts_.size())
                counts_.resize(l + 1, 0);
              ++counts_[l];
            }
          last_ = info;
          segmented_ = true;
        }
      }
    }
    if (!error.empty())
      throw py::value_error(error);
    if (!ok)
      throw segmat::Error(function + "(): the segmentation failed; the message above says why "
                                     "(e.g. a surface that encloses no volume)");
    return toArray(std::move(labels));
  }

  /** The last segment()'s counts and seconds (the programs' --json), None before any. */
  py::object
  info()
  {
    RunInfo last;
    std::vector<std::size_t> counts;
    bool segmented = false;
    int mat_computations = 0;
    {
      py::gil_scoped_release release;
      std::lock_guard<std::mutex> lock(mutex_);
      last = last_;
      counts = counts_;
      segmented = segmented_;
      mat_computations = mat_computations_;
    }
    if (!segmented)
      return py::none();
    py::dict seconds;
    for (const auto& stage : last.stage_seconds)
      seconds[py::str(stage.name)] = stage.seconds;
    py::dict d;
    d["parts"] = counts.size();
    d[py::str(counts_key_)] = py::cast(counts);
    d["seconds"] = seconds;
    d["cpp_seconds"] = last.cpp_seconds;
    d["mat_computations"] = mat_computations;
    d["base_spheres"] = last.base_spheres;
    d["structured_spheres"] = last.structured_spheres;
    py::dict noise;
    noise["sigma"] = last.noise_sigma;
    if (last.cloud)
      noise["spacing"] = last.noise_spacing;
    noise["remaining_sigma"] = last.noise_remaining;
    noise["passes"] = last.denoising_passes;
    d["noise"] = noise;
    d["samples"] = last.samples;
    d["initial_spheres"] = last.initial_spheres;
    if (!last.cloud)
      d["mat_computed"] = last.mat_computed;
    return std::move(d);
  }

  py::object
  medialMesh(bool structured)
  {
    segmat::MedialMesh::ConstPtr mat;
    {
      py::gil_scoped_release release;
      std::lock_guard<std::mutex> lock(mutex_);
      mat = structured ? structured_ : base_;
    }
    if (!mat)
      return py::none();
    return toArrays(mat);
  }

  int
  matComputations()
  {
    py::gil_scoped_release release;
    std::lock_guard<std::mutex> lock(mutex_);
    return mat_computations_;
  }

  /** Current value of every parameter (segment() parameters: their defaults between calls). */
  py::dict
  parameters()
  {
    std::vector<double> values;
    {
      py::gil_scoped_release release;
      std::lock_guard<std::mutex> lock(mutex_);
      for (const Parameter<S>& p : table_)
        values.push_back(p.get(s_));
    }
    return parameterDict(table_, values);
  }

  static py::dict
  parameterDict(const std::vector<Parameter<S>>& table, const std::vector<double>& values)
  {
    py::dict d;
    for (std::size_t i = 0; i < table.size(); ++i) {
      const Parameter<S>& p = table[i];
      if (p.kind == ParameterKind::Flag)
        d[p.name] = values[i] != 0.0;
      else if (p.kind == ParameterKind::Whole)
        d[p.name] = static_cast<long long>(values[i]);
      else
        d[p.name] = values[i];
    }
    return d;
  }

private:
  const std::vector<Parameter<S>>& table_;
  std::string name_, counts_key_;
  S s_;
  std::vector<double> defaults_;
  std::mutex mutex_;
  RunInfo last_;
  std::vector<std::size_t> counts_;
  bool segmented_ = false;
  int mat_computations_ = 0;
  segmat::MedialMesh::ConstPtr base_, structured_;
};

class MeshSegmenter : public Segmenter<segmat::MeshSegmentation>
{
public:
  MeshSegmenter(const py::handle& vertices, const py::handle& faces, const py::kwargs& kwargs,
                Accepts accepts = Accepts::Medial)
    : Segmenter(meshParameters(), "MeshSegmenter", "face_counts")
  {
    configure(kwargs, accepts);
    setInput(segmentation(), toMesh(vertices, faces));
  }
};

class CloudSegmenter : public Segmenter<CloudSegmentation>
{
public:
  CloudSegmenter(const py::handle& points, const py::handle& normals, const py::kwargs& kwargs,
                 Accepts accepts = Accepts::Medial)
    : Segmenter(cloudParameters(), "CloudSegmenter", "point_counts")
  {
    configure(kwargs, accepts);
    setInput(segmentation(), toCloud(points, normals), !normals.is_none());
  }
};

/** The keywords of \a kwargs that \a medial says go to the constructor (or the others). */
template <typename S>
py::kwargs
splitKeywords(const std::vector<Parameter<S>>& table, const py::kwargs& kwargs, bool medial)
{
  py::kwargs part;
  for (const auto& item : kwargs) {
    const std::string name = py::str(item.first);
    bool is_medial = false;
    for (const Parameter<S>& p : table)
      is_medial = is_medial || (name == p.name && p.medial);
    if (is_medial == medial)
      part[item.first] = item.second;
  }
  return part;
}

template <typename S>
py::dict
defaultParameters(const std::vector<Parameter<S>>& table)
{
  S s;
  std::vector<double> values;
  for (const Parameter<S>& p : table)
    values.push_back(p.get(s));
  return Segmenter<S>::parameterDict(table, values);
}

/** Docstring lines for the keywords of \a table. */
template <typename S>
std::string
keywordDoc(const std::vector<Parameter<S>>& table)
{
  S s;
  std::string doc = "\nKeyword arguments (library defaults):\n";
  for (const Parameter<S>& p : table)
    doc += "  " + std::string(p.name) + " = " + formatNumber(p.get(s)) + ": " + p.doc +
           (p.medial ? " [medial step]" : "") + "\n";
  return doc;
}

template <typename SegmenterT>
py::class_<SegmenterT>
bindSegmenter(py::module_& m, const char* name, const std::string& doc)
{
  py::class_<SegmenterT> c(m, name, doc.c_str());
  c.def("segment",
           [name](SegmenterT& s, const py::kwargs& kwargs) {
             return s.segment(kwargs, std::string(name) + ".segment");
           },
           "Labels with the given segment() parameters (the others at their defaults); reuses "
           "the medial step of earlier calls where the C++ class keeps it.")
      .def_property_readonly("info", &SegmenterT::info,
                             "The last segment()'s parts, counts, seconds per stage "
                             "(the command-line program's --json) and cpp_seconds; None before.")
      .def_property_readonly("mat_computations", &SegmenterT::matComputations,
                             "How many segment() calls computed the medial meshes.")
      .def_property_readonly("parameters", &SegmenterT::parameters,
                             "Every parameter's current value.")
      .def_property_readonly(
          "base_mat", [](SegmenterT& s) { return s.medialMesh(false); },
          "(centers, radii, edges, triangles) of the base medial mesh of the last segment().")
      .def_property_readonly(
          "structured_mat", [](SegmenterT& s) { return s.medialMesh(true); },
          "(centers, radii, edges, triangles) of the structured medial mesh.");
  return c;
}

} // namespace

void
bindSegmentation(py::module_& m)
{
  const std::string mesh_keys = keywordDoc(meshParameters());
  const std::string cloud_keys = keywordDoc(cloudParameters());

  m.def(
      "segment_mesh",
      [](const py::handle& vertices, const py::handle& faces, const py::kwargs& kwargs) {
        MeshSegmenter s(vertices, faces, splitKeywords(meshParameters(), kwargs, true),
                        Accepts::Any);
        return s.segment(splitKeywords(meshParameters(), kwargs, false), "segment_mesh");
      },
      py::arg("vertices"), py::arg("faces"),
      ("Parts of a closed triangle mesh (SEG-MAT). vertices: (n, 3) float, faces: (m, 3) int. "
       "Returns one label per face (int32, 0 = largest part).\n" + mesh_keys).c_str());
  m.def(
      "segment_cloud",
      [](const py::handle& points, const py::handle& normals, const py::kwargs& kwargs) {
        CloudSegmenter s(points, normals, splitKeywords(cloudParameters(), kwargs, true),
                         Accepts::Any);
        return s.segment(splitKeywords(cloudParameters(), kwargs, false), "segment_cloud");
      },
      py::arg("points"), py::arg("normals") = py::none(),
      ("Parts of a point cloud (SEG-MAT's cloud path). points: (n, 3) float; normals: (n, 3) "
       "float or None (estimated). Returns one label per point (int32).\n" + cloud_keys).c_str());
  m.def("default_parameters",
        [](const std::string& kind) {
          if (kind == "mesh")
            return defaultParameters(meshParameters());
          if (kind == "cloud")
            return defaultParameters(cloudParameters());
          throw py::value_error("default_parameters(): kind is 'mesh' or 'cloud', not '" + kind +
                                "'");
        },
        py::arg("kind") = "mesh", "The library defaults of every keyword, 'mesh' or 'cloud'.");

  bindSegmenter<MeshSegmenter>(
      m, "MeshSegmenter",
      "MeshSegmenter(vertices, faces, **medial_keywords): computes the medial meshes at the "
      "first segment() and reuses them for every later one.\n" + mesh_keys)
      .def(py::init([](const py::handle& v, const py::handle& f, const py::kwargs& kwargs) {
             return std::make_unique<MeshSegmenter>(v, f, kwargs);
           }),
           py::arg("vertices"), py::arg("faces"));
  bindSegmenter<CloudSegmenter>(
      m, "CloudSegmenter",
      "CloudSegmenter(points, normals=None, **medial_keywords): segments one cloud with "
      "several parameter sets. The C++ CloudSegmentation computes its medial step in every "
      "segment() (see mat_computations).\n" + cloud_keys)
      .def(py::init([](const py::handle& p, const py::handle& n, const py::kwargs& kwargs) {
             return std::make_unique<CloudSegmenter>(p, n, kwargs);
           }),
           py::arg("points"), py::arg("normals") = py::none());
}

} // namespace segmat_python
