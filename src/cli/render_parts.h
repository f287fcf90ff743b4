// The pieces of `drt render` shared by cli/render_command.cpp (scene, outputs)
// and cli/render_run.cpp (the render: processes, interruption, checkpoints).
#pragma once

#include "cli/commands.h"
#include "distributed/render_identity.h"

#include <ctime>
#include <iosfwd>
#include <optional>
#include <string>

namespace drt::cli {

// The front end for `path` as a function of the frame's clock: evaluates the
// scene text as seen at that clock (front end, then the files it names).
SceneEvaluator sceneEvaluator(const std::string& path, const PovCliOptions& pov, const RenderSettings& overrides);

// Loads a scene at one frame's clock, moving over its shutter (animation.h
// evaluateFrame), printing every diagnostic and the scene's warnings
// (render/scene_warnings.h) to `err`. Returns kSuccess and sets `scene` (and
// `sceneSha1`, the hash of the text read: render/provenance.h), or the exit
// status to stop with.
int loadScene(const std::string& path, std::ostream& err, std::optional<Scene>& scene, const PovCliOptions& pov = {},
              const RenderSettings& overrides = {}, std::string* sceneSha1 = nullptr, const FrameClock& frame = {},
              const FrameOptions& frameOptions = {}, FrameReport* report = nullptr);

// What a render's files record besides its identity (render/provenance.h).
struct RunRecord {
    std::string sceneSha1; // of the scene text and its includes
    std::string filter;    // the reconstruction filter's name
    std::time_t started = 0;
};

// The metadata of a render's image files: provenance (version, scene hash,
// size, seed, spp, sampler, filter, effects), the identity crops and
// checkpoints are matched by, and, unless --reproducible, the run (command
// line, threads, start time, seconds).
Metadata renderMetadata(const RenderCommand& command, const RenderOptions& options, const RenderIdentity& identity,
                        const RunRecord& record, const RenderStats& stats, uint64_t nonFinitePixels);

// ".png" for "a/b.PNG".
std::string lowerExtension(const std::string& path);

// Checks, before rendering, that every output can be written. Returns kSuccess or the status.
int checkOutputs(const RenderCommand& command, std::ostream& err);

// Writes the colour, variance and samples-per-pixel images (NaN/Inf cleared:
// `nonFinitePixels` counts them) and removes a stale checkpoint. Returns kSuccess or the status.
int writeOutputs(const RenderCommand& command, const RenderOptions& options, const RenderIdentity& identity,
                 const RunRecord& record, RenderResult& result, uint64_t& nonFinitePixels, std::ostream& err);

// `--stats FILE`: the summary line's figures as JSON, for benchmark scripts.
// load = parse + the files the scene names; render = build + trace; total =
// the whole command after start-up (load, render, writing every output).
struct RenderTimes {
    double loadSeconds = 0, renderSeconds = 0, totalSeconds = 0;
};
std::string writeStatsJson(const RenderCommand& command, const RenderOptions& options, const RenderResult& result,
                           const RenderTimes& times);

// The one-line summary after a render.
void printSummary(const RenderCommand& command, const RenderOptions& options, const RenderResult& result,
                  uint64_t nonFinitePixels, double seconds, std::ostream& err);

} // namespace drt::cli
