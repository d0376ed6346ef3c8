// The Python module's C++ half (`papercraft._papercraft`): the loader and the pipeline on numpy
// arrays. The Python half (papercraft/__init__.py) turns what this returns into the documented
// API. Uses pybind11 2.10's API only (Debian 12's).
//
// run() hands the arrays to the same loader as the command line (written losslessly as an OFF
// into a private temporary folder, so its repairs and errors are the command line's), runs the
// pipeline into that folder with the GIL released, keeps every output file in memory and
// removes the folder before it returns: nothing is left on disk until Result.write(folder).

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>

#include "core/atomic_file.h"
#include "core/errors.h"
#include "graph/config.h"
#include "graph/pipeline.h"
#include "graph/registry.h"
#include "nodes/load/openmesh.h"
#include "runner/batch_journal.h"
#include "runner/batch_row.h"
#include "runner/batch_summary.h"
#include "runner/run_models.h"

namespace py = pybind11;

namespace papercraft::python {
namespace {

constexpr const char* kArrays = "<arrays>";

// An array's shape as numpy prints it: "(4, 2)".
std::string shape_of(const py::array& a) {
  return py::str(py::tuple(py::cast(std::vector<py::ssize_t>(a.shape(), a.shape() + a.ndim()))));
}

// The vertices as an (n, 3) array of finite float64, checked.
py::array_t<double, py::array::c_style> checked_vertices(const py::array& v) {
  if (v.ndim() != 2 || v.shape(1) != 3)
    throw py::value_error("vertices must be an (n, 3) array, got shape " + shape_of(v));
  const char kind = v.dtype().kind();
  if (kind != 'f' && kind != 'i' && kind != 'u')
    throw py::value_error("vertices must be numbers (float or integer), got dtype " +
                          std::string(py::str(v.dtype())));
  auto a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(v);
  if (!a) throw py::value_error("vertices cannot be read as float64");
  const double* p = a.data();
  for (py::ssize_t i = 0; i < a.shape(0); ++i)
    for (int k = 0; k < 3; ++k)
      if (!std::isfinite(p[3 * i + k]))
        throw py::value_error("vertex " + std::to_string(i) + " is not finite (" +
                              std::to_string(p[3 * i + k]) + ")");
  return a;
}

py::array_t<long long, py::array::c_style> checked_faces(const py::array& f, py::ssize_t vertices) {
  if (f.ndim() != 2 || f.shape(1) != 3)
    throw py::value_error("faces must be an (m, 3) array of vertex indices, got shape " +
                          shape_of(f));
  const char kind = f.dtype().kind();
  if (kind != 'i' && kind != 'u')
    throw py::value_error("faces must be integers, got dtype " + std::string(py::str(f.dtype())));
  auto a = py::array_t<long long, py::array::c_style | py::array::forcecast>::ensure(f);
  if (!a) throw py::value_error("faces cannot be read as integers");
  if (a.shape(0) == 0) throw py::value_error("faces: the mesh has no faces");
  const long long* p = a.data();
  for (py::ssize_t i = 0; i < 3 * a.shape(0); ++i)
    if (p[i] < 0 || p[i] >= vertices)
      throw py::value_error("face " + std::to_string(i / 3) + " has vertex index " +
                            std::to_string(p[i]) + ", out of range for " +
                            std::to_string(vertices) + " vertices");
  return a;
}

// The checked arrays as a mesh in memory.
std::shared_ptr<const TriangleMesh> mesh_of(const py::array_t<double, py::array::c_style>& v,
                                            const py::array_t<long long, py::array::c_style>& f) {
  auto mesh = std::make_shared<TriangleMesh>();
  const double* p = v.data();
  mesh->vertices.reserve(v.shape(0));
  for (py::ssize_t i = 0; i < v.shape(0); ++i)
    mesh->vertices.emplace_back(p[3 * i], p[3 * i + 1], p[3 * i + 2]);
  const long long* t = f.data();
  mesh->triangles.reserve(f.shape(0));
  for (py::ssize_t i = 0; i < f.shape(0); ++i)
    mesh->triangles.push_back({static_cast<int>(t[3 * i]), static_cast<int>(t[3 * i + 1]),
                               static_cast<int>(t[3 * i + 2])});
  return mesh;
}

// A Python value as YAML.
YAML::Node yaml_of(const py::handle& value) {
  if (py::isinstance<py::bool_>(value)) return YAML::Node(value.cast<bool>());
  if (py::isinstance<py::int_>(value)) return YAML::Node(value.cast<long long>());
  if (py::isinstance<py::float_>(value)) return YAML::Node(value.cast<double>());
  if (py::isinstance<py::str>(value)) return YAML::Node(value.cast<std::string>());
  if (py::isinstance<py::list>(value) || py::isinstance<py::tuple>(value)) {
    YAML::Node list(YAML::NodeType::Sequence);
    for (const py::handle item : value) list.push_back(yaml_of(item));
    return list;
  }
  throw py::value_error("a node parameter must be a bool, number, string or list, got " +
                        std::string(py::str(value.get_type())));
}

// The config to run: the builtin one, a file or YAML text, with node parameters set over it
// ({"layout.page": "A3"}) and the json files always written (Result reads them).
PipelineConfig config_of(const std::optional<std::string>& config, const py::dict& node_params) {
  const Registry& registry = builtin_registry();
  std::string text = default_config_text();
  std::string file = "<builtin default.yaml>";
  if (config) {
    std::error_code ec;
    if (config->find('\n') == std::string::npos && std::filesystem::is_regular_file(*config, ec)) {
      std::ifstream in(*config);
      std::stringstream buffer;
      buffer << in.rdbuf();
      text = buffer.str();
      file = *config;
    } else {
      text = *config;
      file = "<config text>";
    }
  }
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::Exception& e) {
    throw py::value_error(file + ": " + e.what());
  }
  if (!root.IsMap() || !root["nodes"] || !root["nodes"].IsMap())
    return parse_pipeline_config(text, file, registry);  // its own message
  bool changed = false;
  for (const auto& [key, value] : node_params) {
    const std::string name = py::str(key);
    const std::size_t dot = name.find('.');
    if (dot == std::string::npos || dot == 0 || dot + 1 == name.size())
      throw py::value_error("unknown parameter '" + name +
                            "' (node parameters are given as 'node.param', e.g. 'layout.page')");
    const std::string node = name.substr(0, dot), param = name.substr(dot + 1);
    if (!root["nodes"][node])
      throw py::value_error("unknown node '" + node + "' in parameter '" + name + "'");
    root["nodes"][node]["params"][param] = yaml_of(value);
    changed = true;
  }
  for (auto entry : root["nodes"]) {
    YAML::Node node = entry.second;
    if (node["impl"] && node["impl"].as<std::string>() == "export.files" && node["params"] &&
        node["params"]["formats"]) {
      bool json = false;
      for (auto f : node["params"]["formats"]) json = json || f.as<std::string>() == "json";
      if (!json) {
        node["params"]["formats"].push_back("json");
        changed = true;
      }
    }
  }
  // Unchanged, the text is parsed as given, so its messages name the file's own lines.
  if (!changed) return parse_pipeline_config(text, file, registry);
  YAML::Emitter out;
  out << root;
  return parse_pipeline_config(out.c_str(), file + " with parameters", registry);
}

// What run() made: the files of the model's folder, in memory, and its summary row.
struct RunOutput {
  std::string name;
  std::map<std::string, py::bytes> files;
  ModelResult result;
  double started_at = 0.0, finished_at = 0.0;  // the run's, unix seconds

