#include "lang/lexer.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <stdexcept>
#include <string>

namespace drt::lang {

std::string describe(const Token& token) {
    switch (token.kind) {
    case TokenKind::EndOfFile: return "end of file";
    case TokenKind::String: return "string \"" + token.text + "\"";
    case TokenKind::Directive: return "'#" + token.text + "'";
    case TokenKind::Error: return "invalid token";
    default: return "'" + token.text + "'";
    }
}

namespace {

bool isDigit(char c) { return c >= '0' && c <= '9'; }
bool isWordStart(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool isWordChar(char c) { return isWordStart(c) || isDigit(c); }

// The value of a number literal's text (digits, '.', exponent): correctly
// rounded, without the locale (std::from_chars); strtod only for what it
// refuses (a value beyond double's range, which strtod makes inf or 0).
double numberValue(const char* first, const char* last) {
    double value = 0;
    const auto [end, ec] = std::from_chars(first, last, value, std::chars_format::general);
    if (ec == std::errc() && end == last) return value;
    const std::string copy(first, last);
    return std::strtod(copy.c_str(), nullptr);
}

} // namespace

class TokenStream::Scanner {
public:
    Scanner(int fileId, bool strict) : fileId_(fileId), strict_(strict) {}

    // The text is looked up again before each use: the file table may have moved it.
    void bind(const std::string& text) {
        data_ = text.data();
        size_ = text.size();
    }
    Mark mark() const { return {pos_, line_, column_}; }
    void reset(Mark m) { pos_ = m.pos, line_ = m.line, column_ = m.column; }

    Token next() {
        for (;;) { // POV-Ray reads a '#' with no directive name after it as nothing: the loop skips it
            SourceLoc commentStart;
            const std::string commentError = skipBlanksAndComments(commentStart);
            if (!commentError.empty()) {
                pos_ = size_;
                return make(TokenKind::Error, commentStart, commentError);
            }
            const SourceLoc start = here();
            if (atEnd()) return make(TokenKind::EndOfFile, start, "");
            const char c = peek();
            if (isDigit(c) || (c == '.' && isDigit(peek(1)))) return number(start);
            if (isWordStart(c)) return word(start, TokenKind::Word);
            if (c == '"') return string(start);
            if (c == '#') {
                advance();
                while (peek() == ' ' || peek() == '\t') advance(); // `# declare` is allowed
                if (!isWordStart(peek())) {
                    if (!strict_) continue;
                    return make(TokenKind::Error, start, "expected a directive name after '#'");
                }
                return word(start, TokenKind::Directive);
            }
            advance();
            auto two = [&](char second, const char* both, const char* one) {
                if (peek() == second) {
                    advance();
                    return make(TokenKind::Symbol, start, both);
                }
                return make(TokenKind::Symbol, start, one);
            };
            switch (c) {
            case '<': return two('=', "<=", "<");
            case '>': return two('=', ">=", ">");
            case '!': return two('=', "!=", "!");
            case '{': case '}': case '(': case ')': case '[': case ']': case ',': case ';': case '+': case '-':
            case '*': case '/': case '=': case '?': case ':': case '&': case '|': case '.': case '^':
                return make(TokenKind::Symbol, start, std::string(1, c));
            default: {
                const bool printable = std::isprint(static_cast<unsigned char>(c));
                return make(TokenKind::Error, start,
                            printable ? std::string("unexpected character '") + c + "'"
                                      : "unexpected byte " + std::to_string(static_cast<unsigned char>(c)));
            }
            }
        }
    }

    // ------------------------------------------------ scanning without tokens

    // Skips blanks and comments; false (nothing skipped) at a comment that never ends.
    bool blanks() {
        const Mark m = mark();
        SourceLoc ignored;
        if (skipBlanksAndComments(ignored).empty()) return true;
        reset(m);
        return false;
    }

    bool symbol(char c) {
        const Mark m = mark();
        if (blanks() && peek() == c && !((c == '<' || c == '>' || c == '!') && peek(1) == '=')) {
            advance();
            return true;
        }
        reset(m);
        return false;
    }

