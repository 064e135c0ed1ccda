/// libgeardyn_mpi.so: the only translation unit that calls MPI (see mpi_transport.h).

#include "mpi_transport.h"

#include <mpi.h>

namespace geardyn::cli {
namespace {

int init(int* rank, int* size) {
  int provided = 0;
  int error = MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
  if (error == MPI_SUCCESS) error = MPI_Comm_rank(MPI_COMM_WORLD, rank);
  if (error == MPI_SUCCESS) error = MPI_Comm_size(MPI_COMM_WORLD, size);
  return error;
}

int finalize() {
  return MPI_Finalize();
}

int broadcastInt(int* value) {
  return MPI_Bcast(value, 1, MPI_INT, 0, MPI_COMM_WORLD);
}

int sendBytes(const char* data, int count, int destination, int tag) {
  return MPI_Send(data, count, MPI_CHAR, destination, tag, MPI_COMM_WORLD);
}

int probeBytes(int tag, int* waiting, int* source, int* count) {
  MPI_Status status;
  int error = MPI_Iprobe(MPI_ANY_SOURCE, tag, MPI_COMM_WORLD, waiting, &status);
  if (error == MPI_SUCCESS && *waiting) {
    *source = status.MPI_SOURCE;
    error = MPI_Get_count(&status, MPI_CHAR, count);
  }
  return error;
}

int receiveBytes(char* data, int count, int source, int tag) {
  return MPI_Recv(data, count, MPI_CHAR, source, tag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
}

int sendIndex(long long index, int destination, int tag) {
  return MPI_Send(&index, 1, MPI_LONG_LONG, destination, tag, MPI_COMM_WORLD);
}

int receiveIndex(long long* index, int source, int tag) {
  return MPI_Recv(index, 1, MPI_LONG_LONG, source, tag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
}

const MpiTransport kTransport{kMpiTransportVersion, init,      finalize,
                              broadcastInt,         sendBytes, probeBytes,
                              receiveBytes,         sendIndex, receiveIndex};

}  // namespace
}  // namespace geardyn::cli

extern "C" __attribute__((visibility("default"))) const geardyn::cli::MpiTransport*
geardyn_mpi_transport() {
  return &geardyn::cli::kTransport;
}
