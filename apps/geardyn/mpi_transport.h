#pragma once
/// \file
/// The MPI calls of `geardyn sweep`'s work queue, in a module of their own (libgeardyn_mpi.so,
/// mpi_transport.cpp) that geardyn loads only when an MPI launcher started it: a plain command
/// never maps libmpi and its dependencies (issue 22). The work queue itself stays in
/// sweep_runner.cpp; the module passes bytes and case indices, no exception leaves it.

namespace geardyn::cli {

inline constexpr int kMpiTransportVersion = 1;

/// The functions of libgeardyn_mpi.so, on MPI_COMM_WORLD. Each returns MPI's error code (0: ok).
struct MpiTransport {
  int version;
  /// MPI_Init_thread (funneled: only the calling thread talks MPI); this rank and the size.
  int (*init)(int* rank, int* size);
  int (*finalize)();
  /// MPI_Bcast of one int from rank 0.
  int (*broadcast_int)(int* value);
  int (*send_bytes)(const char* data, int count, int destination, int tag);
  /// Non-blocking probe for a byte message with `tag` from any rank: *waiting = 1 and its source
  /// and length when there is one.
  int (*probe_bytes)(int tag, int* waiting, int* source, int* count);
  int (*receive_bytes)(char* data, int count, int source, int tag);
  int (*send_index)(long long index, int destination, int tag);
  int (*receive_index)(long long* index, int source, int tag);
};

}  // namespace geardyn::cli

/// The entry point of libgeardyn_mpi.so.
extern "C" const geardyn::cli::MpiTransport* geardyn_mpi_transport();
