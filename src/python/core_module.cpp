// sinew._core: the library entry point (sinew/simulation.hpp) for Python (pybind11). python/sinew
// calls it from Scene.run() and spacarlight(); see docs/python.md.
//
//   _core.run(scene, flags=None, comm=None, echo=False, base_dir=".", as_text=False)
//     scene: the scene as a dict (sinew.Scene.data: nodes, elements, nprops, eprops, opt, ...),
//            or a scene file path (str); a dict goes to the reader as the YAML tree its text would
//            give (python_scene.hpp), without text (as_text: as text, for tests)
//     flags: command-line flags as a list of words (["-loadsteps", "5", "-snes_monitor"]) or a dict
//            ({"loadsteps": 5, "calcbuck": True, "gravity": [0, 0, -9.81]})
//     comm:  an mpi4py communicator (default: MPI_COMM_WORLD)
//   returns {"exit_code", "message", "output", "file", "datasets": {name: numpy array},
//            "attrs": {root attribute: int or str}, "group_attrs": {group: {attribute: str}}};
//   a run that produced no results returns "datasets": None with its exit code and message; a run
//   of a dict to memory returns "scene_text", a function that makes the scene text (attrs "scene").
// PETSc and SLEPc start at the first run (without PETSc's signal handlers, which would take Ctrl-C
// from the interpreter) and end at interpreter exit (finalize(), registered by python/sinew).
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "python/python_scene.hpp"
#include "scene/scene_tree.hpp"
#include "sinew/simulation.hpp"

namespace py = pybind11;

