// POV-Ray's file input: `#fopen ID "file" read` opens a text file of values
// separated by commas (numbers, "strings" and <vectors> of 2 to 5 numbers),
// `#read (ID, Var1, Var2, ...)` declares the next values, and when nothing but
// separators is left after a #read the file is closed and ID undefined
// (`#while (defined(ID))` reads to the end). `#fclose ID` closes it early.
// Errors name the #read (file, line, column, caret) and the place in the data
// file (a note there; its lines are quoted only for a scene-like file name).
#include "lang/evaluator.h"

#include "core/source_file.h"

#include <fmt/format.h>

#include <cctype>
#include <cstdlib>

namespace drt::lang {

namespace {

bool isSeparator(char c) { return c == ',' || std::isspace(static_cast<unsigned char>(c)); }

} // namespace

struct Evaluator::DataFile {
    std::string name; // as the scene wrote it
    int fileId = -1;  // in SourceFiles, for the notes' locations
    size_t pos = 0;
    int line = 1, column = 1;

    const std::string& text(const Diagnostics& diags) const { return diags.files().text(fileId); }
};

void Evaluator::openDataFile(const Token& handle, const std::string& name, SourceLoc nameLoc) {
    const std::string path = findDataFile(name, false);
    if (path.empty()) fail(nameLoc, "cannot find the file \"" + name + "\" to read (#fopen ... read)");
    std::string text;
    if (std::string problem = readSourceFile(path, diags_.limits().includeBytes, text); !problem.empty())
        fail(nameLoc, "cannot read \"" + name + "\": " + problem);
    DataFile file;
    file.name = name;
    file.fileId = diags_.files().add(path, std::move(text), hasSceneExtension(path));
    dataFiles_[handle.text] = std::make_shared<DataFile>(std::move(file));
    Value v;
    v.kind = Value::Kind::Opaque;
    v.text = "file";
    declare(handle.text, v, false);
}

void Evaluator::closeDataFile(const std::string& handle) {
    dataFiles_.erase(handle);
    scopes_.eraseInnermost(handle);
}

// #read (ID, Var, ...), after '#read'.
void Evaluator::readDirective() {
    expectSymbol("(", "after #read");
    noExpand_ = true;
    const Token handle = expectWord("a file identifier");
    noExpand_ = false;
    const auto found = dataFiles_.find(handle.text);
    if (found == dataFiles_.end()) {
        if (lookup(handle.text)) fail(handle.loc, "'" + handle.text + "' is not a file opened for reading (#fopen ... read)");
        fail(handle.loc, "'" + handle.text + "' is not an open file: it was never opened, or closed, or read to its end");
    }
    const std::shared_ptr<DataFile> file = found->second;
    const std::string& text = file->text(diags_);
    auto skip = [&] {
        while (file->pos < text.size() && isSeparator(text[file->pos])) {
            if (text[file->pos] == '\n') ++file->line, file->column = 1;
            else ++file->column;
            ++file->pos;
        }
    };
    auto here = [&] { return SourceLoc{file->fileId, file->line, file->column}; };
    auto advance = [&](size_t n) { file->pos += n, file->column += int(n); };
    // An error at the variable being read, with a note at the data.
    auto bad = [&](const Token& var, const std::string& what, SourceLoc at) {
        report(Severity::Error, var.loc,
               fmt::format("#read of '{}' from \"{}\" (line {}, column {}): {}", var.text, file->name, at.line,
                           at.column, what));
        diags_.attachNote(at, "the data read is here");
        throw Abort{};
    };
    // A number at file->pos, or false.
    auto number = [&](double& out) {
        const char* start = text.c_str() + file->pos;
        char* end = nullptr;
        const char c = *start;
        if (!(std::isdigit(static_cast<unsigned char>(c)) || c == '-' || c == '+' || c == '.')) return false;
        out = std::strtod(start, &end);
        if (end == start) return false;
        advance(size_t(end - start));
        return true;
    };
    while (!acceptSymbol(")")) {
        expectSymbol(",", "between the identifiers of #read");
        noExpand_ = true;
        const Token var = expectWord("an identifier to read into");
        noExpand_ = false;
        skip();
        const SourceLoc at = here();
        if (file->pos >= text.size())
            bad(var, "reading past the end of the file", at);
        Value v;
        const char c = text[file->pos];
        if (c == '"') {
            std::string s;
            advance(1);
            for (;;) {
                if (file->pos >= text.size() || text[file->pos] == '\n') bad(var, "the string is not closed", at);
                const char d = text[file->pos];
                if (d == '"') break;
                if (d == '\\' && file->pos + 1 < text.size() && text[file->pos + 1] != '\n') {
                    const char e = text[file->pos + 1];
                    s += e == 'n' ? '\n' : e == 't' ? '\t' : e;
                    advance(2);
                    continue;
                }
                s += d;
                advance(1);
            }
            advance(1);
            v = Value::makeString(std::move(s));
        } else if (c == '<') {
            advance(1);
            v.kind = Value::Kind::Vector;
            v.size = 0;
            for (;;) {
                while (file->pos < text.size() && (text[file->pos] == ' ' || text[file->pos] == '\t')) advance(1);
                const SourceLoc component = here();
                double x = 0;
                if (!number(x)) bad(var, "expected a number in the vector", component);
                if (v.size == 5) bad(var, "a vector has at most 5 components", component);
                v.v[size_t(v.size++)] = x;
                while (file->pos < text.size() && (text[file->pos] == ' ' || text[file->pos] == '\t')) advance(1);
                if (file->pos < text.size() && text[file->pos] == ',') {
                    advance(1);
                    continue;
                }
                if (file->pos < text.size() && text[file->pos] == '>') {
                    advance(1);
                    break;
                }
                bad(var, "expected ',' or '>' in the vector", here());
            }
            if (v.size < 2) bad(var, "a vector needs at least 2 components", at);
        } else {
            double x = 0;
            if (!number(x)) {
                size_t n = 0;
                while (file->pos + n < text.size() && !isSeparator(text[file->pos + n]) && n < 20) ++n;
                bad(var, "expected a number, a \"string\" or a <vector>, found '" + text.substr(file->pos, n) + "'", at);
            }
            v = Value::makeFloat(x);
        }
        if (file->pos < text.size() && !isSeparator(text[file->pos]))
            bad(var, "expected ',' after the value, found '" + text.substr(file->pos, 1) + "'", here());
        declare(var.text, v, false);
    }
    skip();
    if (file->pos >= text.size()) closeDataFile(handle.text); // read to its end: defined(ID) is false now
}

} // namespace drt::lang
