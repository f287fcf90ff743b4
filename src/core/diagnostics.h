// The one diagnostics type: every error and warning carries a source location
// (file, line, column) and prints as
//   file:line:col: error: message
//     source line
//          ^
#pragma once

#include "core/limits.h"

#include <memory>
#include <string>
#include <vector>

namespace drt {

// Owns the text of every file read, so that diagnostics can quote source lines.
class SourceFiles {
public:
    // Returns a stable id for a file's text. The lines of a file that is not
    // `quotable` (a file whose name says it is no scene, e.g. an #include of
    // /etc/passwd) are never printed under its errors.
    int add(std::string path, std::string text, bool quotable = true);
    bool quotable(int id) const { return files_.at(id).quotable; }
    const std::string& path(int id) const { return files_.at(id).path; }
    const std::string& text(int id) const { return files_.at(id).text; }
    // The text of 1-based line `line` of file `id`, without its newline.
    std::string line(int id, int line) const;
    int count() const { return static_cast<int>(files_.size()); }

private:
    struct File {
        std::string path;
        std::string text;
        bool quotable = true;
        std::vector<size_t> lineStarts; // offset of each line's first byte: line() is called per #declare
    };
    std::vector<File> files_;
};

struct SourceLoc {
    int file = -1; // id in SourceFiles; -1: no location
    int line = 0;  // 1-based
    int column = 0; // 1-based, in bytes
    bool valid() const { return file >= 0; }
};

enum class Severity { Note, Warning, Error };

struct Diagnostic {
    Severity severity = Severity::Error;
    SourceLoc loc;
    std::string message;
    // "included from" chain, innermost first.
    std::vector<SourceLoc> includedFrom;
    // Notes that belong to this diagnostic ("the 'sphere' opened here is not
    // closed"), printed right after it.
    std::vector<Diagnostic> notes;
};

class Diagnostics {
public:
    explicit Diagnostics(std::shared_ptr<SourceFiles> files = std::make_shared<SourceFiles>())
        : files_(std::move(files)), limits_(defaultLimits()) {}

    void error(SourceLoc loc, std::string message) { report(Severity::Error, loc, std::move(message)); }
    void warning(SourceLoc loc, std::string message) { report(Severity::Warning, loc, std::move(message)); }
    void note(SourceLoc loc, std::string message) { report(Severity::Note, loc, std::move(message)); }
    void report(Severity s, SourceLoc loc, std::string message, std::vector<SourceLoc> includedFrom = {});
    // Adds a note to the last diagnostic reported (a plain note when there is none).
    void attachNote(SourceLoc loc, std::string message, std::vector<SourceLoc> includedFrom = {});

    // Warnings become errors (POV front end's --strict).
    void setWarningsAsErrors(bool on) { warningsAsErrors_ = on; }

    // The limits the front ends work within (core/limits.h). Beyond
    // Limits::errors errors (or warnings) only the count is kept, and
    // formatAll says how many more there were.
    const Limits& limits() const { return limits_; }
    void setLimits(const Limits& limits) { limits_ = limits; }

    bool hasErrors() const { return errorCount_ > 0; }
    int errorCount() const { return errorCount_; }
    int warningCount() const { return warningCount_; }
    const std::vector<Diagnostic>& all() const { return diagnostics_; }

    SourceFiles& files() { return *files_; }
    const SourceFiles& files() const { return *files_; }
    std::shared_ptr<SourceFiles> sharedFiles() const { return files_; }

    // Renders one diagnostic with its source line (at most Limits::quotedLine
    // characters of it, around the column) and a caret under the column.
    std::string format(const Diagnostic& d) const;
    // Renders all of them, in order, then "N more errors" if some were dropped.
    std::string formatAll() const;

private:
    std::shared_ptr<SourceFiles> files_;
    std::vector<Diagnostic> diagnostics_;
    int errorCount_ = 0;
    int warningCount_ = 0;
    int droppedErrors_ = 0;
    int droppedWarnings_ = 0;
    bool lastDropped_ = false;
    bool warningsAsErrors_ = false;
    Limits limits_;
};

// The known word nearest to `word` by edit distance (or by one swap of
// neighbouring letters, or as a cut-short prefix), or "" if none is close
// enough to be a plausible typo. Used for "did you mean ...?" suggestions.
std::string nearestWord(const std::string& word, const std::vector<std::string>& known);

} // namespace drt
