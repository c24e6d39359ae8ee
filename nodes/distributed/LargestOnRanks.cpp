#include "nodes/distributed/LargestOnRanks.h"

namespace texsplat::distributed {

std::vector<LargestOnRank> largestOnRanks(MPI_Comm comm, const std::vector<double>& values) {
    // MPI_DOUBLE_INT's layout.
    struct ValueAndRank {
        double value;
        int rank;
    };
    int rank = 0;
    MPI_Comm_rank(comm, &rank);
    std::vector<ValueAndRank> pairs;
    pairs.reserve(values.size());
    for (const double value : values) {
        pairs.push_back({value, rank});
    }
    MPI_Allreduce(MPI_IN_PLACE, pairs.data(), static_cast<int>(pairs.size()), MPI_DOUBLE_INT,
                  MPI_MAXLOC, comm);
    std::vector<LargestOnRank> result;
    result.reserve(pairs.size());
    for (const ValueAndRank& pair : pairs) {
        result.push_back({pair.value, pair.rank});
    }
    return result;
}

} // namespace texsplat::distributed
