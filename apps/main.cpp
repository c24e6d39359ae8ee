#include "apps/CommandLine.h"
#include "scenegraph/LoaderPages.h"

#ifdef TEXSPLAT_WITH_MPI
#include "apps/MpiSession.h"

#include <cstdio>
#endif

#include <iostream>

int main(int argc, char** argv) {
    using namespace texsplat::apps;
#ifdef TEXSPLAT_WITH_MPI
    // Under mpirun rank 0 speaks for all: every step of a split render ends with the ranks
    // agreeing on failures, so the others' errors are rank 0's too, and they write nothing.
    const MpiSession mpi(argc, argv);
    if (mpi.rank() != 0) {
        std::freopen("/dev/null", "w", stdout);
        std::freopen("/dev/null", "w", stderr);
    }
#endif
    // What the loader read to bind the libraries (OpenVDB's names alone are 26 MiB) would
    // otherwise stay in every process's resident memory, in every rank of an MPI run.
    texsplat::releaseLoaderPages();
    return runCommandLine(argc, argv, CommandMode::Run, std::cout, std::cerr);
}
