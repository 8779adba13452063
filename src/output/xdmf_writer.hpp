// XDMF description of the visualization mesh in a Sinew result file, for ParaView's "XDMF Reader".
//
// Convention (docs/results.md, "Opening the XDMF in ParaView"): the geometry is the reference mesh
// /mesh/p0, the same at every step; the point attribute "displacement" (/mesh/u) moves it to the
// deformed shape of the step, so Warp By Vector with scale factor 1 shows /mesh/p exactly. Mode
// shapes (/mesh/mode_*) are further point attributes, cell fields (/cell/<kind>/*) cell attributes.
#pragma once
#include <string>
#include <vector>

namespace sinew {

/// A step-indexed [ns, rows, inner...] dataset shown as an attribute.
struct XdmfField {
  std::string name;          ///< attribute name in ParaView ("displacement")
  std::string dataset;       ///< "/mesh/u"
  std::vector<long> inner;
  std::vector<char> written; ///< per dataset row: row was written
  /// A dataset on the step-analysis rows (/step_analysis_rows): its row of each step, -1 where the
  /// step has none; empty: the dataset's rows are the steps.
  std::vector<long> rowOfStep;
  long numRows = -1;         ///< rows of the dataset (-1: the steps)
};

/// One cell kind of /mesh: "Polyline" (2 nodes), "Triangle", "Quadrilateral", with its cell fields.
struct XdmfCellBlock {
  std::string name;          ///< sub-grid name ("lines")
  std::string topologyType;  ///< XDMF TopologyType
  int nodesPerElement = 0;
  long count = 0;
  std::string dataset;       ///< "/mesh/lines"
  std::vector<XdmfField> fields;  ///< [ns, count, inner...] cell attributes ("/cell/lines/stress")
  std::vector<XdmfField> staticFields;  ///< [count, inner...] cell attributes, the same at every step ("/mesh/lines_color")
};

struct XdmfDescription {
  std::string h5Name;                 ///< file name the DataItems reference, relative to the .xdmf
  long numMeshNodes = 0;
  std::vector<double> stepValues;     ///< per step written: load factor or time
  std::string stepName = "load_factor";  ///< "load_factor" or "time": field data name of the step value
  std::vector<char> formFindingRows;  ///< per step: a row before the load or time steps (/formfinding/step written;
                                      ///< in a /time file also a load step of opt.dynamics start: static)
  std::string geometryDataset;        ///< "/mesh/p0", [nmesh, 3]; empty: not written yet, no grids
  std::vector<XdmfCellBlock> cells;   ///< kinds with at least one cell
  std::vector<XdmfField> pointFields;
  bool inputOnly = false;             ///< opt.showinputonly: one grid "input" of the reference geometry, no steps
};

/// The Time value of every step in the XDMF: distinct and increasing. Form-finding rows i = 0 ..
/// nff-1 (they come first) get i - nff (the found shape at -1); the other rows (load or time
/// steps) get their step value when those values are all >= 0 and strictly increasing, otherwise
/// (a continuation path that turns back) their number 1, 2, ... among the load steps.
std::vector<double> xdmfTimes(const std::vector<double>& stepValues, const std::vector<char>& formFindingRows);

/// The XDMF text: a temporal collection with one grid per step written. Several cell kinds become
/// a spatial collection of sub-grids that share the geometry. Each grid carries the step value
/// (field data named stepName) and "hdf5_row" (its 0-based row in the step-indexed datasets).
std::string xdmfText(const XdmfDescription& d);

/// Writes xdmfText(d) to `path` through `path + ".part"` and a rename. Throws on I/O failure.
void writeXdmfFile(const std::string& path, const XdmfDescription& d);

}  // namespace sinew
