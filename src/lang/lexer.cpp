#include "lang/lexer.h"

#include <cctype>
#include <cmath>
#include <cstdlib>

namespace drt {

std::string describe(const Token& token) {
    switch (token.kind) {
    case TokenKind::EndOfFile: return "end of file";
    case TokenKind::String: return "string \"" + token.text + "\"";
    case TokenKind::Directive: return "'#" + token.text + "'";
    case TokenKind::Error: return "invalid token";
    default: return "'" + token.text + "'";
    }
}

char Lexer::advance() {
    const char c = text_[pos_++];
    if (c == '\n') {
        ++line_;
        column_ = 1;
    } else {
        ++column_;
    }
    return c;
}

std::string Lexer::skipBlanksAndComments(SourceLoc& commentStart) {
    for (;;) {
        switch (peek()) {
        case ' ':
        case '\t':
        case '\r':
        case '\n':
        case '\f':
        case '\v': advance(); break;
        case '/':
            if (peek(1) == '/') {
                while (!atEnd() && peek() != '\n') advance();
            } else if (peek(1) == '*') {
                // Block comments nest, as in POV-Ray.
                commentStart = here();
                advance();
                advance();
                int depth = 1;
                while (depth > 0) {
                    if (atEnd()) return "unterminated comment";
                    if (peek() == '/' && peek(1) == '*') {
                        advance();
                        advance();
                        ++depth;
                    } else if (peek() == '*' && peek(1) == '/') {
                        advance();
                        advance();
                        --depth;
                    } else {
                        advance();
                    }
                }
            } else {
                return "";
            }
            break;
        default: return "";
        }
    }
}

Token Lexer::make(TokenKind kind, SourceLoc loc, std::string text) const {
    Token t;
    t.kind = kind;
    t.loc = loc;
    t.text = std::move(text);
    return t;
}

static bool isDigit(char c) { return c >= '0' && c <= '9'; }
static bool isWordStart(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
static bool isWordChar(char c) { return isWordStart(c) || isDigit(c); }

// number = digits [ "." digits ] [ exponent ] | "." digits [ exponent ];
// exponent = ("e" | "E") [ "+" | "-" ] digits.
Token Lexer::number(SourceLoc start) {
    const size_t begin = pos_;
    while (isDigit(peek())) advance();
    if (peek() == '.') {
        advance();
        while (isDigit(peek())) advance();
    }
    if (peek() == 'e' || peek() == 'E') {
        const size_t ahead = (peek(1) == '+' || peek(1) == '-') ? 2 : 1;
        if (!isDigit(peek(ahead))) {
            for (size_t i = 0; i < ahead; ++i) advance();
            return make(TokenKind::Error, start, "malformed number: exponent has no digits");
        }
        for (size_t i = 0; i < ahead; ++i) advance();
        while (isDigit(peek())) advance();
    }
    std::string text = text_.substr(begin, pos_ - begin);
    if (isWordStart(peek()))
        return make(TokenKind::Error, start, "malformed number '" + text + std::string(1, peek()) + "'");
    Token t = make(TokenKind::Number, start, text);
    t.number = std::strtod(t.text.c_str(), nullptr);
    if (!std::isfinite(t.number)) return make(TokenKind::Error, start, "number '" + text + "' is out of range");
    return t;
}

Token Lexer::string(SourceLoc start) {
    advance(); // opening quote
    std::string value;
    while (peek() != '"') {
        if (atEnd() || peek() == '\n') return make(TokenKind::Error, start, "unterminated string");
        const SourceLoc escapeLoc = here();
        char c = advance();
        if (c == '\\') {
            if (atEnd()) return make(TokenKind::Error, start, "unterminated string");
            switch (const char e = advance()) {
            case '"': value += '"'; break;
            case '\\': value += '\\'; break;
            case 'n': value += '\n'; break;
            case 't': value += '\t'; break;
            default:
                // Skip to the closing quote so the rest of the line lexes normally.
                while (!atEnd() && peek() != '"' && peek() != '\n') advance();
                if (peek() == '"') advance();
                return make(TokenKind::Error, escapeLoc, std::string("unknown escape '\\") + e + "' in string");
            }
            continue;
        }
        value += c;
    }
    advance(); // closing quote
    return make(TokenKind::String, start, value);
}

Token Lexer::word(SourceLoc start, TokenKind kind) {
    const size_t begin = pos_;
    while (isWordChar(peek())) advance();
    return make(kind, start, text_.substr(begin, pos_ - begin));
}

Token Lexer::next() {
    SourceLoc commentStart;
    const std::string commentError = skipBlanksAndComments(commentStart);
    if (!commentError.empty()) return make(TokenKind::Error, commentStart, commentError);

    const SourceLoc start = here();
    if (atEnd()) return make(TokenKind::EndOfFile, start, "");
    const char c = peek();
    if (isDigit(c) || (c == '.' && isDigit(peek(1)))) return number(start);
    if (isWordStart(c)) return word(start, TokenKind::Identifier);

    auto single = [&](TokenKind kind) {
        advance();
        return make(kind, start, std::string(1, c));
    };
    switch (c) {
    case '{': return single(TokenKind::LeftBrace);
    case '}': return single(TokenKind::RightBrace);
    case '(': return single(TokenKind::LeftParen);
    case ')': return single(TokenKind::RightParen);
    case '<': return single(TokenKind::LeftAngle);
    case '>': return single(TokenKind::RightAngle);
    case '[': return single(TokenKind::LeftBracket);
    case ']': return single(TokenKind::RightBracket);
    case ',': return single(TokenKind::Comma);
    case ';': return single(TokenKind::Semicolon);
    case '+': return single(TokenKind::Plus);
    case '-': return single(TokenKind::Minus);
    case '*': return single(TokenKind::Star);
    case '/': return single(TokenKind::Slash);
    case '=': return single(TokenKind::Equals);
    case '"': return string(start);
    case '#': {
        advance();
        while (peek() == ' ' || peek() == '\t') advance(); // POV-Ray allows `# declare`
        if (!isWordStart(peek())) return make(TokenKind::Error, start, "expected a directive name after '#'");
        return word(start, TokenKind::Directive);
    }
    default: {
        advance();
        const bool printable = std::isprint(static_cast<unsigned char>(c));
        return make(TokenKind::Error, start,
                    printable ? std::string("unexpected character '") + c + "'"
                              : "unexpected byte " + std::to_string(static_cast<unsigned char>(c)));
    }
    }
}

} // namespace drt
