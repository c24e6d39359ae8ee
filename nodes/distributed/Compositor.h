#pragma once

#include "nodes/distributed/ImageLayer.h"

#include <mpi.h>

#include <string>
#include <vector>

namespace texsplat::distributed {

/// @brief How the ranks' images are composited (docs/distributed.md, "Compositing").
enum class Compositing {
    /// Radix-k over MPI point-to-point messages (Peterka et al. 2009; binary swap when every
    /// round has two ranks): in rounds of groups of k ranks, each rank keeps a k-th of its
    /// group's part of the image and composites the group's pixels there, then the parts go to
    /// rank 0. Each rank sends and composites about as many pixels as the image has whatever
    /// the number of ranks, and only the pixels its brick covers.
    RadixK,
    /// MPI_Reduce with a non-commutative "over" over a communicator whose ranks are ordered by
    /// visibility: MPI's own reduction, whole images at each step of its tree.
    Reduce,
};

/// @brief "radix-k" or "reduce".
std::string toString(Compositing method);

/// @brief Parses "radix-k" or "reduce".
/// @throws DataError naming `option` otherwise.
Compositing parseCompositing(const std::string& text, const std::string& option);

/// @brief Composites the ranks' layers of a width x height image with "over" in a given order:
/// sort-last compositing over MPI.
class Compositor {
public:
    /// @brief A compositor for images of `width` x `height` pixels over `comm`.
    Compositor(MPI_Comm comm, int width, int height, Compositing method = Compositing::RadixK);

    /// @brief Every rank calls it (a collective) with its layer and the ranks back to front
    /// (`backToFront[i]`: the rank of the i-th farthest brick): rank 0 gets the whole image's
    /// pixels (width x height, top row first), composited front over back onto transparent;
    /// the other ranks get nothing (empty). The layer must lie inside the image; it is taken
    /// (moved in), so that its pixels are freed as soon as they are passed on.
    /// Cannot fail (it allocates what its first step checked, checkMemory()): no rank
    /// gives up while the others wait for it.
    image::Pixels composite(ImageLayer layer, const std::vector<int>& backToFront);

    /// @brief The bytes compositing may allocate on this rank at most, for a step that checks
    /// them (checkMemory()) before compositing starts.
    std::uint64_t memoryBound(const ImageLayer& layer) const;

    /// @brief The group sizes of the radix-k rounds for `ranks` ranks: its prime factors, two 2s
    /// merged into a 4 (1024 ranks: five rounds of 4; 12: 4 then 3; a prime: one round).
    static std::vector<int> radixRounds(int ranks);

private:
    image::Pixels compositeRadixK(ImageLayer layer, const std::vector<int>& backToFront);
    image::Pixels compositeReduce(const ImageLayer& layer,
                                           const std::vector<int>& backToFront);

    MPI_Comm mComm;
    int mRank = 0;
    int mSize = 1;
    int mWidth;
    int mHeight;
    Compositing mMethod;
};

} // namespace texsplat::distributed
