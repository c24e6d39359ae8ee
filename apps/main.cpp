#include "apps/CommandLine.h"

#include <iostream>

int main(int argc, char** argv) {
    using namespace texsplat::apps;
    return runCommandLine(argc, argv, CommandMode::Run, std::cout, std::cerr);
}
