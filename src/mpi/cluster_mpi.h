// The MPI cluster (built with -DRP_MPI=ON): every rank of MPI_COMM_WORLD. Only the tools
// built into tools/mpi/ link this; the library never names MPI.
#pragma once

#include <memory>

#include "util/cluster.h"

namespace rp {

// Starts MPI (MPI_Init_thread, serialised calls from any one thread at a time: a TBB
// pipeline's serial stage sends and receives) and finalizes it when the returned object
// is destroyed. Throws InputError when MPI cannot give that thread level.
std::unique_ptr<Cluster> startMpiCluster(int& argc, char**& argv);

}  // namespace rp
