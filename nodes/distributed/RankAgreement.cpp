#include "nodes/distributed/RankAgreement.h"

#include "scenegraph/Error.h"
#include "scenegraph/WorkProgress.h"

#include <new>
#include <string>
#include <vector>

namespace texsplat::distributed {
namespace {

// The error types a failure keeps across ranks.
enum class ErrorKind : int { Other, Parse, Io, Data, Resource, Gl, Cancelled };

// The kind and message of `failure`.
std::pair<ErrorKind, std::string> describe(const std::exception_ptr& failure) {
    try {
        std::rethrow_exception(failure);
    } catch (const ParseError& error) {
        return {ErrorKind::Parse, error.what()};
    } catch (const IoError& error) {
        return {ErrorKind::Io, error.what()};
    } catch (const DataError& error) {
        return {ErrorKind::Data, error.what()};
    } catch (const ResourceError& error) {
        return {ErrorKind::Resource, error.what()};
    } catch (const GlError& error) {
        return {ErrorKind::Gl, error.what()};
    } catch (const sg::Cancelled& error) {
        return {ErrorKind::Cancelled, error.what()};
    } catch (const std::bad_alloc&) {
        return {ErrorKind::Resource, "out of memory"};
    } catch (const std::exception& error) {
        return {ErrorKind::Other, error.what()};
    } catch (...) {
        return {ErrorKind::Other, "unknown error"};
    }
}

[[noreturn]] void throwAs(ErrorKind kind, const std::string& message) {
    switch (kind) {
    case ErrorKind::Parse:
        throw ParseError(message);
    case ErrorKind::Io:
        throw IoError(message);
    case ErrorKind::Data:
        throw DataError(message);
    case ErrorKind::Resource:
        throw ResourceError(message);
    case ErrorKind::Gl:
        throw GlError(message);
    case ErrorKind::Cancelled:
        throw sg::Cancelled(message);
    case ErrorKind::Other:
        break;
    }
    throw Error(message);
}

} // namespace

void agreeOnFailure(MPI_Comm comm, const std::exception_ptr& failure) {
    int rank = 0;
    int size = 1;
    MPI_Comm_rank(comm, &rank);
    MPI_Comm_size(comm, &size);
    const int mine = failure ? rank : size;
    int failed = size;
    MPI_Allreduce(&mine, &failed, 1, MPI_INT, MPI_MIN, comm);
    if (failed == size) {
        return;
    }
    const int failing = failure ? 1 : 0;
    int failures = 0;
    MPI_Allreduce(&failing, &failures, 1, MPI_INT, MPI_SUM, comm);
    // The lowest failing rank tells everyone what happened.
    std::pair<ErrorKind, std::string> error;
    if (rank == failed) {
        error = describe(failure);
    }
    int header[2] = {static_cast<int>(error.first), static_cast<int>(error.second.size())};
    MPI_Bcast(header, 2, MPI_INT, failed, comm);
    std::vector<char> text(static_cast<std::size_t>(header[1]));
    if (rank == failed) {
        text.assign(error.second.begin(), error.second.end());
    }
    MPI_Bcast(text.data(), header[1], MPI_CHAR, failed, comm);
    const std::string message(text.begin(), text.end());
    // An error every rank met (a bad option, a scene file) needs no rank.
    throwAs(static_cast<ErrorKind>(header[0]),
            failures < size ? "rank " + std::to_string(failed) + ": " + message : message);
}

} // namespace texsplat::distributed
