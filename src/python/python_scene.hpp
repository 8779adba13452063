// A scene given to sinew._core as a Python object (dict, lists, tuples, numpy arrays and scalars,
// bools, ints, floats, str, None) as YAML: its text (emitScene), or directly the tree YAML::Load
// would make of that text (sceneTree), so that an in-process run neither writes nor parses text.
#pragma once
#include <pybind11/pybind11.h>
#include <yaml-cpp/yaml.h>

#include <optional>

namespace sinew::python {

/// The object as YAML text: maps in block style, lists and tuples in flow style (maps inside them
/// too), numpy values through tolist(), None as ~, bools true/false, floats by their shortest repr
/// (read back exactly; .nan, .inf, -.inf), ints and other objects by str().
void emitScene(YAML::Emitter& out, const pybind11::handle& v);

/// The tree YAML::Load gives of emitScene's text, node for node: the same kinds, scalars, key order
/// and tags ("!" for a scalar the emitter quotes, "?" for a plain one, as the reader distinguishes
/// them; no marks). nullopt when a string would not read back as itself (then the text is used).
std::optional<YAML::Node> sceneTree(const pybind11::handle& v);

}  // namespace sinew::python
