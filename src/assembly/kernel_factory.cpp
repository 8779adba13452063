#include "assembly/kernel_factory.hpp"

#include <petscsys.h>

#include <algorithm>
#include <map>
#include <memory>

#include "elements/ancf_cable2d.hpp"
#include "elements/beam_corotational.hpp"
#include "elements/cable3d.hpp"
#include "elements/membrane.hpp"

namespace sinew {

namespace {
double sceneElementLength(const Model& model, int e) {
  const auto& en = model.elements[e];
  return norm(model.nodes[en[1]] - model.nodes[en[0]]);
}

/// beamSection of set `set` for scene element e; its errors ("eprops.smod") name the set and the
/// element ("eprops(1).smod", as the scene check does).
BeamSection sectionOf(const BeamProperties& s, int set, const Model& model, int e) {
  try {
    return beamSection(s, sceneElementLength(model, e));
  } catch (const SceneError& ex) {
    const std::string field = ex.path().rfind("eprops.", 0) == 0 ? ex.path().substr(7) : std::string();
    const std::string prefix = ex.path() + ": ";
    const std::string what = std::string(ex.what()).rfind(prefix, 0) == 0 ? std::string(ex.what()).substr(prefix.size()) : ex.what();
    throw SceneError(epropsName(set) + (field.empty() ? "" : "." + field),
                     what + " (element " + std::to_string(e + 1) + ")");
  }
}
}  // namespace

double constraintScaleOf(const Model& model) {
  double scale = 0.0;
  for (size_t e = 0; e < model.elements.size(); ++e) {
    const int set = model.elementSet[e];
    const BeamProperties* s = set < 0 ? nullptr : model.eprops[set].as<BeamProperties>();
    if (!s || s->emod <= 0 || s->dim.empty()) continue;
    const BeamSection sec = sectionOf(*s, set, model, static_cast<int>(e));
    scale = std::max(scale, sec.EA * model.eprops[set].nbeams / sceneElementLength(model, static_cast<int>(e)));
  }
  return scale > 0 ? scale : 1.0;
}

ElementKernels makeKernelFactory(const Model& model, BeamMass beamMass) {
  const double scale = constraintScaleOf(model);
  // per set: membrane pressures (the assembler's follower-load terms) and mass-proportional loads
  std::vector<SetLoads> setLoads(model.eprops.size());
  for (size_t set = 0; set < model.eprops.size(); ++set) {
    if (const auto* mp = model.eprops[set].as<MembraneProperties>()) {
      setLoads[set].pressure = {mp->pressure, mp->pressure_initial, nullptr};
      if (!mp->pressure_t.empty())  // checked by the scene reader
        setLoads[set].pressure.pressureOfTime =
            std::make_shared<const Expression>(Expression::compile(mp->pressure_t, "pressure"));
    }
    if (const auto* a = model.eprops[set].as<AncfCable2DProperties>()) setLoads[set].acceleration = a->massProportionalLoad;
  }
  // ANCF parameters (and their compiled user functions) once per property set
  auto ancf = std::make_shared<std::map<int, std::shared_ptr<const AncfCable2DParameters>>>();
  for (size_t set = 0; set < model.eprops.size(); ++set) {
    const auto* a = model.eprops[set].as<AncfCable2DProperties>();
    if (!a) continue;
    try {
      (*ancf)[static_cast<int>(set)] = std::make_shared<const AncfCable2DParameters>(ancfCable2DParameters(*a));
    } catch (const std::invalid_argument& ex) {
      throw SceneError(epropsName(set), ex.what());
    }
  }
  // -beam_mass lumped: beams give their inertia to their nodes (docs/dynamics.md, "Free-floating beams");
  // linear: their rotary inertia
  const bool lumped = beamMass == BeamMass::Lumped;
  const bool linear = beamMass == BeamMass::Linear;  // constant translation mass, rotary inertia on the nodes
  const bool complete = beamMass == BeamMass::Consistent;  // the complete consistent mass (beam_inertia.cpp)
  KernelFactory kernelOf = [scale, ancf, lumped, linear, complete](const Model& m, const FeMesh& fe, int e) -> std::unique_ptr<ElementKernel> {
    const FeElement& el = fe.elements[e];
    const int set = el.set;
    const Vec3& Xp = fe.X[el.nodes[0]];
    const Vec3& Xq = fe.X[el.nodes[1]];
    const ElementType type = set < 0 ? ElementType::Beam : m.eprops[set].type();
    switch (type) {
      case ElementType::Beam: {
        std::array<BeamMode, 6> modes;
        modes.fill(BeamMode::Rigid);
        BeamSection sec;
        std::optional<Vec3> orien;
        if (set >= 0) {
          const BeamProperties& s = m.eprops[set].get<BeamProperties>();
          for (int i = 0; i < 6; ++i)
            if (s.flex[i]) modes[i] = BeamMode::Flexible;
          const bool flexible = std::any_of(s.flex.begin(), s.flex.end(), [](bool b) { return b; });
          const bool needsSection = s.dens > 0 || flexible;
          if (needsSection) {
            sec = sectionOf(s, set, m, el.sceneElement);
          } else if (m.opt.rigidstress && s.cshape != CrossSection::None) {
            // rigid set reported with rigidstress: section geometry only (stresses from the multipliers)
            BeamProperties geometry = s;
            geometry.dens = 1.0;
            sec = sectionOf(geometry, set, m, el.sceneElement);
            sec.rho = sec.rhoA = sec.rhoIy = sec.rhoIz = sec.rhoIp = 0.0;
          }
          // rigid elements are skipped in the stress output unless opt.rigidstress
          if (!flexible && !m.opt.rigidstress) sec.stressRecovery = false;
          orien = s.orien;
        }
        if (auto it = m.opt.rls.find(el.sceneElement); it != m.opt.rls.end())
          for (int mode : it->second) modes[mode - 1] = BeamMode::Released;
        const bool inertia = set >= 0 && m.eprops[set].get<BeamProperties>().dens > 0;
        auto beam = std::make_unique<BeamCorotational>(Xp, Xq, orien, sec, modes, inertia, scale);
        beam->setLumpedMass(lumped);
        beam->setLinearMass(linear);
        beam->setCompleteMass(complete);
        return beam;
      }
      case ElementType::Cable: {
        const CableProperties& s = m.eprops[set].get<CableProperties>();
        const double N0 = s.prestress ? *s.prestress : (s.prestress_stress ? *s.prestress_stress * s.area : 0.0);
        return std::make_unique<Cable3D>(Xp, Xq, s.area, s.emod, s.dens, N0);
      }
      case ElementType::AncfCable2D: {
        const auto& sp = fe.slope[el.nodes[0]];
        const auto& sq = fe.slope[el.nodes[1]];
        const std::array<double, 8> qRef{Xp[0], Xp[1], sp[0], sp[1], Xq[0], Xq[1], sq[0], sq[1]};
        return std::make_unique<AncfCable2D>(qRef, norm(Xq - Xp), ancf->at(set));
      }
      case ElementType::Membrane: {
        const MembraneProperties& s = m.eprops[set].get<MembraneProperties>();
        std::array<Vec3, 4> X;
        for (int i = 0; i < el.numNodes; ++i) X[i] = fe.X[el.nodes[i]];
        MembraneProps props{s.thickness, s.emod, s.nu, s.dens, s.prestress};
        PrestressFrame frame;
        if (s.prestress_radial_axis) frame = PrestressFrame::radial(*s.prestress_radial_axis);
        else if (s.prestress_dir) frame = PrestressFrame::direction(*s.prestress_dir);
        return std::make_unique<Membrane>(std::span<const Vec3>(X.data(), el.numNodes), props, frame);
      }
    }
    throw std::logic_error("unknown element type");
  };
  return {std::move(kernelOf), std::move(setLoads)};
}

}  // namespace sinew
