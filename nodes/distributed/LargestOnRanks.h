#pragma once

#include <mpi.h>

#include <vector>

namespace texsplat::distributed {

/// @brief A value's largest value over the ranks, and the rank that has it.
struct LargestOnRank {
    double value = 0.0; ///< the largest
    int rank = 0;       ///< the lowest rank that has it
};

/// @brief For each of `values` (as many on every rank), its largest over the ranks of `comm`
/// and where: each step's slowest rank, the largest memory (a collective; every rank gets the
/// answer).
std::vector<LargestOnRank> largestOnRanks(MPI_Comm comm, const std::vector<double>& values);

} // namespace texsplat::distributed
