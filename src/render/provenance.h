// Provenance: what an output image was made from, stored in its metadata (EXR
// header attributes, PNG text chunks, and a one-line summary in
// ImageDescription for formats that keep nothing else), so a file can be traced
// back to the scene text, settings and run that produced it.
//
// Entries come in two kinds:
//   identity  the same for every run of the same scene text, settings and seed
//             (version, scene hash, seed, spp, sampler, filter, crop window...);
//   run       what changes from run to run (command line, threads, start time,
//             seconds, resume details...).
// A reproducible file keeps the identity entries only, so rendering the same
// scene with the same seed twice gives byte-identical files whatever the
// thread count, time or output path (`drt render --reproducible`, and always
// for the goldens of `drt test`).
#pragma once

#include "core/diagnostics.h"
#include "image/image.h"
#include "render/render.h"

#include <ctime>
#include <string>
#include <string_view>

namespace drt {

class Provenance {
  public:
    // Adds (or replaces) an entry; keys are conventionally "drt:name".
    void identify(const std::string& key, const std::string& value);
    void record(const std::string& key, const std::string& value);

    const Metadata& identity() const { return identity_; }
    const Metadata& run() const { return run_; }

    // The metadata to write: identity then run entries, "Software", and
    // "DateTime" (the run's start, or empty when reproducible: OpenEXR would
    // otherwise stamp the time of writing).
    Metadata metadata(bool reproducible) const;

  private:
    Metadata identity_, run_;
};

// The identity entries every render has: drt:version, drt:scene (file name),
// drt:scene_sha1 (sceneTextSha1), drt:seed, drt:spp (or the adaptive target), drt:sampler,
// drt:filter, drt:size.
Provenance renderProvenance(const std::string& scenePath, const std::string& sceneSha1,
                            const RenderOptions& options, const std::string& filter);

// Adds the run entries of a finished render: drt:threads (as asked, 0 = all
// cores, and the number used), drt:started (local time, ISO 8601),
// drt:render_seconds, and drt:command_line when `commandLine` is not empty.
void recordRun(Provenance& provenance, const RenderOptions& options, const RenderStats& stats,
               const std::string& commandLine, std::time_t started);

// SHA-1 (hex) of the text of every file a front end read, in reading order
// (the scene, then its includes), each preceded by its length in bytes in
// decimal and a newline. For a scene without includes it is what
// `{ stat -c %s scene.drt; cat scene.drt; } | sha1sum` prints.
std::string sceneTextSha1(const SourceFiles& files);
std::string sha1Hex(std::string_view bytes);

// argv as one line a POSIX shell reads back to the same words (arguments with
// spaces or quotes are single-quoted).
std::string shellCommandLine(int argc, const char* const* argv);

} // namespace drt