    bool word(const char* w) {
        const Mark m = mark();
        if (blanks()) {
            size_t n = 0;
            while (w[n] && peek(n) == w[n]) ++n;
            if (!w[n] && !isWordChar(peek(n))) {
                pos_ += n, column_ += int(n);
                return true;
            }
        }
        reset(m);
        return false;
    }

    char peekChar() {
        const Mark m = mark();
        const char c = blanks() ? peek() : '\0';
        reset(m);
        return c;
    }

    SourceLoc location() {
        blanks();
        return here();
    }

    // An optionally signed number literal (the sign may be followed by blanks).
    bool signedNumber(double& out) {
        bool negative = false;
        if (peek() == '-' || peek() == '+') {
            negative = peek() == '-';
            advance();
            if (!blanks()) return false;
        }
        return unsignedNumber(out) && ((out = negative ? -out : out), true);
    }

    bool unsignedNumber(double& out) {
        if (!(isDigit(peek()) || (peek() == '.' && isDigit(peek(1))))) return false;
        std::string error;
        return scanNumber(out, error);
    }

    bool vector(LiteralVector& out) {
        const Mark m = mark();
        if (vectorBody(out)) return true;
        reset(m);
        return false;
    }

    bool number(double& out, SourceLoc& loc) {
        const Mark m = mark();
        if (blanks()) {
            loc = here();
            if (unsignedNumber(out) && blanks() && (peek() == ',' || peek() == '}')) return true;
        }
        reset(m);
        return false;
    }

private:
    bool vectorBody(LiteralVector& out) {
        if (!blanks() || peek() != '<' || peek(1) == '=') return false;
        out.loc = here();
        advance();
        out.size = 0;
        for (;;) {
            double value = 0;
            if (out.size == 5 || !blanks() || !signedNumber(value) || !blanks()) return false;
            out.v[out.size++] = value;
            if (peek() == ',') {
                advance();
                continue;
            }
            if (peek() != '>') return false;
            out.end = here();
            advance();
            break;
        }
        if (out.size < 2) return false;
        // Nothing after it may continue the expression (`* 2`, `.x`, `+ <...>`).
        if (!blanks()) return false;
        const char c = peek();
        return c == ',' || c == '}' || (c == '<' && peek(1) != '=') || c == '#' || isWordStart(c);
    }

    char peek(size_t ahead = 0) const { return pos_ + ahead < size_ ? data_[pos_ + ahead] : '\0'; }
    bool atEnd() const { return pos_ >= size_; }
    SourceLoc here() const { return {fileId_, line_, column_}; }
    char advance() {
        const char c = data_[pos_++];
        if (c == '\n') {
            ++line_;
            column_ = 1;
        } else {
            ++column_;
        }
        return c;
    }
    Token make(TokenKind kind, SourceLoc loc, std::string text) const {
        Token t;
        t.kind = kind;
        t.loc = loc;
        t.text = std::move(text);
        return t;
    }

    // Returns an error message for an unterminated block comment, or "".
    std::string skipBlanksAndComments(SourceLoc& commentStart) {
        for (;;) {
            const char c = peek();
            if (c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v') {
                ++pos_, ++column_;
            } else if (c == '\n') {
                ++pos_, ++line_, column_ = 1;
            } else if (c == '/' && peek(1) == '/') {
                while (!atEnd() && peek() != '\n') advance();
            } else if (c == '/' && peek(1) == '*') {
                // Block comments nest, as in POV-Ray.
                commentStart = here();
                advance();
                advance();
                int depth = 1;
                while (depth > 0) {
                    if (atEnd()) return "unterminated comment";
                    if (peek() == '/' && peek(1) == '*') {
                        advance(), advance(), ++depth;
                    } else if (peek() == '*' && peek(1) == '/') {
                        advance(), advance(), --depth;
                    } else {
                        advance();
                    }
                }
            } else if (pos_ == 0 && static_cast<unsigned char>(c) == 0xEF &&
                       static_cast<unsigned char>(peek(1)) == 0xBB && static_cast<unsigned char>(peek(2)) == 0xBF) {
                pos_ += 3; // a UTF-8 byte-order mark starting the file: not text, no column
            } else {
                return "";
            }
        }
    }

