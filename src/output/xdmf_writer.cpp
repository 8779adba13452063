#include "output/xdmf_writer.hpp"

#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace sinew {

namespace {

std::string escape(const std::string& s) {
  std::string out;
  out.reserve(s.size());
  for (char c : s) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&apos;"; break;
      default: out += c;
    }
  }
  return out;
}

std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

std::string joined(const std::vector<long>& v) {
  std::string s;
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (i) s += ' ';
    s += std::to_string(v[i]);
  }
  return s;
}

// Row `step` of a [ns, nmesh, inner...] dataset: a HyperSlab DataItem over the HDF5 dataset.
std::string hyperslab(const XdmfDescription& d, const std::string& dataset, const std::vector<long>& inner, int step,
                      const std::string& indent) {
  const long ns = static_cast<long>(d.stepValues.size());
  std::vector<long> full{ns, d.numMeshNodes}, start{step, 0}, stride{1, 1}, count{1, d.numMeshNodes};
  for (long n : inner) {
    full.push_back(n);
    start.push_back(0);
    stride.push_back(1);
    count.push_back(n);
  }
  std::ostringstream o;
  o << indent << "<DataItem ItemType=\"HyperSlab\" Type=\"HyperSlab\" Dimensions=\"" << joined(count) << "\">\n"
    << indent << "  <DataItem Dimensions=\"3 " << full.size() << "\" NumberType=\"Int\" Format=\"XML\">"
    << joined(start) << "  " << joined(stride) << "  " << joined(count) << "</DataItem>\n"
    << indent << "  <DataItem Dimensions=\"" << joined(full) << "\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">"
    << escape(d.h5Name) << ":" << escape(dataset) << "</DataItem>\n"
    << indent << "</DataItem>\n";
  return o.str();
}

std::string attributeType(const std::vector<long>& inner) {
  long n = 1;
  for (long k : inner) n *= k;
  if (n == 1) return "Scalar";
  if (inner.size() == 1 && n == 3) return "Vector";
  if (inner.size() == 1 && n == 6) return "Tensor6";
  if (n == 9) return "Tensor";
  return "Matrix";
}

// One uniform grid: topology of one cell kind, the geometry row and the point attributes of `step`.
std::string uniformGrid(const XdmfDescription& d, const XdmfCellBlock* cells, const std::string& name, int step,
                        int geometryStep, bool withTime, const std::string& indent) {
  std::ostringstream o;
  o << indent << "<Grid Name=\"" << escape(name) << "\" GridType=\"Uniform\">\n";
  if (withTime) o << indent << "  <Time Value=\"" << number(d.stepValues[step]) << "\"/>\n";
  if (cells) {
    o << indent << "  <Topology TopologyType=\"" << cells->topologyType << "\" NumberOfElements=\"" << cells->count
      << "\" NodesPerElement=\"" << cells->nodesPerElement << "\">\n"
      << indent << "    <DataItem Dimensions=\"" << cells->count << " " << cells->nodesPerElement
      << "\" NumberType=\"Int\" Precision=\"8\" Format=\"HDF\">" << escape(d.h5Name) << ":" << escape(cells->dataset)
      << "</DataItem>\n"
      << indent << "  </Topology>\n";
  } else {
    o << indent << "  <Topology TopologyType=\"Polyvertex\" NumberOfElements=\"" << d.numMeshNodes
      << "\" NodesPerElement=\"1\"/>\n";
  }
  o << indent << "  <Geometry GeometryType=\"XYZ\">\n"
    << hyperslab(d, d.geometryDataset, {3}, geometryStep, indent + "    ") << indent << "  </Geometry>\n";
  for (const auto& f : d.pointFields) {
    if (step >= static_cast<int>(f.written.size()) || !f.written[step]) continue;
    o << indent << "  <Attribute Name=\"" << escape(f.name) << "\" AttributeType=\"" << attributeType(f.inner)
      << "\" Center=\"Node\">\n"
      << hyperslab(d, f.dataset, f.inner, step, indent + "    ") << indent << "  </Attribute>\n";
  }
  o << indent << "</Grid>\n";
  return o.str();
}

}  // namespace

std::string xdmfText(const XdmfDescription& d) {
  std::ostringstream o;
  o << "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n"
    << "<Xdmf xmlns:xi=\"http://www.w3.org/2001/XInclude\" Version=\"3.0\">\n"
    << "  <Domain>\n"
    << "    <Grid Name=\"steps\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
  int geometryStep = -1;
  const std::string indent = "      ";
  for (int s = 0; s < static_cast<int>(d.stepValues.size()); ++s) {
    if (s < static_cast<int>(d.geometryWritten.size()) && d.geometryWritten[s]) geometryStep = s;
    if (geometryStep < 0) continue;
    const std::string name = "step_" + std::to_string(s);
    if (d.cells.size() <= 1) {
      o << uniformGrid(d, d.cells.empty() ? nullptr : &d.cells[0], name, s, geometryStep, true, indent);
      continue;
    }
    o << indent << "<Grid Name=\"" << name << "\" GridType=\"Collection\" CollectionType=\"Spatial\">\n"
      << indent << "  <Time Value=\"" << number(d.stepValues[s]) << "\"/>\n";
    for (const auto& c : d.cells) o << uniformGrid(d, &c, c.name, s, geometryStep, false, indent + "  ");
    o << indent << "</Grid>\n";
  }
  o << "    </Grid>\n"
    << "  </Domain>\n"
    << "</Xdmf>\n";
  return o.str();
}

void writeXdmfFile(const std::string& path, const XdmfDescription& d) {
  const std::string part = path + ".part";
  {
    std::ofstream out(part, std::ios::binary | std::ios::trunc);
    out << xdmfText(d);
    out.close();
    if (!out) throw std::runtime_error("cannot write XDMF file " + part);
  }
  if (std::rename(part.c_str(), path.c_str()) != 0) throw std::runtime_error("cannot rename " + part + " to " + path);
}

}  // namespace sinew
