// The element kinds (eprops type): what the scene check, the plan and the runner ask of a kind's
// property sets, one entry per kind (element_kinds.cpp). Adding a kind: its kernels in src/elements,
// its properties struct (sinew/element_properties.hpp) in ElementSet::Properties, its entry here,
// its reader in src/scene/eprops.cpp and its kernel in src/assembly/kernel_factory.cpp.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include "sinew/model.hpp"

namespace sinew {

struct ElementKind {
  ElementType type = ElementType::Beam;
  /// Its sets can be form-found (cables, membranes): formfinding_elements defaults to them.
  bool formFindable = false;
  /// Its elements carry sensors (`sensors` with `element`).
  bool elementSensors = false;
  /// Theoretical orders of convergence in the element length h (-target_error, docs/accuracy.md):
  /// nodal results (positions, rotations, reactions) and eigenvalues (frequencies with consistent
  /// mass, buckling multipliers).
  double nodalOrder = 2.0;
  double modalOrder = 4.0;
  /// The set has inertia (a density or a mass per length).
  bool (*hasInertia)(const ElementSet& set) = nullptr;
  /// Something of the set acts at load factor 0 (prestress, initial pressure, reference strains, force laws).
  bool (*initiallyLoaded)(const ElementSet& set) = nullptr;
  /// The set loads its elements besides the nodal loads and gravity (a nonzero massProportionalLoad).
  bool (*bodyLoaded)(const ElementSet& set) = nullptr;
  /// The set has stress output (Von Mises; beams with a section and flexible modes).
  bool (*stressOutput)(const ElementSet& set) = nullptr;
  /// A form-found set without prestress: the prestress fields to name in the warning; nullptr when
  /// it has prestress.
  const char* (*missingPrestress)(const ElementSet& set) = nullptr;
  /// Warnings about set `set` of the model (without the "warning: " prefix).
  std::vector<std::string> (*warnings)(const Model& model, std::size_t set) = nullptr;
  /// Variables the kind's element sensors give when the plan checks them (nullptr: checked by the scene reader).
  const std::vector<std::string>* (*sensorVariables)() = nullptr;
  /// Evaluation counters of the kind's kernels in this process for the run summary (nullptr: none),
  /// and the summary line of their sums over the processes.
  std::vector<long> (*counters)() = nullptr;
  std::string (*countersLine)(const std::vector<long>& sums) = nullptr;
};

/// The kind of eprops type t.
const ElementKind& elementKind(ElementType t);
/// Every kind, in ElementType order.
const std::vector<ElementKind>& elementKinds();

/// The eprops sets form finding works on: formfinding_elements, or every set of a form-findable kind.
std::vector<int> formFoundSets(const FormFinding& ff, const std::vector<ElementSet>& eprops);

}  // namespace sinew