    // number = digits ["." digits] [exponent] | "." digits [exponent];
    // exponent = ("e" | "E") ["+" | "-"] digits. Scans one at pos_ (a digit,
    // or '.' and a digit): its value, or false and the message of the error
    // token it makes. A number has no newline, so only the column moves.
    bool scanNumber(double& value, std::string& error) {
        const size_t begin = pos_;
        size_t p = pos_;
        const auto at = [&](size_t i) { return i < size_ ? data_[i] : '\0'; };
        while (isDigit(at(p))) ++p;
        // `1.x`: POV-Ray reads the number 1 and the component `.x`.
        if (at(p) == '.' && !isWordStart(at(p + 1))) {
            ++p;
            while (isDigit(at(p))) ++p;
        }
        if (at(p) == 'e' || at(p) == 'E') {
            const size_t ahead = (at(p + 1) == '+' || at(p + 1) == '-') ? 2 : 1;
            if (isDigit(at(p + ahead))) {
                p += ahead;
                while (isDigit(at(p))) ++p;
            } else if (strict_) {
                p += ahead;
                column_ += int(p - pos_), pos_ = p;
                error = "malformed number: exponent has no digits";
                return false;
            }
        }
        column_ += int(p - pos_), pos_ = p;
        if (strict_ && isWordStart(peek())) {
            error = "malformed number '" + std::string(data_ + begin, pos_ - begin) + std::string(1, peek()) + "'";
            return false;
        }
        value = numberValue(data_ + begin, data_ + pos_);
        if (!std::isfinite(value)) {
            error = "number '" + std::string(data_ + begin, pos_ - begin) + "' is out of range";
            return false;
        }
        return true;
    }

    Token number(SourceLoc start) {
        double value = 0;
        std::string error;
        const size_t begin = pos_;
        if (!scanNumber(value, error)) return make(TokenKind::Error, start, std::move(error));
        Token t = make(TokenKind::Number, start, std::string(data_ + begin, pos_ - begin));
        t.number = value;
        return t;
    }

    Token string(SourceLoc start) {
        advance(); // opening quote
        std::string value;
        while (peek() != '"') {
            if (atEnd() || peek() == '\n') return make(TokenKind::Error, start, "unterminated string");
            const SourceLoc escapeLoc = here();
            const char c = advance();
            if (c != '\\') {
                value += c;
                continue;
            }
            if (atEnd()) return make(TokenKind::Error, start, "unterminated string");
            switch (const char e = advance()) {
            case '"': value += '"'; break;
            case '\\': value += '\\'; break;
            case '\'': value += '\''; break;
            case 'n': value += '\n'; break;
            case 't': value += '\t'; break;
            case 'r': value += '\r'; break;
            case 'a': value += '\a'; break;
            case 'b': value += '\b'; break;
            case 'f': value += '\f'; break;
            case 'v': value += '\v'; break;
            case '0': value += '\0'; break;
            default:
                if (!strict_) {
                    value += e; // POV-Ray keeps the character
                    break;
                }
                // Skip to the closing quote so the rest of the line lexes normally.
                while (!atEnd() && peek() != '"' && peek() != '\n') advance();
                if (peek() == '"') advance();
                return make(TokenKind::Error, escapeLoc, std::string("unknown escape '\\") + e + "' in string");
            }
        }
        advance(); // closing quote
        return make(TokenKind::String, start, value);
    }

    Token word(SourceLoc start, TokenKind kind) {
        const size_t begin = pos_;
        while (isWordChar(peek())) ++pos_;
        column_ += int(pos_ - begin);
        return make(kind, start, std::string(data_ + begin, pos_ - begin));
    }

