#include "apps/CommandLine.h"

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
    return runCommandLine(argc, argv, CommandMode::Run, std::cout, std::cerr);
}
