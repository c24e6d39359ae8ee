#pragma once

/// @file
/// @brief The `texsplat` command line: every subcommand of this build on one CLI11 app, parsed
/// and run as `main` runs it, or only checked (the command-line fuzz target).

#include "apps/Commands.h"

#include <iosfwd>

namespace texsplat::apps {

/// @brief Parses `argv` (argv[0] is the program), runs (or, with CommandMode::CheckOptions, only
/// checks) the subcommand it names, and answers the process exit code (ExitCode). Help and the
/// version go to `out`; command-line mistakes and errors go to `errors` as
/// "texsplat: error: <message>", an exception that is not a texsplat::Error as
/// "texsplat: internal error: <what>".
int runCommandLine(int argc, const char* const* argv, CommandMode mode, std::ostream& out,
                   std::ostream& errors);

} // namespace texsplat::apps
