// Small RAII and error-checking helpers around the HDF5 C API, used by the result file.
#pragma once
#include <hdf5.h>

#include <string>
#include <vector>

namespace sinew::h5 {

/// "HDF5 error: <what> (<innermost HDF5 error description>)" from the current error stack.
std::string failureText(const std::string& what);
/// Throws std::runtime_error with failureText(what).
[[noreturn]] void fail(const std::string& what);

/// Returns `r` when the HDF5 call succeeded (r >= 0), otherwise throws via fail(what).
template <class T>
T check(T r, const std::string& what) {
  if (r < 0) fail(what);
  return r;
}

/// Owns one HDF5 identifier and closes it with the matching H5?close.
class Handle {
 public:
  using Closer = herr_t (*)(hid_t);
  Handle() = default;
  Handle(hid_t id, Closer closer, const std::string& what) : id_(check(id, what)), closer_(closer) {}
  Handle(Handle&& o) noexcept : id_(o.id_), closer_(o.closer_) { o.id_ = H5I_INVALID_HID; }
  Handle& operator=(Handle&& o) noexcept;
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  ~Handle() { reset(); }
  hid_t get() const { return id_; }
  operator hid_t() const { return id_; }
  bool valid() const { return id_ >= 0; }
  /// Closes now; returns the close status (>= 0 on success, or when nothing was open).
  herr_t reset() noexcept;

 private:
  hid_t id_ = H5I_INVALID_HID;
  Closer closer_ = nullptr;
};

Handle dataspace(const std::vector<hsize_t>& dims, const std::vector<hsize_t>& maxdims, const std::string& what);
Handle dataspace(const std::vector<hsize_t>& dims, const std::string& what);
/// Link-creation property list that creates missing parent groups ("node/p" creates /node).
Handle intermediateGroupLcpl(const std::string& what);
/// Transfer property list for independent MPI-IO: each rank writes its own box without the others
/// (with collective transfers a 2-rank dynamics run spent 1.5 times the output time on its small
/// rows, docs/results.md, "Cost"; dataset creation and extension stay collective).
Handle independentDxpl();

/// This rank's write of the box [start, start + count) of `dset` from the dense buffer `data`
/// (independent transfer). A rank with nothing to write passes data == nullptr or a count
/// containing 0 and writes nothing. Empty start and count address a scalar dataset. Returns the
/// status of the H5Dwrite (the caller agrees on it across ranks); selection errors throw.
herr_t writeBox(hid_t dset, hid_t memType, const std::vector<hsize_t>& start, const std::vector<hsize_t>& count,
              const void* data, hid_t dxpl, const std::string& what);

// Root/object attributes. In parallel HDF5 these are collective: every rank passes equal values.
void writeAttribute(hid_t obj, const std::string& name, const std::string& value);
void writeAttribute(hid_t obj, const std::string& name, long value);
void writeAttribute(hid_t obj, const std::string& name, int value);

}  // namespace sinew::h5
