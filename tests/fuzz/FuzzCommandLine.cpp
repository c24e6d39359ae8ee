// libFuzzer target for the texsplat command line: the input, split at newlines, is the argument
// list after "texsplat"; it is parsed and checked as `main` does (runCommandLine), in
// CommandMode::CheckOptions, so nothing is read, written or rendered. Every outcome is help, a
// version, success or an error message ("texsplat: error: ..."); an internal error (an exception
// that is not a texsplat::Error) or a crash is a finding.

#include "apps/CommandLine.h"

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    // More arguments than any real command line has: the fuzzer's time goes to their values.
    constexpr std::size_t kMaxArguments = 64;
    std::vector<std::string> arguments{"texsplat"};
    std::string current;
    for (std::size_t i = 0; i < size && arguments.size() <= kMaxArguments; ++i) {
        if (data[i] == '\n') {
            arguments.push_back(current);
            current.clear();
        } else {
            current += char(data[i]);
        }
    }
    if (!current.empty() && arguments.size() <= kMaxArguments)
        arguments.push_back(current);
    std::vector<const char*> argv;
    for (const std::string& argument : arguments)
        argv.push_back(argument.c_str());
    std::ostringstream out;
    std::ostringstream errors;
    const int exitCode = texsplat::apps::runCommandLine(
        int(argv.size()), argv.data(), texsplat::apps::CommandMode::CheckOptions, out, errors);
    const std::string message = errors.str();
    if (message.rfind("texsplat: internal error", 0) == 0 || exitCode < 0 || exitCode > 2) {
        std::fprintf(stderr, "exit code %d: %s\n", exitCode, message.c_str());
        std::abort();
    }
    return 0;
}
