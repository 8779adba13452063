#include "app/plan.hpp"

#include <algorithm>
#include <sstream>
#include <string>

#include "elements/element_kinds.hpp"

namespace sinew {

Plan makePlan(const Model& model) {
  Plan p;
  p.dynamics = model.opt.dynamics.has_value();
  p.preload = p.dynamics && model.opt.dynamics->start_static;
  p.statics = !p.dynamics || p.preload;
  p.formfinding = model.formfinding.has_value();
  if (model.opt.continuation && p.dynamics)
    throw SceneError(p.preload ? "opt.dynamics.start" : "opt.continuation",
                     p.preload ? "start: static runs the load steps (opt.loadsteps) before the time loop; path following "
                                 "(opt.continuation) cannot precede it: remove opt.continuation or give start: rest"
                               : "path following is a static analysis; remove opt.dynamics or opt.continuation");
  p.continuation = p.statics && model.opt.continuation.has_value();
  bool beams = false, sections = false;
  for (size_t e = 0; e < model.elements.size(); ++e) {
    const int set = model.elementSet[e];
    if (set < 0) {
      beams = true;
      continue;
    }
    const ElementSet& s = model.eprops[set];
    const ElementKind& kind = elementKind(s.type());
    p.inertia |= kind.hasInertia(s);
    beams |= s.type() == ElementType::Beam;
    sections |= kind.stressOutput(s);
  }
  for (size_t i = 0; i < model.sensors.size(); ++i) {
    if (model.sensors[i].node >= 0) {
      // node sensors: beam (Frame6) nodes, i.e. nodes of a beam or rigid element
      const int nd = model.sensors[i].node;
      bool frame = false;
      for (size_t e = 0; e < model.elements.size() && !frame; ++e) {
        const int set = model.elementSet[e];
        if (set >= 0 && model.eprops[set].type() != ElementType::Beam) continue;
        for (int k : model.elements[e]) frame |= k == nd;
      }
      if (!frame)
        throw SceneError(indexedPath("sensors", i) + ".node",
                         "node sensors sample beam nodes; node " + std::to_string(nd + 1) + " is on no beam or rigid element");
      continue;
    }
    const int e = model.sensors[i].element, set = model.elementSet[e];
    const ElementType type = set < 0 ? ElementType::Beam : model.eprops[set].type();  // rigid elements are beams
    const ElementKind& kind = elementKind(type);
    if (!kind.elementSensors)
      throw SceneError(indexedPath("sensors", i) + ".element",
                       "sensors sample ancf_cable2d and beam elements; element " + std::to_string(e + 1) + " is a " +
                           elementTypeName(type));
    // the kind's sensor variables (beams: src/elements/beam_corotational_sensor.cpp; ancf_cable2d: the scene reader checks them)
    if (const std::vector<std::string>* vars = kind.sensorVariables ? kind.sensorVariables() : nullptr;
        vars && std::find(vars->begin(), vars->end(), model.sensors[i].variable) == vars->end()) {
      std::string list;
      for (const auto& v : *vars) list += (list.empty() ? "" : ", ") + v;
      throw SceneError(indexedPath("sensors", i) + ".variable",
                       "'" + model.sensors[i].variable + "' is not available along " + elementTypeName(type) + " element " +
                           std::to_string(e + 1) + "; " + elementTypeName(type) + " sensors give " + list);
    }
  }
  for (const auto& [node, np] : model.nprops) {
    p.inertia |= np.mass > 0;
    for (double v : np.mominertia) p.inertia |= v != 0.0;
  }
  p.frequencies = p.inertia && model.opt.calcfreq.value_or(true);
  p.buckling = model.opt.calcbuck;
  p.compliance = model.opt.calccompl && beams && model.dimension == 3;
  p.transfer = model.opt.transfer;
  if (p.transfer) {
    // SPACAR Light builds the state-space model about the unloaded reference configuration: it
    // refuses loads and prescribed motions (standard and initial) and buckling with `transfer`
    if (model.opt.calcbuck)
      throw SceneError("opt.calcbuck", "buckling together with opt.transfer: SPACAR Light computes the state-space model "
                                       "of the unloaded structure and no buckling with it; set opt.calcbuck: false or "
                                       "opt.transfer: false");
    auto loadPath = [](int node, const std::string& field) { return npropsPath(node, field); };
    for (const auto& [node, np] : model.nprops) {
      std::string field;
      const char* axes[3] = {"x", "y", "z"};
      if (norm(np.force) != 0.0 || !np.force_t[0].empty() || !np.force_t[1].empty() || !np.force_t[2].empty()) field = "force";
      else if (norm(np.moment) != 0.0 || !np.moment_t[0].empty() || !np.moment_t[1].empty() || !np.moment_t[2].empty())
        field = "moment";
      else if (norm(np.force_initial) != 0.0) field = "force_initial";
      else if (norm(np.moment_initial) != 0.0) field = "moment_initial";
      else if (np.rot) field = "rot";
      else if (np.rot_initial) field = "rot_initial";
      for (int k = 2; k >= 0; --k) {
        if (np.displ_initial[k]) field = std::string("displ_initial_") + axes[k];
        if (np.displ[k]) field = std::string("displ_") + axes[k];
      }
      if (!field.empty()) {
        const bool motion = field.rfind("displ", 0) == 0 || field.rfind("rot", 0) == 0;
        throw SceneError(loadPath(node, field),
                         std::string(motion ? "prescribed motion" : "applied load") +
                             " together with opt.transfer: the state-space model is linearized about the unloaded "
                             "equilibrium (as in SPACAR Light, which refuses loads and prescribed motions with transfer); remove " +
                             loadPath(node, field) + " or set opt.transfer: false");
      }
    }
    if (model.opt.gravity && norm(*model.opt.gravity) != 0.0)
      throw SceneError("opt.gravity", "applied load together with opt.transfer: the state-space model is linearized about "
                                      "the unloaded equilibrium (as in SPACAR Light); remove opt.gravity or set opt.transfer: false");
    bool in = false, out = false;
    for (const auto& [node, np] : model.nprops) {
      in |= !np.transfer_in.empty();
      out |= !np.transfer_out.empty();
    }
    if (!in || !out)
      throw SceneError("opt.transfer", std::string("the state-space model needs at least one nprops transfer_in and one "
                                                   "transfer_out; the scene has no ") +
                                           (!in ? "transfer_in" : "transfer_out"));
    if (!p.inertia)
      throw SceneError("opt.transfer", "the state-space model needs mass (eprops dens or nprops mass/mominertia)");
    if (p.dynamics)
      throw SceneError("opt.transfer", "the state-space model is built at the end of the static load steps; "
                                       "remove opt.dynamics or opt.transfer");
  }
  p.stress = sections || model.opt.rigidstress;
  p.stressPerElement = p.stress && model.opt.stressperelement;
  return p;
}

std::string Plan::describe(const Model& model, int lastLoadStep) const {
  std::ostringstream s;
  const char* sep = "";
  auto add = [&](const std::string& what) {
    s << sep << what;
    sep = ", ";
  };
  if (formfinding) add("form finding");
  if (continuation)
    add("statics, path following (" + model.opt.continuation->method + ", up to " +
        std::to_string(model.opt.continuation->max_steps) + " points)");
  else if (statics) add("statics (" + std::to_string(lastLoadStep) + " load steps)");
  if (dynamics) add(preload ? "dynamics from the end of the load steps" : "dynamics");
  if (frequencies) add("natural frequencies");
  if (buckling) add("buckling");
  if (compliance) add("compliance");
  if (transfer) add("state-space");
  if (stress) add("stress");
  return s.str();
}

}  // namespace sinew
