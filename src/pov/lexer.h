// The POV-Ray lexer: one switch over the current character (after Lua's llex.c
// and clox's scanner). A file is lexed once into a token vector; loops and
// macros replay it by index (pov/reader.cpp).
#pragma once

#include "core/diagnostics.h"

#include <string>
#include <vector>

namespace drt::pov {

enum class TokKind {
    Number,
    String,    // text holds the contents, escapes resolved
    Word,      // keywords and identifiers alike
    Directive, // `#declare`: text holds the word after '#'
    Symbol,    // punctuation and operators: text holds it ("{", "<=", "!=", ...)
    EndOfFile,
    Error, // text holds the message
};

struct Tok {
    TokKind kind = TokKind::EndOfFile;
    std::string text;
    double number = 0;
    SourceLoc loc;

    bool is(const char* symbol) const { return kind == TokKind::Symbol && text == symbol; }
    bool isWord(const char* word) const { return kind == TokKind::Word && text == word; }
};

// `'sphere'`, `'{'`, `string "abc"`, `end of file`: a token for messages.
std::string describe(const Tok& token);

// Lexes a whole file. The last token is always EndOfFile. Malformed input gives
// Error tokens and lexing carries on after them.
std::vector<Tok> lexPov(const std::string& text, int fileId);

} // namespace drt::pov
