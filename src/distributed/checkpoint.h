// Checkpoints: a render in progress saved to a file, so that it can be
// resumed (drt render --resume) after an interruption, a crash or on another
// number of processes, to the same image bit for bit. The file holds the
// render's identity (render_identity.h), its tile size and its RenderState
// (render/tile_state.h: the round, which tiles are done, every pixel's state),
// in this build's byte layout; it is written to a temporary file and renamed.
#pragma once

#include "distributed/render_identity.h"
#include "render/tile_state.h"

#include <string>

namespace drt {

// Where a render writing `output` keeps its checkpoint: OUTPUT.drt-checkpoint.
std::string checkpointPathFor(const std::string& output);

struct Checkpoint {
    RenderIdentity identity;
    std::string crop; // formatWindow of the crop, "" for the whole image
    int tileSize = 0;
    std::vector<std::byte> state; // RenderState::save
};

// `state` as a checkpoint: call it with the state consistent (between tiles,
// under its scheduler's lock), then write it outside the lock.
Checkpoint makeCheckpoint(const RenderIdentity& identity, const RenderState& state);

// Writes a checkpoint file (a temporary file renamed when complete). Returns "" or the problem.
std::string writeCheckpoint(const std::string& path, const Checkpoint& checkpoint);

// Reads a checkpoint file. Returns "" or the problem (missing, not a
// checkpoint, written by another build).
std::string readCheckpoint(const std::string& path, Checkpoint& checkpoint);

// Why `checkpoint` (read from `path`) cannot continue a render of `identity`
// and `options`, or "" if it can: another drt version, scene, size, seed or
// setting, or crop window.
std::string checkpointMismatch(const Checkpoint& checkpoint, const std::string& path, const RenderIdentity& identity,
                               const RenderOptions& options);

} // namespace drt
