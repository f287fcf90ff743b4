// Diagnostics of the evaluator: errors with their include chain, "did you
// mean", where a misplaced keyword belongs, values with where they came from,
// and the block a missing '}' leaves open.
#include "lang/evaluator.h"

#include <fmt/format.h>

#include <algorithm>

namespace drt::lang {

namespace {
constexpr int kMaxErrors = 100; // then the evaluator stops
} // namespace

std::vector<SourceLoc> Evaluator::includeChain(size_t frameCount) const {
    std::vector<SourceLoc> chain;
    for (size_t i = std::min(frameCount, frames_.size()); i-- > 0;)
        if (!frames_[i].isMacro && frames_[i].includedFrom.valid()) chain.push_back(frames_[i].includedFrom);
    return chain;
}

void Evaluator::report(Severity severity, SourceLoc loc, const std::string& message) {
    if (severity == Severity::Warning && options_.strict) severity = Severity::Error;
    diags_.report(severity, loc, message, includeChain());
    // An included file that is no scene (an #include of /etc/passwd) is read
    // no further after its first error, so its contents do not leak into the
    // messages token by token.
    if (severity == Severity::Error && loc.valid() && !diags_.files().quotable(loc.file)) abandonedFile_ = loc.file;
    // An error inside a macro body names the calls that led there, innermost first.
    if (severity == Severity::Error)
        for (auto it = frames_.rbegin(); it != frames_.rend(); ++it)
            if (it->isMacro && it->includedFrom.valid())
                diags_.attachNote(it->includedFrom, "in macro '" + it->macroName + "' called here");
    if (severity == Severity::Error && ++errorsSeen_ == kMaxErrors) {
        diags_.report(Severity::Note, loc, fmt::format("{} errors: stopping here", kMaxErrors), includeChain());
        frames_.clear();
        throw Abort{};
    }
}

void Evaluator::fail(SourceLoc loc, const std::string& message) {
    report(Severity::Error, loc, message);
    throw Abort{};
}

void Evaluator::failLimit(SourceLoc loc, const std::string& message) {
    limitReached_ = true;
    fail(loc, message);
}

void Evaluator::failExpected(const Token& got, const std::string& what) {
    fail(got.loc, "expected " + what + ", found " + describe(got));
}

void Evaluator::error(SourceLoc loc, const std::string& message) {
    report(Severity::Error, loc, message);
    if (!scene().recoverAfterErrors) throw Abort{};
}

void Evaluator::refuse(SourceLoc loc, const std::string& message, bool always) {
    if (always || syntax().strictValues) error(loc, message);
}

void Evaluator::warn(SourceLoc loc, const std::string& message) { report(Severity::Warning, loc, message); }

namespace {

// Defers a diagnostic raised inside a #declare to the identifier's first use.
bool deferred(std::vector<PendingWarning>* pending, const std::string& kind, Severity severity, SourceLoc loc,
              const std::string& message, const std::vector<SourceLoc>& chain) {
    if (!pending) return false;
    for (const PendingWarning& p : *pending)
        if (p.kind == kind) return true;
    pending->push_back({kind, severity, loc, message, chain});
    return true;
}

} // namespace

void Evaluator::warnOnce(const std::string& kind, SourceLoc loc, const std::string& message) {
    if (deferred(pending_, kind, Severity::Warning, loc, message, includeChain())) return;
    if (!warned_.insert(kind).second) return;
    report(Severity::Warning, loc, message);
}

void Evaluator::note(SourceLoc loc, const std::string& message) { report(Severity::Note, loc, message); }

void Evaluator::noteOnce(const std::string& kind, SourceLoc loc, const std::string& message) {
    if (deferred(pending_, kind, Severity::Note, loc, message, includeChain())) return;
    if (!warned_.insert(kind).second) return;
    report(Severity::Note, loc, message);
}

void Evaluator::unsupported(const std::string& kind, SourceLoc loc, const std::string& message) {
    if (syntax().unsupportedIsError) fail(loc, message);
    warnOnce(kind, loc, message);
}

void Evaluator::failUnknownIn(const Token& word, const std::vector<std::string>& known, const char* kind) {
    std::string message = std::string("unknown ") + kind + " '" + word.text + "'";
    const std::string suggestion = nearestWord(word.text, known);
    if (!suggestion.empty()) message += "; did you mean '" + suggestion + "'?";
    fail(word.loc, message);
}

void Evaluator::failUnknown(const Token& word, Block block, const std::vector<std::string>& extra, const char* kind) {
    const std::vector<Block> homes = homesOf(word.text, block);
    if (!homes.empty() && block != Block::Statement) {
        std::string where;
        for (size_t i = 0; i < homes.size(); ++i)
            where += (i == 0 ? "" : i + 1 == homes.size() ? " or " : ", ") + std::string("'") + blockName(homes[i]) + "'";
        fail(word.loc, "'" + word.text + "' goes in " + where + ", not '" + blockName(block) + "'");
    }
    std::vector<std::string> known = blockKeywords(block);
    known.insert(known.end(), extra.begin(), extra.end());
    failUnknownIn(word, known, kind);
}

std::string Evaluator::got(double value) const {
    std::string text = fmt::format(", got {}", value);
    if (lastOrigin_) text += " (" + lastOrigin_->name + " = " + lastOrigin_->text + ")";
    return text;
}

std::string Evaluator::got(const Vec3& value) const {
    std::string text = fmt::format(", got <{}, {}, {}>", value.x, value.y, value.z);
    if (lastOrigin_) text += " (" + lastOrigin_->name + " = " + lastOrigin_->text + ")";
    return text;
}

Evaluator::BlockScope::BlockScope(Evaluator& ev, const std::string& keyword, SourceLoc loc) : e(ev) {
    e.openBlocks_.push_back({keyword, loc});
}

Evaluator::BlockScope::~BlockScope() {
    if (!e.openBlocks_.empty()) e.openBlocks_.pop_back();
}

void Evaluator::failInBlock(const Token& got, const std::string& what) {
    report(Severity::Error, got.loc, "expected " + what + ", found " + describe(got));
    // The end of the file, or a statement that cannot be inside the block: its '}' is missing.
    bool missingBrace = got.kind == TokenKind::EndOfFile;
    if (got.kind == TokenKind::Word && !lookup(got.text)) {
        const auto& top = blockKeywords(Block::Statement);
        missingBrace = (std::find(top.begin(), top.end(), got.text) != top.end() && got.text != "media") ||
                       isObjectWord(got);
    }
    if (missingBrace && !openBlocks_.empty()) {
        const OpenBlock& block = openBlocks_.back();
        diags_.attachNote(block.loc, "the '" + block.keyword + "' opened here is not closed", includeChain());
        // Recovery resumes at the statement the missing '}' ran into.
        if (got.kind != TokenKind::EndOfFile) pushBack(got);
    }
    throw Abort{};
}

} // namespace drt::lang
