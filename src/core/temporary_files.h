// Temporary files that a writer fills before renaming them over the real
// output. A signal that ends the process (SIGTERM, SIGINT, SIGHUP) must not
// leave them behind: while a TemporaryFile is alive its path is registered,
// and the handler installed by removeTemporaryFilesOnSignal() unlinks every
// registered path before the process dies of the signal.
#pragma once

#include <string>

namespace drt {

class TemporaryFile {
public:
    explicit TemporaryFile(std::string path);
    ~TemporaryFile(); // unregisters (the writer has renamed or removed the file)
    TemporaryFile(const TemporaryFile&) = delete;
    TemporaryFile& operator=(const TemporaryFile&) = delete;
    const std::string& path() const { return path_; }

private:
    std::string path_;
    int slot_ = -1; // -1: more files at once than slots (then not cleaned up on a signal)
};

// Installs the handler for SIGTERM, SIGINT and SIGHUP (once per process):
// removes the registered temporary files (async-signal-safe), then re-raises
// the signal with its default action, so the exit status still says which
// signal ended the process.
void removeTemporaryFilesOnSignal();

// What the handler does first: unlinks every registered path, and waits (at
// most 2 s) for writers on other threads to finish the file they are writing,
// unlinking again after. Async-signal-safe.
void removeRegisteredTemporaryFiles() noexcept;

// What a handler that ends the process calls before that: from then on a
// TemporaryFile being made waits for the process to end instead of letting its
// thread make a file that the removal could miss. Async-signal-safe.
void makeNoMoreTemporaryFiles() noexcept;

} // namespace drt
