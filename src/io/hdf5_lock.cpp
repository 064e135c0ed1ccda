/// The process-wide HDF5 lock (see the header).

#include "geardyn/io/hdf5_lock.h"

namespace geardyn::io {

std::mutex& hdf5Mutex() {
  static std::mutex m;
  return m;
}

}  // namespace geardyn::io
