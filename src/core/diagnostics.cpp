#include "core/diagnostics.h"

#include <algorithm>
#include <fmt/format.h>
#include <string_view>
#include <vector>

namespace drt {

int SourceFiles::add(std::string path, std::string text, bool quotable) {
    File f{std::move(path), std::move(text), quotable, {0}};
    for (size_t at = f.text.find('\n'); at != std::string::npos; at = f.text.find('\n', at + 1))
        f.lineStarts.push_back(at + 1);
    files_.push_back(std::move(f));
    return static_cast<int>(files_.size()) - 1;
}

std::string SourceFiles::line(int id, int line) const {
    const File& f = files_.at(id);
    const std::string& t = f.text;
    if (line < 1 || size_t(line) > f.lineStarts.size()) return {};
    const size_t start = f.lineStarts[size_t(line) - 1];
    if (start > t.size()) return {};
    size_t end = t.find('\n', start);
    std::string s = t.substr(start, end == std::string::npos ? std::string::npos : end - start);
    if (!s.empty() && s.back() == '\r') s.pop_back();
    return s;
}

void Diagnostics::report(Severity s, SourceLoc loc, std::string message, std::vector<SourceLoc> includedFrom) {
    if (s == Severity::Warning && warningsAsErrors_) s = Severity::Error;
    // Past the limit only the count is kept; a note goes where the error or
    // warning it explains went.
    if (s == Severity::Error) lastDropped_ = ++errorCount_ > limits_.errors && ++droppedErrors_;
    if (s == Severity::Warning) lastDropped_ = ++warningCount_ > limits_.errors && ++droppedWarnings_;
    if (lastDropped_) return;
    diagnostics_.push_back({s, loc, std::move(message), std::move(includedFrom), {}});
}

void Diagnostics::attachNote(SourceLoc loc, std::string message, std::vector<SourceLoc> includedFrom) {
    if (diagnostics_.empty()) {
        report(Severity::Note, loc, std::move(message), std::move(includedFrom));
        return;
    }
    diagnostics_.back().notes.push_back({Severity::Note, loc, std::move(message), std::move(includedFrom), {}});
}

static const char* severityName(Severity s) {
    switch (s) {
    case Severity::Note: return "note";
    case Severity::Warning: return "warning";
    case Severity::Error: return "error";
    }
    return "error";
}

std::string Diagnostics::format(const Diagnostic& d) const {
    std::string out;
    for (auto it = d.includedFrom.rbegin(); it != d.includedFrom.rend(); ++it)
        if (it->valid()) out += fmt::format("In file included from {}:{}:\n", files_->path(it->file), it->line);
    if (!d.loc.valid()) {
        out += fmt::format("drt: {}: {}\n", severityName(d.severity), d.message);
        for (const Diagnostic& n : d.notes) out += format(n);
        return out;
    }
    out += fmt::format("{}:{}:{}: {}: {}\n", files_->path(d.loc.file), d.loc.line, d.loc.column,
                       severityName(d.severity), d.message);
    if (!files_->quotable(d.loc.file)) return out;
    std::string src = files_->line(d.loc.file, d.loc.line);
    // A long line is quoted as a window of quotedLine characters around the
    // column, its cut ends marked "...".
    size_t column = size_t(std::max(d.loc.column, 1)) - 1;
    const size_t width = size_t(std::max<int64_t>(limits_.quotedLine, 8));
    if (src.size() > width) {
        const size_t first = column > width / 2 ? std::min(column - width / 2, src.size() - width) : 0;
        const bool cutLeft = first > 0, cutRight = first + width < src.size();
        src = (cutLeft ? "..." : "") + src.substr(first, width) + (cutRight ? "..." : "");
        column = column - first + (cutLeft ? 3 : 0);
    }
    // Tabs keep their width in the caret line so the caret sits under the spot.
    std::string caret;
    for (size_t i = 0; i < column && i < src.size(); ++i)
        caret += (src[i] == '\t') ? '\t' : ' ';
    out += fmt::format("  {}\n  {}^\n", src, caret);
    for (const Diagnostic& n : d.notes) out += format(n);
    return out;
}

std::string Diagnostics::formatAll() const {
    std::string out;
    for (const auto& d : diagnostics_) out += format(d);
    const auto more = [&](int count, const char* kind) {
        if (count > 0)
            out += fmt::format("drt: {} more {}{} not shown ({})\n", count, kind, count == 1 ? "" : "s",
                               limitHint(limits_, &Limits::errors));
    };
    more(droppedErrors_, "error");
    more(droppedWarnings_, "warning");
    return out;
}

// The Levenshtein distance of a and b when it is below `limit`, else `limit`.
// Words whose lengths alone differ by `limit` are never compared, and a row of
// the table whose every entry has reached `limit` ends the comparison: a
// misspelt word is compared with hundreds of keywords, and a fuzzer's or a
// binary file's "words" can be thousands of characters long.
static size_t editDistanceBelow(std::string_view a, std::string_view b, size_t limit, std::vector<size_t>& row) {
    if (a.size() > b.size()) std::swap(a, b);
    if (b.size() - a.size() >= limit) return limit;
    row.resize(a.size() + 1);
    for (size_t j = 0; j <= a.size(); ++j) row[j] = j;
    for (size_t i = 1; i <= b.size(); ++i) {
        size_t diagonal = row[0];
        row[0] = i;
        size_t smallest = row[0];
        for (size_t j = 1; j <= a.size(); ++j) {
            const size_t above = row[j];
            row[j] = std::min({above + 1, row[j - 1] + 1, diagonal + (b[i - 1] == a[j - 1] ? 0 : 1)});
            diagonal = above;
            smallest = std::min(smallest, row[j]);
        }
        if (smallest >= limit) return limit;
    }
    return std::min(row[a.size()], limit);
}

// Whether k is word with two neighbouring characters swapped.
static bool isNeighbourSwap(std::string_view word, std::string_view k) {
    if (word.size() != k.size()) return false;
    size_t i = 0;
    while (i < word.size() && word[i] == k[i]) ++i;
    if (i + 1 >= word.size()) return false;
    return word[i] == k[i + 1] && word[i + 1] == k[i] && word.substr(i + 2) == k.substr(i + 2);
}

std::string nearestWord(const std::string& word, const std::vector<std::string>& known) {
    std::vector<size_t> row;
    const std::string* best = nullptr;
    size_t bestDistance = std::max<size_t>(1, word.size() / 3) + 1;
    for (const auto& k : known) {
        const size_t d = editDistanceBelow(word, k, bestDistance, row);
        if (d < bestDistance) {
            bestDistance = d;
            best = &k;
        }
    }
    if (best && !best->empty()) return *best;
    // Two swapped neighbours ("widht") cost 2 edits: too many for a short word
    // by distance alone, but a typical typo.
    for (const std::string& k : known)
        if (isNeighbourSwap(word, k)) return k;
    // A cut-short keyword ("max_trace" for "max_trace_level").
    if (word.size() >= 4)
        for (const std::string& k : known)
            if (k.compare(0, word.size(), word) == 0) return k;
    return "";
}

} // namespace drt
