// The subcommands of drt as library functions, so tests can call them without
// a process. Each returns the exit status and writes to the given streams.
//
// Exit statuses of render and check: 0 success, 1 scene error (parse or
// validation error, unsupported scene type, render failure), 2 usage error,
// 3 I/O error (scene file missing or unreadable, output not writable, write
// failed). A missing scene file is an I/O error (3); a missing #include inside
// a scene is a scene error (1), reported with its location.
// compare uses idiff's statuses instead (compare/compare.h: CompareStatus).
#pragma once

#include "compare/compare.h"
#include "render/render.h"

#include <iosfwd>
#include <optional>
#include <string>

namespace drt::cli {

enum ExitCode { kSuccess = 0, kSceneError = 1, kUsageError = 2, kIoError = 3 };

struct RenderCommand {
    std::string scene;
    std::string output;
    std::string varianceOutput; // "" : none; else an .exr path
    RenderOverrides overrides;
    std::optional<int> tileSize;
    bool quiet = false;
    bool progress = false; // draw a progress line (the caller checks that stderr is a terminal)
};
int runRender(const RenderCommand& command, std::ostream& out, std::ostream& err);

int runCheck(const std::string& scenePath, std::ostream& out, std::ostream& err);

struct CompareCommand {
    std::string candidate;
    std::string reference;
    std::string referenceVariance; // --variance
    std::string candidateVariance; // --candidate-variance
    std::string diffOutput;        // --diff
    std::string zmapOutput;        // --zmap
    double diffScale = 0;          // 0: the largest error
    bool json = false;
    CompareOptions options;
};
int runCompare(const CompareCommand& command, std::ostream& out, std::ostream& err);

// The metadata drt stores in rendered images (keys "drt:...").
Metadata renderMetadata(const std::string& scenePath, const RenderOptions& options, const RenderStats& stats,
                        uint64_t nonFinitePixels);

} // namespace drt::cli
