#pragma once

namespace texsplat::apps {

/// @brief MPI for the lifetime of `texsplat` when a launcher (mpirun, mpiexec, srun) started it:
/// MPI_Init then, MPI_Finalize at the end; nothing when it was started alone, so that a plain run
/// needs no MPI runtime. `texsplat render` renders split over the processes when MPI is
/// initialized (docs/distributed.md).
class MpiSession {
public:
    /// @brief Initializes MPI (funneled: only the main thread calls it) when a launcher's
    /// variables are set (OpenMPI's OMPI_COMM_WORLD_SIZE, PMI's PMI_SIZE, PMIx's PMIX_RANK).
    MpiSession(int& argc, char**& argv);
    ~MpiSession();
    MpiSession(const MpiSession&) = delete;
    MpiSession& operator=(const MpiSession&) = delete;

    /// @brief This process's rank, 0 without MPI.
    int rank() const { return mRank; }

private:
    bool mIsInitialized = false;
    int mRank = 0;
};

/// @brief Whether this process runs under MPI (MpiSession initialized it), so that `render` is
/// split over the processes.
bool isDistributed();

} // namespace texsplat::apps
