#include "app/input_summary.hpp"

#include <sstream>
#include <vector>

namespace sinew {

std::string oneBasedList(const std::vector<int>& v, std::size_t shown) {
  std::string s;
  for (std::size_t i = 0; i < v.size() && i < shown; ++i) s += (i ? ", " : "") + std::to_string(v[i] + 1);
  if (v.size() > shown) s += " and " + std::to_string(v.size() - shown) + " more";
  return s;
}

namespace {

constexpr std::size_t kShown = 8;  // entries of a list before "and N more"

std::string num(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

template <class C>
std::string vec(const C& v) {
  std::string s = "[";
  std::size_t i = 0;
  for (double x : v) s += (i++ ? ", " : "") + num(x);
  return s + "]";
}

std::string numbers(const std::vector<int>& v) { return oneBasedList(v, kShown); }

/// One line per entry, at most kShown of them, then "... and N more".
void list(std::ostringstream& o, const std::string& title, const std::vector<std::string>& entries) {
  o << "  " << title << ":";
  if (entries.empty()) {
    o << " none\n";
    return;
  }
  o << "\n";
  for (std::size_t i = 0; i < entries.size() && i < kShown; ++i) o << "    " << entries[i] << "\n";
  if (entries.size() > kShown) o << "    ... and " << entries.size() - kShown << " more\n";
}

std::string setLine(const ElementSet& s, std::size_t index) {
  std::ostringstream o;
  o << epropsName(static_cast<int>(index)) << " " << elementTypeName(s.type()) << ", element" << (s.elems.size() > 1 ? "s " : " ")
    << numbers(s.elems) << ":";
  double dens = 0;
  if (const auto* b = s.as<BeamProperties>()) {
    std::vector<double> flex;
    for (int m = 0; m < 6; ++m)
      if (b->flex[m]) flex.push_back(m + 1);
    o << " flex " << vec(flex);
    if (b->cshape != CrossSection::None) o << ", " << (b->cshape == CrossSection::Rect ? "rect " : "circ ") << vec(b->dim);
    if (b->orien) o << ", orien " << vec(*b->orien);
    if (s.nbeams > 1) o << ", nbeams " << s.nbeams;
    if (b->emod > 0) o << ", emod " << num(b->emod);
    if (b->smod > 0) o << ", smod " << num(b->smod);
    if (b->cw) o << ", cw";
    dens = b->dens;
  } else if (const auto* c = s.as<CableProperties>()) {
    o << " area " << num(c->area) << ", emod " << num(c->emod);
    if (c->prestress) o << ", prestress " << num(*c->prestress);
    if (c->prestress_stress) o << ", prestress_stress " << num(*c->prestress_stress);
    dens = c->dens;
  } else if (const auto* mp = s.as<MembraneProperties>()) {
    o << " thickness " << num(mp->thickness) << ", emod " << num(mp->emod) << ", nu " << num(mp->nu) << ", prestress "
      << vec(mp->prestress);
    if (!mp->pressure_t.empty()) o << ", pressure = " << mp->pressure_t;
    else if (mp->pressure != 0.0) o << ", pressure " << num(mp->pressure);
    if (mp->pressure_initial != 0.0) o << ", pressure_initial " << num(mp->pressure_initial);
    dens = mp->dens;
  } else if (const auto* a = s.as<AncfCable2DProperties>()) {
    o << " physicsAxialStiffness " << num(a->physicsAxialStiffness) << ", physicsBendingStiffness "
      << num(a->physicsBendingStiffness) << ", physicsMassPerLength " << num(a->physicsMassPerLength);
  }
  if (dens > 0) o << ", dens " << num(dens);
  return o.str();
}

}  // namespace

std::string inputSummary(const Model& model, const InputCounts& c) {
  std::ostringstream o;
  o << "\n input (opt.showinputonly: read and checked, nothing solved)\n";
  o << "  nodes: " << model.nodes.size() << " (" << model.dimension << "D)";
  if (model.nodes.size() > model.connectedNodes)
    o << ", of which " << model.nodes.size() - model.connectedNodes << " trailing unconnected";
  o << "; elements: " << model.elements.size() << "; finite elements: " << c.feElements << " on " << c.feNodes
    << " nodes; unknowns: " << c.unknowns << " (ndof " << c.ndof << ")\n";
  std::vector<std::string> sets;
  for (std::size_t i = 0; i < model.eprops.size(); ++i) sets.push_back(setLine(model.eprops[i], i));
  std::vector<int> rigid;
  for (std::size_t e = 0; e < model.elementSet.size(); ++e)
    if (model.elementSet[e] < 0) rigid.push_back(static_cast<int>(e));
  if (!rigid.empty()) sets.push_back("rigid, massless (in no set): element" + std::string(rigid.size() > 1 ? "s " : " ") + numbers(rigid));
  list(o, "element sets", sets);

  std::vector<std::string> supports, motions, loads, masses;
  const char* axes = "xyz";
  for (const auto& [node, p] : model.nprops) {
    const std::string n = "node " + std::to_string(node + 1) + ":";
    std::string held;
    auto add = [](std::string& s, const std::string& what) { s += (s.empty() ? " " : ", ") + what; };
    if (p.fix) add(held, "fix");
    if (p.fix_pos) add(held, "fix_pos");
    if (p.fix_orien) add(held, "fix_orien");
    if (p.fix_x) add(held, "fix_x");
    if (p.fix_y) add(held, "fix_y");
    if (p.fix_z) add(held, "fix_z");
    if (p.fix_coords) add(held, "fix_coords " + vec(*p.fix_coords));
    if (!held.empty()) supports.push_back(n + held);
    std::string moved;
    for (int k = 0; k < 3; ++k) {
      if (p.displ_initial[k]) add(moved, std::string("displ_initial_") + axes[k] + " " + num(*p.displ_initial[k]));
      if (p.displ[k] && !p.displ_t[k].empty()) add(moved, std::string("displ_") + axes[k] + " = " + p.displ_t[k]);
      else if (p.displ[k]) add(moved, std::string("displ_") + axes[k] + " " + num(*p.displ[k]));
    }
    if (p.rot_initial) add(moved, "rot_initial " + vec(*p.rot_initial) + " (rotation vector)");
    if (p.rot && !p.rot_t.empty()) add(moved, "rot angle = " + p.rot_t + " about " + vec(p.rot_axis));
    else if (p.rot) add(moved, "rot " + vec(*p.rot) + " (rotation vector)");
    if (!moved.empty()) motions.push_back(n + moved);
    std::string load;
    if (norm(p.force_initial) != 0.0) add(load, "force_initial " + vec(p.force_initial));
    if (norm(p.force) != 0.0) add(load, "force " + vec(p.force));
    if (norm(p.moment_initial) != 0.0) add(load, "moment_initial " + vec(p.moment_initial));
    if (norm(p.moment) != 0.0) add(load, "moment " + vec(p.moment));
    for (int k = 0; k < 3; ++k) {  // functions of time (the values above are those at t = 0)
      if (!p.force_t[k].empty()) add(load, std::string("force_") + axes[k] + " = " + p.force_t[k]);
      if (!p.moment_t[k].empty()) add(load, std::string("moment_") + axes[k] + " = " + p.moment_t[k]);
    }
    if (!p.transfer_in.empty()) add(load, "transfer_in " + std::to_string(p.transfer_in.size()));
    if (!load.empty()) loads.push_back(n + load);
    std::string mass;
    if (p.mass != 0.0) add(mass, "mass " + num(p.mass));
    if (p.mominertia != std::array<double, 6>{}) add(mass, "mominertia " + vec(p.mominertia));
    if (!mass.empty()) masses.push_back(n + mass);
  }
  list(o, "supports", supports);
  list(o, "prescribed motions (*_initial at load step 1, the others ramped)", motions);
  if (model.opt.gravity) loads.push_back("gravity " + vec(*model.opt.gravity));
  list(o, "loads (*_initial at load step 1, the others ramped)", loads);
  list(o, "point masses", masses);
  return o.str();
}

}  // namespace sinew
