// XDMF 3 description of the visualization mesh in a Sinew result file (ParaView's Xdmf3 reader).
#pragma once
#include <string>
#include <vector>

namespace sinew {

/// One cell kind of /mesh: "Polyline" (2 nodes), "Triangle", "Quadrilateral".
struct XdmfCellBlock {
  std::string name;          ///< sub-grid name ("lines")
  std::string topologyType;  ///< XDMF TopologyType
  int nodesPerElement = 0;
  long count = 0;
  std::string dataset;       ///< "/mesh/lines"
};

/// A step-indexed [ns, nmesh, inner...] dataset shown as a point attribute.
struct XdmfPointField {
  std::string name;          ///< attribute name in ParaView ("u")
  std::string dataset;       ///< "/mesh/u"
  std::vector<long> inner;
  std::vector<char> written; ///< per step: row was written
};

struct XdmfDescription {
  std::string h5Name;                 ///< file name the DataItems reference, relative to the .xdmf
  long numMeshNodes = 0;
  std::vector<double> stepValues;     ///< per step written: load factor or time
  std::string geometryDataset;        ///< "/mesh/p", [ns, nmesh, 3]
  std::vector<char> geometryWritten;  ///< per step: geometry row written
  std::vector<XdmfCellBlock> cells;   ///< kinds with at least one cell
  std::vector<XdmfPointField> pointFields;
};

/// The XDMF text: a temporal collection with one grid per step that has a geometry (the latest
/// geometry row written at or before the step). Several cell kinds become a spatial collection of
/// sub-grids that share the geometry.
std::string xdmfText(const XdmfDescription& d);

/// Writes xdmfText(d) to `path` through `path + ".part"` and a rename. Throws on I/O failure.
void writeXdmfFile(const std::string& path, const XdmfDescription& d);

}  // namespace sinew
