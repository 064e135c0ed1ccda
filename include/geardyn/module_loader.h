#pragma once
/// \file
/// Optional modules: shared libraries built with geardyn that carry a heavy dependency only some
/// runs need — libgeardyn_hdf5.so (HDF5, for .h5 files) and libgeardyn_mpi.so (OpenMPI, for
/// `mpirun ... geardyn sweep`). They are loaded on first use, so a plain command maps neither
/// (issue 22: they made up 90 % of the start-up).

#include <string>

namespace geardyn {

/// Loads `file_name` (once; later calls reuse it) and returns the address of `symbol` in it.
/// Searched, in order: the folder $GEARDYN_MODULE_DIR; the folder of the executable or shared
/// library that holds geardyn's code, and its ../lib; the build tree's lib folder. `global`
/// makes the module's symbols available to libraries it loads later (OpenMPI's components
/// need it). Throws IoError naming the places searched and the loader's reason.
void* loadModuleSymbol(const std::string& file_name, const char* symbol, bool global = false);

}  // namespace geardyn
