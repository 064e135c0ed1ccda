/// sweep.h5, the gathered results of `geardyn sweep` (see sweep_io.h), written atomically.

#include <fmt/format.h>
#include <hdf5.h>

#include <limits>
#include <mutex>

#include "geardyn/error.h"
#include "geardyn/io/atomic_file.h"
#include "geardyn/io/hdf5_lock.h"
#include "geardyn/io/sweep_io.h"
#include "geardyn/version.h"

namespace geardyn::io {
namespace fs = std::filesystem;

namespace {

struct H5 {
  hid_t id;
  herr_t (*close)(hid_t);
  ~H5() {
    if (id >= 0) close(id);
  }
};

void writeStrings(hid_t file, const char* name, const std::vector<std::string>& values,
                  hsize_t rows, hsize_t cols) {
  H5 type{H5Tcopy(H5T_C_S1), H5Tclose};
  H5Tset_size(type.id, H5T_VARIABLE);
  H5Tset_cset(type.id, H5T_CSET_UTF8);
  const hsize_t dims[2] = {rows, cols};
  H5 space{H5Screate_simple(cols > 0 ? 2 : 1, dims, nullptr), H5Sclose};
  H5 set{H5Dcreate2(file, name, type.id, space.id, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
         H5Dclose};
  std::vector<const char*> ptrs;
  for (const auto& s : values) ptrs.push_back(s.c_str());
  if (set.id < 0 ||
      (!ptrs.empty() && H5Dwrite(set.id, type.id, H5S_ALL, H5S_ALL, H5P_DEFAULT, ptrs.data()) < 0))
    throw IoError(fmt::format("cannot write dataset {}", name));
}

template <typename T>
void writeNumbers(hid_t file, const char* name, hid_t file_type, hid_t memory_type,
                  const std::vector<T>& values, hsize_t rows, hsize_t cols) {
  const hsize_t dims[2] = {rows, cols};
  H5 space{H5Screate_simple(cols > 0 ? 2 : 1, dims, nullptr), H5Sclose};
  H5 set{H5Dcreate2(file, name, file_type, space.id, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
         H5Dclose};
  if (set.id < 0 || (!values.empty() && H5Dwrite(set.id, memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT,
                                                 values.data()) < 0))
    throw IoError(fmt::format("cannot write dataset {}", name));
}

void writeAttribute(hid_t object, const char* name, const std::string& value) {
  H5 type{H5Tcopy(H5T_C_S1), H5Tclose};
  H5Tset_size(type.id, H5T_VARIABLE);
  H5Tset_cset(type.id, H5T_CSET_UTF8);
  H5 space{H5Screate(H5S_SCALAR), H5Sclose};
  H5 attr{H5Acreate2(object, name, type.id, space.id, H5P_DEFAULT, H5P_DEFAULT), H5Aclose};
  const char* p = value.c_str();
  if (attr.id < 0 || H5Awrite(attr.id, type.id, &p) < 0)
    throw IoError(fmt::format("cannot write attribute {}", name));
}

}  // namespace

void writeSweepHdf5(const fs::path& path, const SweepDefinition& study,
                    const std::vector<SweepCaseRecord>& records, const std::string& base_config) {
  const fs::path temp = temporaryPathFor(path);
  const std::lock_guard<std::mutex> lock(hdf5Mutex());
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  try {
    H5 file{H5Fcreate(temp.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), H5Fclose};
    if (file.id < 0) throw IoError("cannot create " + temp.string());
    const hsize_t n = records.size(), np = study.parameters.size(), no = study.outputs.size();
    std::vector<long long> index;
    std::vector<unsigned long long> seeds;
    std::vector<std::string> status, message, text;
    std::vector<double> params, outputs;
    for (const auto& r : records) {
      index.push_back(r.index);
      seeds.push_back(r.seed);
      status.push_back(r.status);
      message.push_back(r.message);
      for (const auto& v : r.values) {
        params.push_back(v.is_number() ? v.get<double>()
                                       : std::numeric_limits<double>::quiet_NaN());
        text.push_back(v.is_string() ? v.get<std::string>() : v.dump());
      }
      outputs.insert(outputs.end(), r.outputs.begin(), r.outputs.end());
    }
    writeNumbers(file.id, "case", H5T_STD_I64LE, H5T_NATIVE_LLONG, index, n, 0);
    writeNumbers(file.id, "seed", H5T_STD_U64LE, H5T_NATIVE_ULLONG, seeds, n, 0);
    writeStrings(file.id, "status", status, n, 0);
    writeStrings(file.id, "message", message, n, 0);
    writeNumbers(file.id, "parameters", H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, params, n, np);
    writeStrings(file.id, "parameter_text", text, n, np);
    writeNumbers(file.id, "outputs", H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, outputs, n, no);
    std::vector<std::string> pnames, onames;
    for (const auto& p : study.parameters) pnames.push_back(p.key);
    for (const auto& o : study.outputs) onames.push_back(o.name);
    writeStrings(file.id, "parameter_names", pnames, np, 0);
    writeStrings(file.id, "output_names", onames, no, 0);
    writeAttribute(file.id, "geardyn_version", kVersion);
    writeAttribute(file.id, "study", study.resolved.dump());
    writeAttribute(file.id, "base_config", base_config);
    if (H5Fflush(file.id, H5F_SCOPE_GLOBAL) < 0) throw IoError("cannot flush " + temp.string());
  } catch (...) {
    fs::remove(temp);
    throw;
  }
  commitTemporary(temp, path);
}

}  // namespace geardyn::io
