// How the programs that split their work over MPI ranks (mkpmap, rtrace, rcontrib, rpict)
// start their cluster and end it on an error. Built twice: in tools/ as this process
// alone, and with RP_WITH_MPI (cmake -DRP_MPI=ON) in tools/mpi/ over MPI_COMM_WORLD.
#pragma once

#include <chrono>
#include <iostream>
#include <memory>
#include <string>
#include <thread>

#include "util/cluster.h"
#include "util/warnings.h"
#ifdef RP_WITH_MPI
#include "mpi/cluster_mpi.h"
#endif

namespace rp::tools {

inline std::unique_ptr<Cluster> startCluster(int& argc, char**& argv) {
#ifdef RP_WITH_MPI
    return startMpiCluster(argc, argv);
#else
    (void)argc;
    (void)argv;
    return std::make_unique<LocalCluster>();
#endif
}

// Ranks other than the root say nothing but errors: their warnings are the root's too.
inline void quietUnlessRoot(const Cluster& cluster) {
    if (!cluster.isRoot()) setWarningSink([](const std::string&) {});
}

// The start of this rank's error line: "rtrace: " on the root and alone, "rtrace: rank 2: "
// on another rank, which first waits a moment, so that an error every rank meets (a bad
// scene, an existing output) is reported once, by the root, before it ends the run.
inline std::string errorPrefix(const Cluster& cluster, const std::string& program) {
    if (cluster.isRoot()) return program + ": ";
    std::this_thread::sleep_for(std::chrono::seconds(2));
    return program + ": rank " + std::to_string(cluster.rank()) + ": ";
}

// After an error has been reported: the exit code alone, or, with other ranks, the end of
// every rank (none may be left waiting for this one), with that code from mpirun.
inline int endRun(Cluster& cluster, int exitCode) {
    if (distributed(&cluster)) cluster.abortAll(exitCode);
    return exitCode;
}

// Reports this rank's error on `diag` (and on standard error too when diag is a file) and
// ends the run with `exitCode`. `cluster` may be null (MPI did not start).
inline int failRun(Cluster* cluster, const std::string& program, const std::string& message,
                   std::ostream& diag, int exitCode = 1) {
    LocalCluster alone;
    Cluster& c = cluster ? *cluster : alone;
    const std::string line = errorPrefix(c, program) + message;
    diag << line << '\n';
    if (&diag != &std::cerr) std::cerr << line << '\n';
    diag.flush();
    return endRun(c, exitCode);
}

}  // namespace rp::tools
