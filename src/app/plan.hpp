// What a scene asks for: the analyses, fields and matrices to create (and nothing else).
#pragma once
#include <string>

#include "sinew/model.hpp"

namespace sinew {

struct Plan {
  bool statics = true;        ///< load-stepped statics (loadsteps)
  bool dynamics = false;      ///< opt.dynamics
  bool preload = false;       ///< opt.dynamics.start: static: the load steps first, the time loop from their end
  bool continuation = false;  ///< opt.continuation: path following instead of load steps
  bool formfinding = false;   ///< formfinding block
  bool inertia = false;       ///< some element density or nodal mass
  bool frequencies = false;   ///< inertia and calcfreq != false
  bool buckling = false;      ///< calcbuck
  bool compliance = false;    ///< calccompl and the model has beams
  bool transfer = false;      ///< state-space
  bool stress = false;        ///< some element has a stress measure
  bool stressPerElement = false;
  /// One line of what runs; lastLoadStep: the load steps the statics runs (a restart may go on past opt.loadsteps).
  std::string describe(const Model& model, int lastLoadStep) const;
};

Plan makePlan(const Model& model);

}  // namespace sinew
