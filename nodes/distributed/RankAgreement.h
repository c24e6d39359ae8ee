#pragma once

#include <mpi.h>

#include <exception>
#include <optional>
#include <type_traits>
#include <utility>

namespace texsplat::distributed {

/// @brief Ends a step of a distributed render on every rank of `comm` (a collective: every rank
/// calls it at the same point): when the step failed on some ranks (`failure` set there), every
/// rank throws the error of the lowest failing rank, of the same type (DataError, IoError,
/// ParseError, ResourceError, GlError, sg::Cancelled; any other exception as texsplat::Error),
/// its message prefixed with "rank R: " unless every rank failed. So a bad file or a memory
/// refusal on one rank ends the run on all of them with that rank's message, and no rank waits
/// in a later collective for one that gave up (docs/distributed.md, "Failures").
///
/// A distributed render runs as steps of local work, each ended by this, and collectives that
/// cannot fail between them: a rank that failed calls this once and so meets the others at the
/// end of the step they are in.
void agreeOnFailure(MPI_Comm comm, const std::exception_ptr& failure);

/// @brief Runs `step` on this rank and agrees on its failure (agreeOnFailure()): returns what
/// `step` returns on every rank, or throws on every rank what the lowest failing rank threw.
template <class Step> auto runAgreed(MPI_Comm comm, Step&& step) {
    using Result = std::invoke_result_t<Step&>;
    std::exception_ptr failure;
    if constexpr (std::is_void_v<Result>) {
        try {
            step();
        } catch (...) {
            failure = std::current_exception();
        }
        agreeOnFailure(comm, failure);
    } else {
        std::optional<Result> result;
        try {
            result.emplace(step());
        } catch (...) {
            failure = std::current_exception();
        }
        agreeOnFailure(comm, failure);
        return std::move(*result);
    }
}

} // namespace texsplat::distributed
