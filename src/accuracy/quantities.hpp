// The result quantities whose discretization error -target_error estimates, read from one level's
// results (the last row of each dataset: the end of the load steps and its step analyses). Node
// quantities belong to scene nodes, which every refinement keeps (nbeams adds nodes inside elements).
#pragma once
#include <set>
#include <string>
#include <vector>

#include "sinew/model.hpp"
#include "sinew/result_store.hpp"

namespace sinew::accuracy {

/// What a quantity is and how its relative error is measured.
struct QuantityDef {
  enum class Kind {
    Frequency,     ///< /freq column `index` (scale: itself)
    Buckling,      ///< /buck column `index` (scale: itself)
    StressMax,     ///< /stressmax (scale: itself)
    Displacement,  ///< node/p - node/p0 of `node` (scale: the largest displacement of any scene node)
    Rotation,      ///< rotation vector of node/r_quat (scale: the largest rotation angle of any scene node)
    Force,         ///< node/Freac (scale: the largest reaction force)
    Moment,        ///< node/Mreac (scale: the largest reaction moment)
    ComplianceTT,  ///< translational 3x3 block of node/CMglob (scale: its largest entry)
    ComplianceRR,  ///< rotational 3x3 block of node/CMglob (scale: its largest entry)
    LimitLoad,        ///< load factor of limit point `index` in /path/critical_points (scale: itself)
    BifurcationLoad,  ///< load factor of bifurcation `index` (scale: itself)
    Shape,            ///< found shape: positions of scene nodes 0..index-1 (accuracy/path_quantities.hpp)
    DisplacementHistory,  ///< node/p - node/p0 of `node` at every row, [rows x 3] (dynamics; scale: the largest
                          ///< displacement of any node at any row; error: the worst row)
  };
  Kind kind = Kind::Frequency;
  std::string name;  ///< as printed and stored: "freq 1", "node 2 p", "node 1 Freac", "node 2 CMglob tt"
  long node = -1;    ///< 0-based scene node (node quantities)
  long index = 0;    ///< 0-based column (freq, buck), critical point (limit, bifurcation) or node count (shape)
};

/// The elements' theoretical orders in h, the lowest over the model's element kinds (ElementKind::
/// nodalOrder, modalOrder in src/elements/element_kinds.hpp): nodal results (positions, rotations,
/// reactions, compliance) and eigenvalues (frequencies with consistent mass, buckling multipliers).
struct ElementOrders {
  double nodal = 2.0;
  double modal = 4.0;
};

/// The theoretical order of convergence of a quantity (docs/accuracy.md): the elements' modal order
/// for frequencies (consistent mass) and buckling multipliers (h^4 for the cubic beam and ANCF
/// interpolation), h^2 for frequencies with lumped beam mass, the elements' nodal order for nodal
/// results (h^2 for the corotational beam under large displacements, h^4 for the ANCF cable's cubic
/// Hermite nodes), h^2 for the max stress (a derivative); h^2 for every quantity of a scene with
/// membranes (linear triangles: displacements, stresses and frequencies). Time histories: historyOrder
/// (accuracy/refinement_study.hpp).
double theoreticalOrder(const QuantityDef& q, bool lumpedMass, bool membranes, const ElementOrders& orders);

/// The scene loads the node (forces, moments, prescribed displacements or rotations).
bool loadedNode(const NodeProps& p);

/// The quantities watched: `names` as in opt.accuracy_quantities ("freq", "buck", "stressmax",
/// "node <n> <p|r|Freac|Mreac|CMglob>", "limit", "bifurcation", "shape"), or when empty those the scene
/// asks for: the limit and bifurcation load factors of a path, the found shape of form finding, positions and
/// rotations of loaded nodes and of the node that moves most (on the coarsest level), reactions of
/// supported nodes, the max stress, every frequency and finite buckling multiplier, the compliance
/// blocks of the loaded and most-moving nodes (in a scene with membranes neither reactions nor
/// compliance blocks: they do not converge under refinement). Quantities that are zero on the coarsest level
/// (a node that does not move, no reaction) are left out. With opt.dynamics: time histories
/// (accuracy/time_refinement.hpp).
std::vector<QuantityDef> selectQuantities(const Model& model, const RunResults& coarsest,
                                          const std::vector<std::string>& names);

/// The quantity's values on one level (empty when its dataset is missing).
std::vector<double> readQuantity(const QuantityDef& q, const RunResults& r);
/// The scale its error is relative to (> 0; 1 when the level has nothing to scale by).
double quantityScale(const QuantityDef& q, const RunResults& r);
/// The datasets these quantities and their scales read.
std::set<std::string> datasetsUsed(const std::vector<QuantityDef>& qs);

}  // namespace sinew::accuracy
