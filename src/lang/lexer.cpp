#include "lang/lexer.h"

#include <cctype>
#include <cmath>
#include <cstdlib>

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

class Scanner {
public:
    Scanner(const std::string& text, int fileId, bool strict) : text_(text), fileId_(fileId), strict_(strict) {}

    std::vector<Token> run() {
        std::vector<Token> out;
        for (;;) {
            out.push_back(next());
            if (out.back().kind == TokenKind::EndOfFile) return out;
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
            if (c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v') {
                advance();
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
    // exponent = ("e" | "E") ["+" | "-"] digits.
    Token number(SourceLoc start) {
        const size_t begin = pos_;
        while (isDigit(peek())) advance();
        // `1.x`: POV-Ray reads the number 1 and the component `.x`.
        if (peek() == '.' && !isWordStart(peek(1))) {
            advance();
            while (isDigit(peek())) advance();
        }
        if (peek() == 'e' || peek() == 'E') {
            const size_t ahead = (peek(1) == '+' || peek(1) == '-') ? 2 : 1;
            if (isDigit(peek(ahead))) {
                for (size_t i = 0; i < ahead; ++i) advance();
                while (isDigit(peek())) advance();
            } else if (strict_) {
                for (size_t i = 0; i < ahead; ++i) advance();
                return make(TokenKind::Error, start, "malformed number: exponent has no digits");
            }
        }
        const std::string text = text_.substr(begin, pos_ - begin);
        if (strict_ && isWordStart(peek()))
            return make(TokenKind::Error, start, "malformed number '" + text + std::string(1, peek()) + "'");
        Token t = make(TokenKind::Number, start, text);
        t.number = std::strtod(t.text.c_str(), nullptr);
        if (!std::isfinite(t.number)) return make(TokenKind::Error, start, "number '" + text + "' is out of range");
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
        while (isWordChar(peek())) advance();
        return make(kind, start, text_.substr(begin, pos_ - begin));
    }

    Token next() {
        SourceLoc commentStart;
        const std::string commentError = skipBlanksAndComments(commentStart);
        if (!commentError.empty()) {
            pos_ = text_.size();
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
            if (!isWordStart(peek())) return make(TokenKind::Error, start, "expected a directive name after '#'");
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

    const std::string& text_;
    int fileId_;
    bool strict_;
    size_t pos_ = 0;
    int line_ = 1;
    int column_ = 1;
};

} // namespace

std::vector<Token> lex(const std::string& text, int fileId, bool strict) { return Scanner(text, fileId, strict).run(); }

} // namespace drt::lang