namespace {

/// A flag's value as the command line would give it: true/false, comma lists, text.
std::string flagValue(const py::handle& v) {
  if (v.is_none()) return "";
  if (py::isinstance<py::bool_>(v)) return v.cast<bool>() ? "true" : "false";
  if (py::hasattr(v, "tolist") && !py::isinstance<py::str>(v)) return flagValue(v.attr("tolist")());
  if (py::isinstance<py::list>(v) || py::isinstance<py::tuple>(v)) {
    std::string s;
    for (const py::handle item : v) s += (s.empty() ? "" : ",") + flagValue(item);
    return s;
  }
  return py::str(v).cast<std::string>();
}

/// A word of a flag list that names a flag: "-name", but not a negative number ("-9.81").
bool isFlagWord(const std::string& w) {
  return w.size() > 1 && w[0] == '-' && !(std::isdigit(static_cast<unsigned char>(w[1])) || w[1] == '.');
}

std::vector<sinew::Flag> flagsOf(const py::object& flags) {
  std::vector<sinew::Flag> out;
  if (flags.is_none()) return out;
  if (py::isinstance<py::dict>(flags)) {
    for (const auto& [key, value] : py::reinterpret_borrow<py::dict>(flags)) {
      std::string name = py::str(key).cast<std::string>();
      if (!name.empty() && name[0] == '-') name.erase(0, 1);
      out.emplace_back(name, flagValue(value));
    }
    return out;
  }
  std::vector<std::string> words;
  for (const py::handle w : flags) words.push_back(py::str(w).cast<std::string>());
  for (std::size_t i = 0; i < words.size(); ++i) {
    if (!isFlagWord(words[i])) throw sinew::RunError(2, "error: flag list: " + words[i] + " follows no flag");
    const std::string name = words[i].substr(1);
    std::string value;
    if (i + 1 < words.size() && !isFlagWord(words[i + 1])) value = words[++i];
    out.emplace_back(name, value);
  }
  return out;
}

MPI_Comm commOf(const py::object& comm) {
  if (comm.is_none()) return MPI_COMM_WORLD;
  return MPI_Comm_f2c(comm.attr("py2f")().cast<MPI_Fint>());  // an mpi4py communicator
}

py::array arrayOf(const std::string& name, const sinew::ResultArray& a) {
  std::vector<py::ssize_t> shape(a.shape.begin(), a.shape.end());
  if (static_cast<std::size_t>(a.size()) != (a.integer ? a.integers.size() : a.values.size()))
    throw std::logic_error("sinew._core: dataset /" + name + ": values do not fill its shape");
  if (a.integer) {
    py::array_t<std::int64_t> out(shape);
    std::copy(a.integers.begin(), a.integers.end(), out.mutable_data());
    return out;
  }
  py::array_t<double> out(shape);
  std::copy(a.values.begin(), a.values.end(), out.mutable_data());
  return out;
}

/// PETSc/SLEPc for this process (once), with extra PETSc options; -no_signal_handler keeps Ctrl-C
/// (SIGINT) and the other signals the interpreter's.
void start(const std::vector<std::string>& options) {
  std::vector<std::string> words{"sinew", "-no_signal_handler"};
  words.insert(words.end(), options.begin(), options.end());
  std::vector<char*> argv;
  for (std::string& w : words) argv.push_back(w.data());
  argv.push_back(nullptr);
  int argc = static_cast<int>(words.size());
  char** args = argv.data();
  sinew::initialize(&argc, &args);
}

/// The scene text of a run's tree, made when called (a run to memory makes none).
struct SceneText {
  std::shared_ptr<const YAML::Node> tree;
  std::string operator()() const { return sinew::sceneTreeText(*tree); }
};

std::string sceneText(const py::object& scene) {
  YAML::Emitter text;
  sinew::python::emitScene(text, scene);
  return text.c_str();
}

/// The scene of a run: a file, or the object's YAML tree (its text when a string would not read
/// back as itself, or asText: the text path, for tests).
sinew::SceneSource sourceOf(const py::object& scene, const std::string& baseDir, bool asText) {
  if (py::isinstance<py::str>(scene)) return sinew::SceneSource::file(scene.cast<std::string>());
  if (!asText)
    if (std::optional<YAML::Node> tree = sinew::python::sceneTree(scene)) return sinew::SceneSource::yamlTree(*tree, baseDir);
  return sinew::SceneSource::yaml(sceneText(scene), baseDir);
}

/// "" when the object's tree is node for node YAML::Load of its text, else the first difference.
std::string treeCheck(const py::object& scene) {
  const std::optional<YAML::Node> tree = sinew::python::sceneTree(scene);
  if (!tree) return "no tree: a string does not read back as itself";
  const std::string text = sceneText(scene);
  if (const std::string d = sinew::treeDifference(*tree, YAML::Load(text)); !d.empty()) return d;
  if (sinew::sceneTreeText(*tree) != text) return "the tree's text differs from the object's text";
  return "";
}

py::dict run(const py::object& scene, const py::object& flags, const py::object& comm, bool echo,
             const std::string& baseDir, bool asText) {
  const sinew::SceneSource source = sourceOf(scene, baseDir, asText);
  py::dict result;
  result["datasets"] = py::none();
  try {
    const std::vector<sinew::Flag> pairs = flagsOf(flags);
    start({});
    sinew::RunOutput out = sinew::run(commOf(comm), source, pairs, echo);
    result["exit_code"] = out.exitCode;
    result["message"] = out.message;
    result["output"] = out.output;
    result["file"] = out.file;
    py::dict datasets, attrs, groups;
    for (const auto& [name, a] : out.results.datasets) datasets[py::str(name)] = arrayOf(name, a);
    for (const auto& [name, v] : out.results.numbers) attrs[py::str(name)] = v;
    for (const auto& [name, v] : out.results.texts) attrs[py::str(name)] = v;
    if (source.tree && out.file.empty()) {  // a run to memory from a tree: the scene text on demand
      if (attrs.contains("scene") && attrs["scene"].cast<std::string>().empty()) PyDict_DelItemString(attrs.ptr(), "scene");
      result["scene_text"] = SceneText{source.tree};
    }
    for (const auto& [group, texts] : out.results.groupTexts) groups[py::str(group)] = texts;
    if (out.file.empty()) result["datasets"] = datasets;
    result["attrs"] = attrs;
    result["group_attrs"] = groups;
  } catch (const sinew::RunError& e) {
    result["exit_code"] = e.exitCode();
    result["message"] = std::string(e.what());
    result["output"] = e.output();
    result["file"] = "";
  }
  return result;
}

}  // namespace

PYBIND11_MODULE(_core, m) {
  m.doc() = "Sinew's library entry point: runs scenes in this process, results as numpy arrays (docs/python.md)";
  m.def("run", &run, py::arg("scene"), py::arg("flags") = py::none(), py::arg("comm") = py::none(),
        py::arg("echo") = false, py::arg("base_dir") = ".", py::arg("as_text") = false,
        "Runs a scene (dict or file path) on comm's ranks; returns its datasets, attributes, exit code and message "
        "(a run to memory: the scene text by the function under scene_text). as_text: the dict as YAML text (tests).");
  py::class_<SceneText>(m, "SceneText", "A run's scene text, made when called.").def("__call__", &SceneText::operator());
  m.def("scene_text", &sceneText, py::arg("scene"), "The scene object as the YAML text Sinew reads.");
  m.def("scene_tree_check", &treeCheck, py::arg("scene"),
        "'' when the YAML tree built from the scene object is YAML::Load of its text node for node, else the difference.");
  m.def("finalize", &sinew::finalize, "Ends PETSc/SLEPc if a run started them (at interpreter exit).");
  m.def("initialize", &start, py::arg("options") = std::vector<std::string>{},
        "Starts PETSc/SLEPc (once per process) with extra PETSc options.");
}
