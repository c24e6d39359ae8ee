#include "apps/Commands.h"
#include "apps/DataFileOptions.h"
#include "apps/MemoryLimitOption.h"

#include "nodes/NodeTypes.h"
#include "nodes/volume/VolumeFileInfo.h"
#include "scenegraph/AtomicFile.h"
#include "scenegraph/Error.h"
#include "scenegraph/MemoryLimit.h"
#include "scenegraph/Node.h"
#include "scenegraph/NodeRegistry.h"
#include "scenegraph/engines/EngineTypes.h"
#include "scenegraph/io/SceneReader.h"
#include "scenegraph/io/SceneReference.h"
#include "scenegraph/io/SceneSummary.h"
#include "scenegraph/io/WriteAction.h"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <fstream>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace texsplat::apps {

namespace {

struct InfoArguments {
    std::string scene;
    bool reference = false;
    std::string update;
    bool printScene = false;
    HeaderlessOptions headerless;
    std::string memoryLimit;
    std::vector<std::string> dataRoots;
};

// The types a scene file may name: the core's and the nodes library's nodes, and the engines.
void registerTypes() {
    nodes::registerNodeTypes();
    sg::registerEngineTypes(sg::NodeRegistry::instance());
}

std::string readText(const std::string& path) {
    std::ifstream file(path, std::ios::binary);
    if (!file) {
        throw IoError(path + ": cannot open");
    }
    std::ostringstream text;
    text << file.rdbuf();
    return text.str();
}

// The graph as the writer writes it (so the output is itself a valid scene file), with a
// summary comment after the header.
void printScene(const std::string& path) {
    const std::shared_ptr<sg::Node> root = sg::SceneReader::readFile(path);
    std::string text = sg::WriteAction::writeString(*root);
    const std::string summary = "# " + path + ": " + sg::SceneSummary(*root).text() + "\n";
    text.insert(text.find('\n') + 1, summary);
    std::fputs(text.c_str(), stdout);
}

void runInfo(const InfoArguments& arguments) {
    registerTypes();
    if (!arguments.reference) {
        setMemoryLimit(memoryLimitOf(arguments.memoryLimit));
        const std::optional<volume::HeaderlessRawLayout> headerless =
            headerlessLayout(arguments.headerless);
        // A data file (by its first bytes or extension) gets what a scene needs to read it.
        if (headerless ||
            volume::detectVolumeFileFormat(arguments.scene) != volume::VolumeFileFormat::Unknown) {
            if (const auto roots = dataRootsOf(arguments.dataRoots)) {
                roots->check(arguments.scene, "data file");
            }
            std::fputs((arguments.printScene
                            ? volume::quickLookScene(arguments.scene, headerless)
                            : volume::describeVolumeFile(arguments.scene, 10, headerless,
                                                         dataRootsOf(arguments.dataRoots).get()))
                           .c_str(),
                       stdout);
            return;
        }
        if (arguments.printScene) {
            throw DataError("--scene: " + arguments.scene +
                            " is not a data file texsplat reads (texsplat-raw, .npy, NRRD, NetCDF, "
                            ".vdb, or headerless raw with --dims)");
        }
        printScene(arguments.scene);
        return;
    }
    const std::string reference = sg::sceneReferenceMarkdown();
    if (arguments.update.empty()) {
        std::fputs(reference.c_str(), stdout);
        return;
    }
    writeFileAtomically(arguments.update,
                        sg::replaceGeneratedReference(readText(arguments.update), reference,
                                                      arguments.update));
}

} // namespace

void addInfoCommand(CLI::App& app, int& exitCode, CommandMode mode) {
    auto arguments = std::make_shared<InfoArguments>();
    CLI::App* command = app.add_subcommand(
        "info", "Print a scene file's graph (types, names, fields that differ from their "
                "defaults), what a data file holds (texsplat-raw, .npy, NRRD, NetCDF, .vdb, or "
                "headerless raw with --dims: grids, dimensions, voxel size, bounds, value range, "
                "histogram) and a scene that draws it (--scene), or the scene-file reference of "
                "every node and engine type");
    CLI::Option* scene = command->add_option(
        "scene", arguments->scene,
        "Inventor scene file (.iv) or data file (texsplat-raw, .npy, NRRD, NetCDF, .vdb; raw "
        "values with --dims) to describe");
    CLI::Option* reference = command->add_flag(
        "--reference", arguments->reference,
        "Print the Markdown reference of every node and engine type, generated from the types");
    command
        ->add_option("--update", arguments->update,
                     "With --reference: rewrite the generated section of this Markdown file "
                     "(docs/scene-files.md) instead of printing")
        ->needs(reference);
    reference->excludes(scene);
    command->add_flag("--scene", arguments->printScene,
                      "For a data file: print a scene file that draws it (what `texsplat render "
                      "FILE` draws), to save and edit");
    addHeaderlessOptions(*command, arguments->headerless);
    addMemoryLimitOption(*command, arguments->memoryLimit);
    addDataRootOption(*command, arguments->dataRoots);
    command->callback([arguments, scene, mode, &exitCode] {
        if (!arguments->reference && scene->count() == 0) {
            throw CLI::RequiredError("scene (or --reference)");
        }
        headerlessLayout(arguments->headerless);
        memoryLimitOf(arguments->memoryLimit);
        if (mode == CommandMode::Run) {
            runInfo(*arguments);
        }
        exitCode = kExitOk;
    });
}

} // namespace texsplat::apps
