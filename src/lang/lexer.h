// The .drt lexer: one switch over the current character (after Lua's llex.c
// and clox's scanner). Tokens carry their text and where they start.
#pragma once

#include "core/diagnostics.h"

#include <string>

namespace drt {

enum class TokenKind {
    Number,
    String,     // text holds the contents, escapes resolved
    Identifier, // keywords too: the parser tells them apart by context
    Directive,  // `#declare`, `#include`, ...: text holds the word after '#'
    LeftBrace,
    RightBrace,
    LeftParen,
    RightParen,
    LeftAngle,
    RightAngle,
    LeftBracket,
    RightBracket,
    Comma,
    Semicolon,
    Plus,
    Minus,
    Star,
    Slash,
    Equals,
    EndOfFile,
    Error, // text holds the message
};

struct Token {
    TokenKind kind = TokenKind::EndOfFile;
    std::string text;
    double number = 0;
    SourceLoc loc;
};

// Human-readable form of a token for messages: `'sphere'`, `'{'`, `end of file`.
std::string describe(const Token& token);

class Lexer {
public:
    // `fileId` is the text's id in SourceFiles (the lexer keeps its own copy:
    // SourceFiles may move its strings as it grows).
    Lexer(std::string text, int fileId) : text_(std::move(text)), fileId_(fileId) {}

    // The next token; after the end, EndOfFile forever. Malformed input gives
    // an Error token and the lexer carries on after it.
    Token next();

private:
    char peek(size_t ahead = 0) const { return pos_ + ahead < text_.size() ? text_[pos_ + ahead] : '\0'; }
    bool atEnd() const { return pos_ >= text_.size(); }
    char advance();
    // Skips blanks and comments; returns an Error token's message for an
    // unterminated block comment, or "".
    std::string skipBlanksAndComments(SourceLoc& commentStart);
    SourceLoc here() const { return {fileId_, line_, column_}; }
    Token make(TokenKind kind, SourceLoc loc, std::string text) const;
    Token number(SourceLoc start);
    Token string(SourceLoc start);
    Token word(SourceLoc start, TokenKind kind);

    std::string text_;
    int fileId_;
    size_t pos_ = 0;
    int line_ = 1;
    int column_ = 1;
};

} // namespace drt