  void write(const std::string& folder) const {
    const std::filesystem::path out(folder);
    std::error_code ec;
    std::filesystem::create_directories(out, ec);
    if (ec) throw IOException(folder + ": cannot create folder: " + ec.message());
    const std::filesystem::path partial = out / ("." + name + ".partial");
    std::filesystem::remove_all(partial, ec);
    std::filesystem::create_directories(partial, ec);
    if (ec) throw IOException(partial.string() + ": cannot create folder: " + ec.message());
    for (const auto& [file, bytes] : files) write_file_atomic(partial / file, std::string(bytes));
    const std::filesystem::path final_dir = out / name;
    std::filesystem::remove_all(final_dir, ec);
    std::filesystem::rename(partial, final_dir, ec);
    if (ec) throw IOException(final_dir.string() + ": cannot write: " + ec.message());
    // run.json and run.jsonl, as `papercraft run` writes them, with the run's own times.
    JournalOptions options;
    options.files = run_summary_files(out);
    options.ran_from = started_at;
    options.ran_to = finished_at;
    BatchJournal journal(options, {pending_row(name, kArrays)});
    journal.started(0);
    BatchRow row = row_from_result(result, out, finished_at);
    row.input = kArrays;
    journal.record(0, row);
    journal.close("");
  }
};

py::tuple load(const std::string& path) {
  LoadedMesh loaded;
  {
    py::gil_scoped_release release;
    loaded = load_mesh(path);
  }
  const Mesh& mesh = loaded.mesh;
  py::array_t<double> v({static_cast<py::ssize_t>(mesh.n_vertices()), py::ssize_t{3}});
  auto vv = v.mutable_unchecked<2>();
  for (auto h : mesh.vertices())
    for (int k = 0; k < 3; ++k) vv(h.idx(), k) = mesh.point(h)[k];
  py::array_t<int> f({static_cast<py::ssize_t>(mesh.n_faces()), py::ssize_t{3}});
  auto ff = f.mutable_unchecked<2>();
  for (auto face : mesh.faces()) {
    int k = 0;
    for (auto h : face.vertices()) ff(face.idx(), k++) = h.idx();
  }
  return py::make_tuple(v, f);
}

RunOutput run(const py::array& vertices, const py::array& faces, const std::string& tolerance,
              std::optional<double> height_mm, int threads, std::optional<std::string> config,
              const std::string& name, const py::dict& paper, const py::dict& node_params) {
  const auto v = checked_vertices(vertices);
  const auto f = checked_faces(faces, v.shape(0));
  if (name.empty() || name.find('/') != std::string::npos || name[0] == '.')
    throw py::value_error("name must be a plain folder name, got '" + name + "'");
  if (threads < 0)
    throw py::value_error("threads must be at least 0, got " + std::to_string(threads));
  PipelineConfig pipeline_config = config_of(config, node_params);
  RunRequest request;
  if (!tolerance.empty()) request.tolerance = parse_tolerance_option(tolerance);
  request.height_mm = height_mm;
  request.threads = threads;
  for (const auto& [key, value] : paper) {
    const std::string k = py::str(key);
    if (k == "min_width_mm")
      request.min_width_mm = value.cast<double>();
    else if (k == "min_area_mm2")
      request.min_area_mm2 = value.cast<double>();
    else if (k == "scale")
      request.scale = value.cast<double>();
    else if (k == "max_pages")
      request.max_pages = value.cast<int>();
    else if (k == "allow_large_tolerance")
      request.allow_large_tolerance = value.cast<bool>();
    else
      throw py::value_error("unknown parameter '" + k + "'");
  }
  if (request.scale) request.height_mm.reset();
  // Nothing is written: the mesh goes in as arrays, the files come back in memory.
  request.output = "<memory>";
  const std::shared_ptr<RunSettings> settings = run_settings(request, pipeline_config);
  settings->keep_in_memory = true;

  if (v.shape(0) > std::numeric_limits<int>::max() - 1)
    throw py::value_error("vertices: more than " +
                          std::to_string(std::numeric_limits<int>::max() - 1) + " vertices");
  const std::shared_ptr<const TriangleMesh> mesh = mesh_of(v, f);

  RunOutput output;
  output.name = name;
  std::map<std::string, std::string> files;
  {
    py::gil_scoped_release release;
    Pipeline pipeline(std::move(pipeline_config), builtin_registry());
    PipelineOptions options;
    options.threads = settings->threads;
    options.names = {name};
    options.meshes = {mesh};
    options.on_model_done = [&files](const ModelRun& model, const ModelResult&) {
      files = model.files();
    };
    output.started_at = unix_seconds_now();
    output.result = pipeline.run({kArrays}, settings, options).at(0);
    output.finished_at = unix_seconds_now();
  }
  for (const auto& [file, bytes] : files) output.files.emplace(file, py::bytes(bytes));
  if (!output.result.ok) {
    if (output.result.internal_error) throw std::runtime_error(output.result.error);
    throw py::value_error(output.result.error);
  }
  return output;
}

}  // namespace
}  // namespace papercraft::python

PYBIND11_MODULE(_papercraft, m) {
  using namespace papercraft;
  using namespace papercraft::python;
  m.doc() = "papercraft's C++ core; use the papercraft package";
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const InvalidInputException& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    } catch (const ConfigException& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    } catch (const IOException& e) {
      PyErr_SetString(PyExc_OSError, e.what());
    }
  });
  py::class_<RunOutput>(m, "RunOutput")
      .def_readonly("name", &RunOutput::name)
      .def_readonly("files", &RunOutput::files)
      .def("write", &RunOutput::write, py::arg("folder"));
  m.def("load", &load, py::arg("path"));
  m.def("run", &run, py::arg("vertices"), py::arg("faces"), py::arg("tolerance"),
        py::arg("height_mm"), py::arg("threads"), py::arg("config"), py::arg("name"),
        py::arg("paper"), py::arg("node_params"));
  m.attr("__version__") = PAPERCRAFT_VERSION;
}
