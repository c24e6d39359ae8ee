#include "apps/CommandLine.h"

#include "nodes/image/ImageIo.h"
#include "nodes/render/cpu/SplatSpans.h"
#include "scenegraph/Error.h"

#include <CLI/CLI.hpp>

#include <exception>
#include <new>
#include <ostream>
#include <string>

namespace texsplat::apps {
namespace {

// `texsplat --version`: the version and what this build can do.
std::string versionText() {
    const auto yesNo = [](bool value) { return value ? "yes" : "no"; };
#ifdef TEXSPLAT_WITH_GL
    constexpr bool kGl = true;
#else
    constexpr bool kGl = false;
#endif
#ifdef TEXSPLAT_WITH_VIEWER
    constexpr bool kViewer = true;
#else
    constexpr bool kViewer = false;
#endif
#ifdef TEXSPLAT_WITH_OPENVDB
    constexpr bool kOpenVdb = true;
#else
    constexpr bool kOpenVdb = false;
#endif
#ifdef TEXSPLAT_WITH_GLTF
    constexpr bool kGltf = true;
#else
    constexpr bool kGltf = false;
#endif
    return std::string("texsplat ") + TEXSPLAT_VERSION + "\nbackends: CPU (" +
           texsplat::render::cpu::compositeTarget() + ")" + (kGl ? ", GL" : "") +
           "\nviewer: " + yesNo(kViewer) + ", OpenVDB: " + yesNo(kOpenVdb) +
           ", glTF: " + yesNo(kGltf) +
           ", OpenEXR: " + yesNo(texsplat::image::isExrSupported());
}

} // namespace

int runCommandLine(int argc, const char* const* argv, CommandMode mode, std::ostream& out,
                   std::ostream& errors) {
    CLI::App app{"texsplat: texture splats for 3D scalar and vector field visualization"};
    app.require_subcommand(1);
    app.set_version_flag("--version", versionText());
    int exitCode = kExitOk;
    addKernelCommand(app, exitCode, mode);
    addInfoCommand(app, exitCode, mode);
    addCompareCommand(app, exitCode, mode);
    addRenderCommand(app, exitCode, mode);
    addBenchCommand(app, exitCode, mode);
#ifdef TEXSPLAT_WITH_VIEWER
    addViewCommand(app, exitCode, mode);
#endif
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e, out, errors);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e, out, errors);
    } catch (const CLI::CallForVersion& e) {
        return app.exit(e, out, errors);
    } catch (const CLI::ParseError& e) {
        // Command-line mistakes in the same form as every other error, with the usage code.
        errors << "texsplat: error: " << e.what() << "\nRun with --help for more information.\n";
        return kExitUsage;
    } catch (const texsplat::Error& e) {
        errors << "texsplat: error: " << e.what() << "\n";
        return kExitFailure;
    } catch (const std::bad_alloc&) {
        // Work in a known stage reports itself as a ResourceError (MemoryLimit.h); this is
        // what ran out elsewhere.
        errors << "texsplat: error: out of memory; use a smaller volume, image or splat budget, "
                  "or a larger --memory-limit\n";
        return kExitFailure;
    } catch (const std::exception& e) {
        errors << "texsplat: internal error: " << e.what() << "\n";
        return kExitFailure;
    }
    return exitCode;
}

} // namespace texsplat::apps
