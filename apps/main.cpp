#include "apps/Commands.h"
#include "scenegraph/Error.h"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <exception>

int main(int argc, char** argv) {
    using namespace texsplat::apps;
    CLI::App app{"texsplat: texture splats for 3D scalar and vector field visualization"};
    app.require_subcommand(1);
    int exitCode = kExitOk;
    addKernelCommand(app, exitCode);
    addInfoCommand(app, exitCode);
    addCompareCommand(app, exitCode);
    addRenderCommand(app, exitCode);
    addBenchCommand(app, exitCode);
#ifdef TEXSPLAT_WITH_VIEWER
    addViewCommand(app, exitCode);
#endif
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return app.exit(e);
    } catch (const texsplat::Error& e) {
        std::fprintf(stderr, "texsplat: error: %s\n", e.what());
        return kExitFailure;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "texsplat: internal error: %s\n", e.what());
        return kExitFailure;
    }
    return exitCode;
}
