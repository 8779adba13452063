#include "app/plan.hpp"

#include <algorithm>
#include <sstream>

namespace sinew {

Plan makePlan(const Model& model) {
  Plan p;
  p.dynamics = model.opt.dynamics.has_value();
  p.statics = !p.dynamics;
  p.formfinding = model.formfinding.has_value();
  bool beams = false, sections = false;
  for (size_t e = 0; e < model.elements.size(); ++e) {
    const int set = model.elementSet[e];
    if (set < 0) {
      beams = true;
      continue;
    }
    const ElementSet& s = model.eprops[set];
    p.inertia |= s.dens > 0 || (s.type == ElementType::AncfCable2D && s.physicsMassPerLength > 0);
    beams |= s.type == ElementType::Beam;
    sections |= s.type == ElementType::Beam && s.cshape != CrossSection::None &&
                std::any_of(s.flex.begin(), s.flex.end(), [](bool b) { return b; });
  }
  for (const auto& [node, np] : model.nprops) {
    p.inertia |= np.mass > 0;
    for (double v : np.mominertia) p.inertia |= v != 0.0;
  }
  p.frequencies = p.inertia && model.opt.calcfreq.value_or(true);
  p.buckling = model.opt.calcbuck;
  p.compliance = model.opt.calccompl && beams && model.dimension == 3;
  p.transfer = model.opt.transfer;
  p.stress = sections || model.opt.rigidstress;
  p.stressPerElement = p.stress && model.opt.stressperelement;
  return p;
}

std::string Plan::describe(const Model& model) const {
  std::ostringstream s;
  const char* sep = "";
  auto add = [&](const std::string& what) {
    s << sep << what;
    sep = ", ";
  };
  if (formfinding) add("form finding");
  if (statics) add("statics (" + std::to_string(model.opt.loadsteps) + " load steps)");
  if (dynamics) add("dynamics");
  if (frequencies) add("natural frequencies");
  if (buckling) add("buckling");
  if (compliance) add("compliance");
  if (transfer) add("state-space");
  if (stress) add("stress");
  return s.str();
}

}  // namespace sinew
