#include "elements/element_kinds.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "elements/ancf_cable2d.hpp"
#include "elements/beam_corotational.hpp"
#include "elements/beam_section.hpp"

namespace sinew {

namespace {

bool nonzero(const std::optional<Vec3>& v) { return v && norm(*v) > 0.0; }

/// 1-based element numbers, the first `shown` of them, then "and N more".
std::string elementNumbers(const std::vector<int>& v, std::size_t shown) {
  std::string s;
  for (std::size_t i = 0; i < v.size() && i < shown; ++i) s += (i ? ", " : "") + std::to_string(v[i] + 1);
  if (v.size() > shown) s += " and " + std::to_string(v.size() - shown) + " more";
  return s;
}

// ---- beam (SPACAR Light)
const BeamProperties& beam(const ElementSet& s) { return std::get<BeamProperties>(s.props); }

bool beamFlexible(const BeamProperties& b) { return std::any_of(b.flex.begin(), b.flex.end(), [](bool f) { return f; }); }

std::vector<std::string> beamWarnings(const Model& model, std::size_t set) {
  std::vector<std::string> w;
  const ElementSet& s = model.eprops[set];
  const BeamProperties& b = beam(s);
  if (b.cshape == CrossSection::Rect && !b.orien && !s.elems.empty())
    w.push_back(epropsName(static_cast<int>(set)) + " element" + (s.elems.size() > 1 ? "s " : " ") +
                elementNumbers(s.elems, 5) +
                ": cshape rect without orien (SPACAR Light requires it); the width dim(1) is taken along the global z "
                "axis (global y for an element along z): give orien");
  std::vector<int> shortElems;  // every element of the set with L/w < 3, and the smallest L/w
  double smallest = HUGE_VAL;
  for (int e : s.elems) {
    const auto& en = model.elements[static_cast<std::size_t>(e)];
    const double L = norm(model.nodes[static_cast<std::size_t>(en[1])] - model.nodes[static_cast<std::size_t>(en[0])]);
    if (!beamNeedsWarpingWarning(b, L)) continue;
    shortElems.push_back(e);
    smallest = std::min(smallest, L / b.dim[0]);
  }
  if (!shortElems.empty()) {
    char ratio[40];
    std::snprintf(ratio, sizeof ratio, "%.3g", smallest);
    w.push_back(epropsName(static_cast<int>(set)) + " element" + (shortElems.size() > 1 ? "s " : " ") +
                elementNumbers(shortElems, 5) + ": L/w " + (shortElems.size() > 1 ? "down to " : "= ") + ratio +
                " < 3 without cw; constrained warping stiffens torsion (set cw: true)");
  }
  return w;
}

const std::vector<std::string>* beamSensorVariables() { return &BeamCorotational::sensorVariables(); }

// ---- cable (3D, tension only)
const CableProperties& cable(const ElementSet& s) { return std::get<CableProperties>(s.props); }

// ---- membrane
const MembraneProperties& membrane(const ElementSet& s) { return std::get<MembraneProperties>(s.props); }

// ---- ancf_cable2d (Exudyn)
const AncfCable2DProperties& ancf(const ElementSet& s) { return std::get<AncfCable2DProperties>(s.props); }

std::vector<long> ancfCounters() {
  const AncfCable2D::EvaluationCounts c = AncfCable2D::evaluationCounts();
  return {c.userFunctions, c.dampingTerms};
}

std::string ancfCountersLine(const std::vector<long>& n) {
  return "  ancf_cable2d force laws: " + std::to_string(n[0]) + " user-function evaluations, " + std::to_string(n[1]) +
         " damping-term evaluations\n";
}

std::vector<ElementKind> makeKinds() {
  std::vector<ElementKind> kinds(4);
  ElementKind& b = kinds[static_cast<std::size_t>(ElementType::Beam)];
  b.type = ElementType::Beam;
  b.elementSensors = true;
  b.hasInertia = [](const ElementSet& s) { return beam(s).dens > 0; };
  b.initiallyLoaded = [](const ElementSet&) { return false; };
  b.bodyLoaded = [](const ElementSet&) { return false; };
  b.stressOutput = [](const ElementSet& s) { return beam(s).cshape != CrossSection::None && beamFlexible(beam(s)); };
  b.warnings = beamWarnings;
  b.sensorVariables = beamSensorVariables;

  ElementKind& c = kinds[static_cast<std::size_t>(ElementType::Cable)];
  c.type = ElementType::Cable;
  c.formFindable = true;
  c.modalOrder = 2.0;  // linear interpolation: eigenvalues converge as h^2
  c.hasInertia = [](const ElementSet& s) { return cable(s).dens > 0; };
  c.initiallyLoaded = [](const ElementSet& s) {
    const CableProperties& p = cable(s);
    return (p.prestress && *p.prestress != 0.0) || (p.prestress_stress && *p.prestress_stress != 0.0);
  };
  c.bodyLoaded = [](const ElementSet&) { return false; };
  c.stressOutput = [](const ElementSet&) { return false; };
  c.missingPrestress = [](const ElementSet& s) -> const char* {
    const CableProperties& p = cable(s);
    return p.prestress.value_or(0.0) == 0.0 && p.prestress_stress.value_or(0.0) == 0.0 ? "prestress / prestress_stress" : nullptr;
  };

  ElementKind& m = kinds[static_cast<std::size_t>(ElementType::Membrane)];
  m.type = ElementType::Membrane;
  m.formFindable = true;
  m.hasInertia = [](const ElementSet& s) { return membrane(s).dens > 0; };
  m.initiallyLoaded = [](const ElementSet& s) {
    const MembraneProperties& p = membrane(s);
    return p.pressure_initial != 0.0 || p.prestress[0] != 0.0 || p.prestress[1] != 0.0 || p.prestress[2] != 0.0;
  };
  m.bodyLoaded = [](const ElementSet&) { return false; };
  m.stressOutput = [](const ElementSet&) { return false; };
  m.missingPrestress = [](const ElementSet& s) -> const char* {
    const auto& p = membrane(s).prestress;
    return p[0] == 0.0 && p[1] == 0.0 && p[2] == 0.0 ? "prestress [s11, s22, s12]" : nullptr;
  };

  ElementKind& a = kinds[static_cast<std::size_t>(ElementType::AncfCable2D)];
  a.type = ElementType::AncfCable2D;
  a.elementSensors = true;
  // cubic Hermite positions (C1, degree k = 3, energy of order m = 2): nodal values and slopes
  // superconverge as h^(2(k+1-m)) = h^4, eigenvalues as h^(2(k+1-m)) = h^4 (Strang & Fix, ch. 1 and 6)
  a.nodalOrder = 4.0;
  a.modalOrder = 4.0;
  a.hasInertia = [](const ElementSet& s) { return ancf(s).physicsMassPerLength > 0; };
  a.initiallyLoaded = [](const ElementSet& s) {
    const AncfCable2DProperties& p = ancf(s);
    return p.physicsReferenceAxialStrain != 0.0 || p.physicsReferenceCurvature != 0.0 || !p.axialForceUserFunction.empty() ||
           !p.bendingMomentUserFunction.empty();
  };
  a.bodyLoaded = [](const ElementSet& s) { return nonzero(ancf(s).massProportionalLoad); };
  a.stressOutput = [](const ElementSet&) { return false; };
  a.counters = ancfCounters;
  a.countersLine = ancfCountersLine;
  return kinds;
}

}  // namespace

const std::vector<ElementKind>& elementKinds() {
  static const std::vector<ElementKind> kinds = makeKinds();
  return kinds;
}

const ElementKind& elementKind(ElementType t) { return elementKinds()[static_cast<std::size_t>(t)]; }

std::vector<int> formFoundSets(const FormFinding& ff, const std::vector<ElementSet>& eprops) {
  std::vector<int> sets = ff.formfinding_elements;
  if (sets.empty())
    for (std::size_t s = 0; s < eprops.size(); ++s)
      if (elementKind(eprops[s].type()).formFindable) sets.push_back(static_cast<int>(s));
  return sets;
}

}  // namespace sinew
