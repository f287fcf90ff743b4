// The lexer of both dialects: one switch over the current character (after
// Lua's llex.c and clox's scanner). A file is lexed once into a token vector;
// loops and macros replay it by index (lang/reader.cpp).
#pragma once

#include "core/diagnostics.h"

#include <string>
#include <vector>

namespace drt::lang {

enum class TokenKind {
    Number,
    String,    // text holds the contents, escapes resolved
    Word,      // keywords and identifiers alike: the evaluator tells them apart by context
    Directive, // `#declare`: text holds the word after '#'
    Symbol,    // punctuation and operators: text holds it ("{", "<=", "!=", ...)
    EndOfFile,
    Error, // text holds the message
};

struct Token {
    TokenKind kind = TokenKind::EndOfFile;
    std::string text;
    double number = 0;
    SourceLoc loc;

    bool is(const char* symbol) const { return kind == TokenKind::Symbol && text == symbol; }
    bool isWord(const char* word) const { return kind == TokenKind::Word && text == word; }
};

// `'sphere'`, `'{'`, `string "abc"`, `'#declare'`, `end of file`: a token for messages.
std::string describe(const Token& token);

// Lexes a whole file. The last token is always EndOfFile. Malformed input
// gives Error tokens and lexing carries on after them. `strict` (the .drt
// dialect) makes a number run into a word (`12ab`), an exponent without digits
// and an unknown string escape errors; POV-Ray reads them as a number then a
// word, and keeps the escaped character.
std::vector<Token> lex(const std::string& text, int fileId, bool strict);

} // namespace drt::lang
