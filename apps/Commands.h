#pragma once

/// @file
/// @brief The `texsplat` subcommands. Each lives in its own `<Name>Command.cpp` and registers
/// itself on the CLI11 app; the command parses, calls the libraries, prints, and returns the
/// process exit code through `CommandResult`.

namespace CLI {
class App;
} // namespace CLI

namespace texsplat::apps {

/// @brief Exit codes shared by every subcommand.
enum ExitCode : int {
    kExitOk = 0,
    kExitFailure = 1, ///< an input or runtime error (texsplat::Error); the message says where
    kExitUsage = 2,   ///< bad command-line usage (CLI11's own code for parse errors)
};

/// @brief What a subcommand does once CLI11 has parsed its options.
enum class CommandMode {
    Run,          ///< check the option values, then do the work (the texsplat program)
    CheckOptions, ///< only check the option values, as the command does before any work: no file
                  ///< is read or written, no context made, nothing printed (the fuzz target)
};

/// @brief Adds `texsplat kernel` (the reconstruction kernel and the paper's table).
void addKernelCommand(CLI::App& app, int& exitCode, CommandMode mode);

/// @brief Adds `texsplat info` (a scene file's graph, or the generated scene-file reference).
void addInfoCommand(CLI::App& app, int& exitCode, CommandMode mode);

/// @brief Adds `texsplat compare` (RMSE, PSNR and max abs error between two images, and a
/// false-color difference image).
void addCompareCommand(CLI::App& app, int& exitCode, CommandMode mode);

/// @brief Adds `texsplat render` (a scene, or the built-in one, to a PNG or EXR image).
void addRenderCommand(CLI::App& app, int& exitCode, CommandMode mode);

/// @brief Adds `texsplat bench` (frame time, fragments, fill-rate ceiling ratio and error of
/// each splat method; table, CSV and an SVG plot).
void addBenchCommand(CLI::App& app, int& exitCode, CommandMode mode);

/// @brief Adds `texsplat view` (the interactive GLFW viewer); only in builds with
/// TEXSPLAT_WITH_VIEWER.
void addViewCommand(CLI::App& app, int& exitCode, CommandMode mode);

} // namespace texsplat::apps
