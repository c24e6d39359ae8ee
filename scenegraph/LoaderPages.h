#pragma once

#include <cstdint>

namespace texsplat {

/// @brief Gives back the pages the dynamic loader read to bind this process's shared libraries
/// and that nothing reads again: the first, read-only segment of each library (ELF headers,
/// symbol table and names, relocations). Returns the bytes that were resident.
///
/// Debian links its libraries with BIND_NOW, so at start-up the loader looks up every symbol a
/// library imports by name: libopenvdb's 22 MB of mangled names become 26 MiB of this process's
/// resident memory (of a plain `texsplat render`'s 53 MiB), in every process of an MPI run,
/// whatever the data. The pages are clean copies of the files: the kernel reads them again if
/// anything asks (dlopen, dlsym, a backtrace), so releasing them changes nothing but the
/// resident set. Only private, clean, read-only mappings at a file's start are released, never a
/// page the loader wrote (relocated data sits in a later, writable segment). Call it once at
/// start-up, before the process maps files of its own.
std::uint64_t releaseLoaderPages();

} // namespace texsplat
