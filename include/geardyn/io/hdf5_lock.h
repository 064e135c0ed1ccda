#pragma once
/// \file
/// Debian's HDF5 is built without thread safety, and `geardyn sweep` runs commands on several
/// threads of one process: every use of the HDF5 library holds this lock.

#include <mutex>

namespace geardyn::io {

/// The process-wide lock around HDF5 calls.
std::mutex& hdf5Mutex();

}  // namespace geardyn::io
