#pragma once
/// \file
/// The boundary to HDF5 (issue 22). Every HDF5 call of geardyn is in libgeardyn_hdf5.so
/// (hdf5_module.cpp), loaded on the first use of an .h5 file, so that the commands and files
/// that never touch HDF5 do not load it: Debian's libhdf5 alone maps some 35 libraries (libcurl,
/// GnuTLS, Kerberos, LDAP, ...) at start-up. The module exchanges plain data and reports
/// failures as values, never as exceptions; callers hold hdf5Mutex() (Debian's HDF5 is not
/// thread-safe) and turn failures into InputError/IoError with their own messages.

#include <cstdint>
#include <string>
#include <vector>

#include "geardyn/io/hdf5_file.h"

namespace geardyn::io::detail {

using io::Hdf5Attribute;
using io::Hdf5Content;
using io::Hdf5Dataset;
using io::writeHdf5File;

/// Results of the reading functions.
enum Hdf5Read : int {
  kHdf5Ok = 0,
  kHdf5NotHdf5 = 1,     ///< not an HDF5 file (or truncated)
  kHdf5CannotOpen = 2,  ///< the file or dataset cannot be opened
  kHdf5NotOneDim = 3,   ///< the dataset is not one-dimensional
  kHdf5CannotRead = 4,  ///< the values cannot be read as numbers
};

inline constexpr int kHdf5ModuleVersion = 1;

/// The functions of libgeardyn_hdf5.so. File handles are HDF5's hid_t (int64). The module only
/// reads what it is given and writes into plain buffers: it may run on another copy of the C++
/// runtime than the executable (which links libstdc++ statically).
struct Hdf5ModuleApi {
  int version;
  /// Writes `content` to `path` (truncating); nullptr, or what failed (a static string).
  const char* (*write)(const char* path, const Hdf5Content& content);
  /// Opens read-only: a handle >= 0, or −kHdf5NotHdf5 / −kHdf5CannotOpen.
  std::int64_t (*open)(const char* path);
  void (*close)(std::int64_t file);
  bool (*has_dataset)(std::int64_t file, const char* name);
  bool (*has_attribute)(std::int64_t file, const char* name);
  int (*read_number_attribute)(std::int64_t file, const char* name, double* value);
  /// The length of a one-dimensional dataset (kHdf5CannotOpen, kHdf5NotOneDim otherwise).
  int (*dataset_length)(std::int64_t file, const char* name, std::uint64_t* length);
  /// Reads `length` doubles of a one-dimensional dataset into `values`.
  int (*read_doubles)(std::int64_t file, const char* name, double* values, std::uint64_t length);
};

/// The loaded module (loaded on the first call; IoError naming where it was searched when it
/// cannot be loaded).
const Hdf5ModuleApi& hdf5Module();

}  // namespace geardyn::io::detail

/// The entry point of libgeardyn_hdf5.so.
extern "C" const geardyn::io::detail::Hdf5ModuleApi* geardyn_hdf5_module();
