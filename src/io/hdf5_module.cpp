/// libgeardyn_hdf5.so: the only translation unit that calls HDF5 (see hdf5_module.h). Built as
/// a module of its own and loaded on demand; no geardyn symbol is used here, no exception leaves.

#include "hdf5_module.h"

#include <hdf5.h>

namespace geardyn::io::detail {
namespace {

/// Closes an HDF5 handle on scope exit.
struct Handle {
  hid_t id;
  herr_t (*close)(hid_t);
  ~Handle() {
    if (id >= 0) close(id);
  }
};

hid_t utf8StringType() {
  const hid_t type = H5Tcopy(H5T_C_S1);
  H5Tset_size(type, H5T_VARIABLE);
  H5Tset_cset(type, H5T_CSET_UTF8);
  return type;
}

bool writeDataset(hid_t file, const Hdf5Dataset& d) {
  const hsize_t dims[2] = {d.rows, d.cols};
  Handle space{H5Screate_simple(d.cols > 0 ? 2 : 1, dims, nullptr), H5Sclose};
  using Type = Hdf5Dataset::Type;
  hid_t file_type = H5T_IEEE_F64LE, memory_type = H5T_NATIVE_DOUBLE;
  const void* data = d.f64.data();
  bool empty = d.f64.empty();
  Handle text_type{-1, H5Tclose};
  std::vector<const char*> pointers;
  switch (d.type) {
    case Type::kFloat64:
      break;
    case Type::kInt64:
      file_type = H5T_STD_I64LE, memory_type = H5T_NATIVE_INT64, data = d.i64.data();
      empty = d.i64.empty();
      break;
    case Type::kUInt64:
      file_type = H5T_STD_U64LE, memory_type = H5T_NATIVE_UINT64, data = d.u64.data();
      empty = d.u64.empty();
      break;
    case Type::kString:
      text_type.id = utf8StringType();
      file_type = memory_type = text_type.id;
      for (const auto& s : d.text) pointers.push_back(s.c_str());
      data = pointers.data();
      empty = pointers.empty();
      break;
  }
  Handle set{
      H5Dcreate2(file, d.name.c_str(), file_type, space.id, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
      H5Dclose};
  return set.id >= 0 &&
         (empty || H5Dwrite(set.id, memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data) >= 0);
}

bool writeAttribute(hid_t file, const Hdf5Attribute& a) {
  if (a.is_text) {
    Handle type{utf8StringType(), H5Tclose};
    Handle space{H5Screate(H5S_SCALAR), H5Sclose};
    Handle attr{H5Acreate2(file, a.name.c_str(), type.id, space.id, H5P_DEFAULT, H5P_DEFAULT),
                H5Aclose};
    const char* p = a.text.c_str();
    return attr.id >= 0 && H5Awrite(attr.id, type.id, &p) >= 0;
  }
  const hsize_t one = 1;
  Handle space{H5Screate_simple(1, &one, nullptr), H5Sclose};
  Handle attr{H5Acreate2(file, a.name.c_str(), H5T_IEEE_F64LE, space.id, H5P_DEFAULT, H5P_DEFAULT),
              H5Aclose};
  return attr.id >= 0 && H5Awrite(attr.id, H5T_NATIVE_DOUBLE, &a.number) >= 0;
}

const char* write(const char* path, const Hdf5Content& content) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  Handle file{H5Fcreate(path, H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), H5Fclose};
  if (file.id < 0) return "cannot create the file";
  for (const auto& a : content.attributes) {
    if (!writeAttribute(file.id, a)) return "cannot write an attribute";
  }
  for (const auto& d : content.datasets) {
    if (!writeDataset(file.id, d)) return "cannot write a dataset";
  }
  if (H5Fflush(file.id, H5F_SCOPE_GLOBAL) < 0) return "cannot flush the file";
  return nullptr;
}

std::int64_t open(const char* path) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  if (H5Fis_hdf5(path) <= 0) return -kHdf5NotHdf5;
  const hid_t file = H5Fopen(path, H5F_ACC_RDONLY, H5P_DEFAULT);
  return file >= 0 ? file : -kHdf5CannotOpen;
}

void close(std::int64_t file) {
  if (file >= 0) H5Fclose(file);
}

bool hasDataset(std::int64_t file, const char* name) {
  return H5Lexists(file, name, H5P_DEFAULT) > 0;
}

bool hasAttribute(std::int64_t file, const char* name) {
  return H5Aexists(file, name) > 0;
}

int readNumberAttribute(std::int64_t file, const char* name, double* value) {
  Handle attr{H5Aopen(file, name, H5P_DEFAULT), H5Aclose};
  if (attr.id < 0) return kHdf5CannotOpen;
  return H5Aread(attr.id, H5T_NATIVE_DOUBLE, value) < 0 ? kHdf5CannotRead : kHdf5Ok;
}

int datasetLength(std::int64_t file, const char* name, std::uint64_t* length) {
  Handle set{H5Dopen2(file, name, H5P_DEFAULT), H5Dclose};
  if (set.id < 0) return kHdf5CannotOpen;
  Handle space{H5Dget_space(set.id), H5Sclose};
  if (H5Sget_simple_extent_ndims(space.id) != 1) return kHdf5NotOneDim;
  hsize_t n = 0;
  H5Sget_simple_extent_dims(space.id, &n, nullptr);
  *length = n;
  return kHdf5Ok;
}

int readDoubles(std::int64_t file, const char* name, double* values, std::uint64_t length) {
  Handle set{H5Dopen2(file, name, H5P_DEFAULT), H5Dclose};
  if (set.id < 0) return kHdf5CannotOpen;
  if (length > 0 && H5Dread(set.id, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values) < 0)
    return kHdf5CannotRead;
  return kHdf5Ok;
}

const Hdf5ModuleApi kApi{
    kHdf5ModuleVersion,  write,         open,       close, hasDataset, hasAttribute,
    readNumberAttribute, datasetLength, readDoubles};

}  // namespace
}  // namespace geardyn::io::detail

extern "C" __attribute__((visibility("default"))) const geardyn::io::detail::Hdf5ModuleApi*
geardyn_hdf5_module() {
  return &geardyn::io::detail::kApi;
}
