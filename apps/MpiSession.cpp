#include "apps/MpiSession.h"

#include <mpi.h>

#include <cstdlib>

namespace texsplat::apps {
namespace {

bool isLaunched() {
    for (const char* variable : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK"}) {
        if (std::getenv(variable) != nullptr) {
            return true;
        }
    }
    return false;
}

} // namespace

MpiSession::MpiSession(int& argc, char**& argv) {
    if (!isLaunched()) {
        return;
    }
    int provided = 0;
    MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided);
    mIsInitialized = true;
    MPI_Comm_rank(MPI_COMM_WORLD, &mRank);
}

MpiSession::~MpiSession() {
    if (mIsInitialized) {
        MPI_Finalize();
    }
}

bool isDistributed() {
    int initialized = 0;
    MPI_Initialized(&initialized);
    int finalized = 0;
    MPI_Finalized(&finalized);
    return initialized != 0 && finalized == 0;
}

} // namespace texsplat::apps
