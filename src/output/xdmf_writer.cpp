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

// Row `row` of a [ns, rows, inner...] dataset (ns: its rows, f.numRows on the step-analysis rows):
// a HyperSlab DataItem over the HDF5 dataset.
std::string hyperslab(const XdmfDescription& d, const XdmfField& f, long rows, long row, const std::string& indent) {
  const long ns = f.numRows >= 0 ? f.numRows : static_cast<long>(d.stepValues.size());
  std::vector<long> full{ns, rows}, start{row, 0}, stride{1, 1}, count{1, rows};
  for (long n : f.inner) {
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
    << escape(d.h5Name) << ":" << escape(f.dataset) << "</DataItem>\n"
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

std::string attributes(const XdmfDescription& d, const std::vector<XdmfField>& fields, long rows, const char* center,
                       int step, const std::string& indent) {
  std::ostringstream o;
  for (const auto& f : fields) {
    // the dataset row of this step: the step itself, or its step-analysis row (none: not shown)
    long row = step;
    if (!f.rowOfStep.empty()) row = step < static_cast<int>(f.rowOfStep.size()) ? f.rowOfStep[step] : -1;
    if (row < 0 || row >= static_cast<long>(f.written.size()) || !f.written[row]) continue;
    o << indent << "<Attribute Name=\"" << escape(f.name) << "\" AttributeType=\"" << attributeType(f.inner)
      << "\" Center=\"" << center << "\">\n"
      << hyperslab(d, f, rows, row, indent + "  ") << indent << "</Attribute>\n";
  }
  return o.str();
}

// Attributes that are the same at every step: a plain [rows, inner...] HDF DataItem.
std::string staticAttributes(const XdmfDescription& d, const std::vector<XdmfField>& fields, long rows, const char* center,
                             const std::string& indent) {
  std::ostringstream o;
  for (const auto& f : fields) {
    std::vector<long> dims{rows};
    dims.insert(dims.end(), f.inner.begin(), f.inner.end());
    o << indent << "<Attribute Name=\"" << escape(f.name) << "\" AttributeType=\"" << attributeType(f.inner)
      << "\" Center=\"" << center << "\">\n"
      << indent << "  <DataItem Dimensions=\"" << joined(dims) << "\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">"
      << escape(d.h5Name) << ":" << escape(f.dataset) << "</DataItem>\n"
      << indent << "</Attribute>\n";
  }
  return o.str();
}

// A value for the whole grid (ParaView field data).
std::string gridValue(const std::string& name, double v, const std::string& indent) {
  return indent + "<Attribute Name=\"" + escape(name) + "\" AttributeType=\"Scalar\" Center=\"Grid\">\n" + indent +
         "  <DataItem Dimensions=\"1\" NumberType=\"Float\" Precision=\"8\" Format=\"XML\">" + number(v) +
         "</DataItem>\n" + indent + "</Attribute>\n";
}

// One uniform grid: topology of one cell kind, the reference geometry, the attributes of `step`
// (step -1: no step, only the attributes that are the same at every step).
std::string uniformGrid(const XdmfDescription& d, const XdmfCellBlock* cells, const std::string& name, int step,
                        const double* time, const std::string& indent) {
  std::ostringstream o;
  o << indent << "<Grid Name=\"" << escape(name) << "\" GridType=\"Uniform\">\n";
  if (time) o << indent << "  <Time Value=\"" << number(*time) << "\"/>\n";
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
  // A plain HDF DataItem (no HyperSlab): ParaView's XDMF reader caches the geometry by its path.
  o << indent << "  <Geometry GeometryType=\"XYZ\">\n"
    << indent << "    <DataItem Dimensions=\"" << d.numMeshNodes
    << " 3\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">" << escape(d.h5Name) << ":"
    << escape(d.geometryDataset) << "</DataItem>\n"
    << indent << "  </Geometry>\n";
  if (step >= 0) o << attributes(d, d.pointFields, d.numMeshNodes, "Node", step, indent + "  ");
  if (cells && step >= 0) o << attributes(d, cells->fields, cells->count, "Cell", step, indent + "  ");
  if (cells) o << staticAttributes(d, cells->staticFields, cells->count, "Cell", indent + "  ");
  if (step >= 0) o << gridValue(d.stepName, d.stepValues[step], indent + "  ") << gridValue("hdf5_row", step, indent + "  ");
  o << indent << "</Grid>\n";
  return o.str();
}

}  // namespace

std::vector<double> xdmfTimes(const std::vector<double>& stepValues, const std::vector<char>& formFindingRows) {
  const int ns = static_cast<int>(stepValues.size());
  auto isFormFinding = [&](int s) { return s < static_cast<int>(formFindingRows.size()) && formFindingRows[s]; };
  int nff = 0;
  for (int s = 0; s < ns; ++s) nff += isFormFinding(s);
  bool increasing = true;
  double last = -1.0;
  bool first = true;
  for (int s = 0; s < ns; ++s) {
    if (isFormFinding(s)) continue;
    const double v = stepValues[s];
    if (!(v >= 0.0) || (!first && !(v > last))) increasing = false;
    last = v;
    first = false;
  }
  std::vector<double> t(ns);
  int iff = 0, iload = 0;
  for (int s = 0; s < ns; ++s) {
    if (isFormFinding(s)) t[s] = static_cast<double>(iff++ - nff);
    else t[s] = increasing ? stepValues[s] : static_cast<double>(++iload);
  }
  return t;
}

std::string xdmfText(const XdmfDescription& d) {
  std::ostringstream o;
  o << "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n"
    << "<Xdmf xmlns:xi=\"http://www.w3.org/2001/XInclude\" Version=\"3.0\">\n"
    << "  <Domain>\n";
  if (d.inputOnly) {
    // an input-only run (opt.showinputonly) has no step rows: the reference geometry alone, grid "input"
    if (d.cells.size() <= 1 && !d.geometryDataset.empty()) {
      o << uniformGrid(d, d.cells.empty() ? nullptr : &d.cells[0], "input", -1, nullptr, "    ");
    } else if (!d.geometryDataset.empty()) {
      o << "    <Grid Name=\"input\" GridType=\"Collection\" CollectionType=\"Spatial\">\n";
      for (const auto& c : d.cells) o << uniformGrid(d, &c, c.name, -1, nullptr, "      ");
      o << "    </Grid>\n";
    }
    o << "  </Domain>\n"
      << "</Xdmf>\n";
    return o.str();
  }
  o << "    <Grid Name=\"steps\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
  const std::string indent = "      ";
  const std::vector<double> times = xdmfTimes(d.stepValues, d.formFindingRows);
  for (int s = 0; s < static_cast<int>(d.stepValues.size()) && !d.geometryDataset.empty(); ++s) {
    const std::string name = "step_" + std::to_string(s);
    if (d.cells.size() <= 1) {
      o << uniformGrid(d, d.cells.empty() ? nullptr : &d.cells[0], name, s, &times[s], indent);
      continue;
    }
    o << indent << "<Grid Name=\"" << name << "\" GridType=\"Collection\" CollectionType=\"Spatial\">\n"
      << indent << "  <Time Value=\"" << number(times[s]) << "\"/>\n";
    for (const auto& c : d.cells) o << uniformGrid(d, &c, c.name, s, nullptr, indent + "  ");
    o << indent << "</Grid>\n";
  }
  o << "    </Grid>\n";
  o << "  </Domain>\n"
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
