// Temporary files being written, so that a process stopped by a signal can
// remove them before it exits: files are written to a temporary name and
// renamed over the real one when complete, and a signal in between would
// otherwise leave the temporary file behind.
#pragma once

#include <string>

namespace drt {

// Registers `path` while it exists (in scope); at most a few dozen at once
// (further ones are written all the same, just not registered).
class TemporaryFile {
public:
    explicit TemporaryFile(const std::string& path);
    ~TemporaryFile();
    TemporaryFile(const TemporaryFile&) = delete;
    TemporaryFile& operator=(const TemporaryFile&) = delete;

private:
    int slot_ = -1;
};

// Removes every registered temporary file. Async-signal-safe: for a signal
// handler that is about to _exit.
void removeTemporaryFiles() noexcept;

} // namespace drt
