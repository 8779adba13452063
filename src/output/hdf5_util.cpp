#include "output/hdf5_util.hpp"

#include <stdexcept>

namespace sinew::h5 {

namespace {
// Walks the error stack from the innermost frame and keeps the first description.
herr_t innermost(unsigned /*n*/, const H5E_error2_t* err, void* data) {
  auto* out = static_cast<std::string*>(data);
  if (out->empty() && err && err->desc) *out = err->desc;
  return 0;
}
}  // namespace

std::string failureText(const std::string& what) {
  std::string detail;
  H5Ewalk2(H5E_DEFAULT, H5E_WALK_DOWNWARD, innermost, &detail);
  return "HDF5 error: " + what + (detail.empty() ? "" : " (" + detail + ")");
}

void fail(const std::string& what) { throw std::runtime_error(failureText(what)); }

Handle& Handle::operator=(Handle&& o) noexcept {
  if (this != &o) {
    reset();
    id_ = o.id_;
    closer_ = o.closer_;
    o.id_ = H5I_INVALID_HID;
  }
  return *this;
}

herr_t Handle::reset() noexcept {
  herr_t status = 0;
  if (id_ >= 0 && closer_) status = closer_(id_);
  id_ = H5I_INVALID_HID;
  return status;
}

Handle dataspace(const std::vector<hsize_t>& dims, const std::vector<hsize_t>& maxdims, const std::string& what) {
  if (dims.empty()) return Handle(H5Screate(H5S_SCALAR), H5Sclose, what + ": scalar dataspace");
  return Handle(H5Screate_simple(static_cast<int>(dims.size()), dims.data(), maxdims.empty() ? nullptr : maxdims.data()),
                H5Sclose, what + ": dataspace");
}

Handle dataspace(const std::vector<hsize_t>& dims, const std::string& what) { return dataspace(dims, {}, what); }

Handle intermediateGroupLcpl(const std::string& what) {
  Handle lcpl(H5Pcreate(H5P_LINK_CREATE), H5Pclose, what + ": link creation list");
  check(H5Pset_create_intermediate_group(lcpl, 1), what + ": intermediate groups");
  return lcpl;
}

Handle independentDxpl() {
  Handle dxpl(H5Pcreate(H5P_DATASET_XFER), H5Pclose, "dataset transfer list");
  check(H5Pset_dxpl_mpio(dxpl, H5FD_MPIO_INDEPENDENT), "independent transfer");
  return dxpl;
}

herr_t writeBox(hid_t dset, hid_t memType, const std::vector<hsize_t>& start, const std::vector<hsize_t>& count,
              const void* data, hid_t dxpl, const std::string& what) {
  hsize_t n = 1;
  for (hsize_t c : count) n *= c;
  if (!data || n == 0) return 0;  // nothing here (the transfer is independent: no call to take part in)
  Handle fileSpace(H5Dget_space(dset), H5Sclose, what + ": file dataspace");
  if (!count.empty())
    check(H5Sselect_hyperslab(fileSpace, H5S_SELECT_SET, start.data(), nullptr, count.data(), nullptr),
          what + ": select rows");
  Handle memSpace = dataspace(count, what);
  return H5Dwrite(dset, memType, memSpace, fileSpace, dxpl, data);
}

namespace {
void writeScalarAttribute(hid_t obj, const std::string& name, hid_t fileType, hid_t memType, const void* value) {
  const std::string what = "attribute " + name;
  if (check(H5Aexists(obj, name.c_str()), what) > 0) check(H5Adelete(obj, name.c_str()), what + ": replace");
  Handle space = dataspace({}, what);
  Handle attr(H5Acreate2(obj, name.c_str(), fileType, space, H5P_DEFAULT, H5P_DEFAULT), H5Aclose, what + ": create");
  check(H5Awrite(attr, memType, value), what + ": write");
  check(attr.reset(), what + ": close");
}
}  // namespace

void writeAttribute(hid_t obj, const std::string& name, const std::string& value) {
  // Variable-length UTF-8 string: lives in the global heap, so a long scene text does not hit
  // the 64 KiB object-header limit of compact attributes.
  Handle type(H5Tcopy(H5T_C_S1), H5Tclose, "attribute " + name + ": string type");
  check(H5Tset_size(type, H5T_VARIABLE), "attribute " + name + ": string size");
  check(H5Tset_cset(type, H5T_CSET_UTF8), "attribute " + name + ": string charset");
  const char* ptr = value.c_str();
  writeScalarAttribute(obj, name, type, type, &ptr);
}

void writeAttribute(hid_t obj, const std::string& name, long value) {
  const long long v = value;
  writeScalarAttribute(obj, name, H5T_STD_I64LE, H5T_NATIVE_LLONG, &v);
}

void writeAttribute(hid_t obj, const std::string& name, int value) {
  writeScalarAttribute(obj, name, H5T_STD_I32LE, H5T_NATIVE_INT, &value);
}

}  // namespace sinew::h5