    const char* data_ = nullptr;
    size_t size_ = 0;
    int fileId_;
    bool strict_;
    size_t pos_ = 0;
    int line_ = 1;
    int column_ = 1;
};

TokenStream::TokenStream(const SourceFiles& files, int fileId, bool strict)
    : files_(&files), fileId_(fileId), scanner_(std::make_unique<Scanner>(fileId, strict)) {}

TokenStream::TokenStream(std::string text, int fileId, bool strict)
    : own_(std::move(text)), fileId_(fileId), scanner_(std::make_unique<Scanner>(fileId, strict)) {}

TokenStream::~TokenStream() = default;

const std::string& TokenStream::text() const { return files_ ? files_->text(fileId_) : own_; }

void TokenStream::lexOne() const {
    if ((count_ >> kBlockBits) == blocks_.size()) blocks_.push_back(std::make_unique<Token[]>(kBlock));
    scanner_->bind(text());
    starts_[count_ % kRing] = scanner_->mark();
    Token& t = blocks_[count_ >> kBlockBits][count_ & (kBlock - 1)];
    t = scanner_->next();
    ended_ = t.kind == TokenKind::EndOfFile;
    ++count_;
}

const Token& TokenStream::operator[](size_t i) const {
    while (i >= count_ && !ended_) lexOne();
    if (i >= count_) i = count_ - 1;
    const auto& block = blocks_[i >> kBlockBits];
    if (!block) [[unlikely]]
        throw std::logic_error("internal: token " + std::to_string(i) + " was read after the reader released it");
    return block[i & (kBlock - 1)];
}

void TokenStream::release(size_t before) {
    // The block holding the last token made stays: lexOne() writes into it.
    const size_t end = std::min(before, count_ > 0 ? count_ - 1 : 0) >> kBlockBits;
    for (size_t b = releasedBefore_; b < end; ++b) {
        const size_t first = b << kBlockBits, last = first + kBlock;
        const bool held = std::any_of(kept_.begin(), kept_.end(),
                                      [&](const auto& r) { return r.first < last && first < r.second; });
        if (held || !blocks_[b]) continue;
        blocks_[b].reset();
        ++releasedBlocks_;
    }
    releasedBefore_ = std::max(releasedBefore_, end);
}

void TokenStream::keep(size_t first, size_t last) {
    if (first < last) kept_.emplace_back(first, last);
}

bool TokenStream::rewind(size_t i) {
    if (i > count_ || count_ - i > kRing || !available(i)) return false;
    if (i == count_) return true;
    scanner_->reset(starts_[i % kRing]);
    for (size_t j = i; j < count_; ++j) blocks_[j >> kBlockBits][j & (kBlock - 1)] = Token{};
    count_ = i;
    ended_ = false;
    return true;
}

TokenStream::Mark TokenStream::mark() const { return scanner_->mark(); }
void TokenStream::reset(Mark m) { scanner_->reset(m); }

bool TokenStream::symbol(char c) {
    if (ended_) return false;
    scanner_->bind(text());
    return scanner_->symbol(c);
}

bool TokenStream::word(const char* w) {
    if (ended_) return false;
    scanner_->bind(text());
    return scanner_->word(w);
}

char TokenStream::peekChar() {
    if (ended_) return '\0';
    scanner_->bind(text());
    return scanner_->peekChar();
}

bool TokenStream::vector(LiteralVector& out) {
    if (ended_) return false;
    scanner_->bind(text());
    return scanner_->vector(out);
}

bool TokenStream::item(LiteralVector& out) {
    const Mark start = mark();
    symbol(',');
    if (vector(out)) return true;
    reset(start);
    return false;
}

bool TokenStream::number(double& out, SourceLoc& loc) {
    if (ended_) return false;
    scanner_->bind(text());
    return scanner_->number(out, loc);
}

SourceLoc TokenStream::here() {
    scanner_->bind(text());
    return scanner_->location();
}

std::vector<Token> lex(const std::string& text, int fileId, bool strict) {
    TokenStream stream(text, fileId, strict);
    std::vector<Token> out;
    for (size_t i = 0;; ++i) {
        out.push_back(stream[i]);
        if (out.back().kind == TokenKind::EndOfFile) return out;
    }
}

} // namespace drt::lang
