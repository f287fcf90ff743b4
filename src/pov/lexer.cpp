#include "pov/lexer.h"

#include <cctype>
#include <cmath>
#include <cstdlib>

namespace drt::pov {

std::string describe(const Tok& token) {
    switch (token.kind) {
    case TokKind::EndOfFile: return "end of file";
    case TokKind::String: return "string \"" + token.text + "\"";
    case TokKind::Directive: return "'#" + token.text + "'";
    case TokKind::Error: return "invalid token";
    default: return "'" + token.text + "'";
    }
}

namespace {

bool isDigit(char c) { return c >= '0' && c <= '9'; }
bool isWordStart(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool isWordChar(char c) { return isWordStart(c) || isDigit(c); }

class Scanner {
public:
    Scanner(const std::string& text, int fileId) : text_(text), fileId_(fileId) {}

    std::vector<Tok> run() {
        std::vector<Tok> out;
        for (;;) {
            out.push_back(next());
            if (out.back().kind == TokKind::EndOfFile) return out;
        }
    }

private:
    char peek(size_t ahead = 0) const { return pos_ + ahead < text_.size() ? text_[pos_ + ahead] : '\0'; }
    bool atEnd() const { return pos_ >= text_.size(); }
    SourceLoc here() const { return {fileId_, line_, column_}; }
    char advance() {
        const char c = text_[pos_++];
        if (c == '\n') {
            ++line_;
            column_ = 1;
        } else {
            ++column_;
        }
        return c;
    }
    Tok make(TokKind kind, SourceLoc loc, std::string text) const {
        Tok t;
        t.kind = kind;
        t.loc = loc;
        t.text = std::move(text);
        return t;
    }

    // Returns an error message for an unterminated block comment, or "".
    std::string skipBlanksAndComments(SourceLoc& commentStart) {
        for (;;) {
            const char c = peek();
            if (c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v') {
                advance();
            } else if (c == '/' && peek(1) == '/') {
                while (!atEnd() && peek() != '\n') advance();
            } else if (c == '/' && peek(1) == '*') {
                // Block comments nest in POV-Ray.
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
            } else if (static_cast<unsigned char>(c) == 0xEF && static_cast<unsigned char>(peek(1)) == 0xBB &&
                       static_cast<unsigned char>(peek(2)) == 0xBF) {
                advance(), advance(), advance(); // UTF-8 byte-order mark
            } else {
                return "";
            }
        }
    }

    // number = digits ["." digits] [exponent] | "." digits [exponent]
    Tok number(SourceLoc start) {
        const size_t begin = pos_;
        while (isDigit(peek())) advance();
        if (peek() == '.' && !isWordStart(peek(1))) {
            advance();
            while (isDigit(peek())) advance();
        }
        if ((peek() == 'e' || peek() == 'E') &&
            (isDigit(peek(1)) || ((peek(1) == '+' || peek(1) == '-') && isDigit(peek(2))))) {
            advance();
            if (peek() == '+' || peek() == '-') advance();
            while (isDigit(peek())) advance();
        }
        Tok t = make(TokKind::Number, start, text_.substr(begin, pos_ - begin));
        t.number = std::strtod(t.text.c_str(), nullptr);
        if (!std::isfinite(t.number)) return make(TokKind::Error, start, "number '" + t.text + "' is out of range");
        return t;
    }

    Tok string(SourceLoc start) {
        advance(); // opening quote
        std::string value;
        while (peek() != '"') {
            if (atEnd() || peek() == '\n') return make(TokKind::Error, start, "unterminated string");
            const char c = advance();
            if (c != '\\') {
                value += c;
                continue;
            }
            if (atEnd()) return make(TokKind::Error, start, "unterminated string");
            switch (const char e = advance()) {
            case 'n': value += '\n'; break;
            case 't': value += '\t'; break;
            case 'r': value += '\r'; break;
            case 'a': value += '\a'; break;
            case 'b': value += '\b'; break;
            case 'f': value += '\f'; break;
            case 'v': value += '\v'; break;
            case '0': value += '\0'; break;
            default: value += e; break; // \" \\ \' and unknown escapes keep the character
            }
        }
        advance(); // closing quote
        return make(TokKind::String, start, value);
    }

    Tok word(SourceLoc start, TokKind kind) {
        const size_t begin = pos_;
        while (isWordChar(peek())) advance();
        return make(kind, start, text_.substr(begin, pos_ - begin));
    }

    Tok next() {
        SourceLoc commentStart;
        const std::string commentError = skipBlanksAndComments(commentStart);
        if (!commentError.empty()) {
            pos_ = text_.size();
            return make(TokKind::Error, commentStart, commentError);
        }
        const SourceLoc start = here();
        if (atEnd()) return make(TokKind::EndOfFile, start, "");
        const char c = peek();
        if (isDigit(c) || (c == '.' && isDigit(peek(1)))) return number(start);
        if (isWordStart(c)) return word(start, TokKind::Word);
        if (c == '"') return string(start);
        if (c == '#') {
            advance();
            while (peek() == ' ' || peek() == '\t') advance(); // `# declare` is allowed
            if (!isWordStart(peek())) return make(TokKind::Error, start, "expected a directive name after '#'");
            return word(start, TokKind::Directive);
        }
        advance();
        auto two = [&](char second, const char* both, const char* one) {
            if (peek() == second) {
                advance();
                return make(TokKind::Symbol, start, both);
            }
            return make(TokKind::Symbol, start, one);
        };
        switch (c) {
        case '<': return two('=', "<=", "<");
        case '>': return two('=', ">=", ">");
        case '!': return two('=', "!=", "!");
        case '{': case '}': case '(': case ')': case '[': case ']': case ',': case ';': case '+': case '-':
        case '*': case '/': case '=': case '?': case ':': case '&': case '|': case '.': case '^':
            return make(TokKind::Symbol, start, std::string(1, c));
        default: {
            const bool printable = std::isprint(static_cast<unsigned char>(c));
            return make(TokKind::Error, start,
                        printable ? std::string("unexpected character '") + c + "'"
                                  : "unexpected byte " + std::to_string(static_cast<unsigned char>(c)));
        }
        }
    }

    const std::string& text_;
    int fileId_;
    size_t pos_ = 0;
    int line_ = 1;
    int column_ = 1;
};

} // namespace

std::vector<Tok> lexPov(const std::string& text, int fileId) { return Scanner(text, fileId).run(); }

} // namespace drt::pov
