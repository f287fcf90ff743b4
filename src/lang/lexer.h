// The lexer of both dialects: one switch over the current character (after
// Lua's llex.c and clox's scanner). A file is lexed on demand into a
// TokenStream as the reader pulls tokens; loops and macros replay it by index
// (lang/reader.cpp). Readers of long literal lists (mesh vertices and
// indices, shapes_mesh*.cpp) may scan plain numbers and vectors straight from
// the text at the stream's end (its frontier) without making tokens.
#pragma once

#include "core/diagnostics.h"
#include "core/vec.h"

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
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
    // The reader's cache of where a word's name is in its symbol table
    // (lang/symbols.h: Scopes::slotOf), made at its first lookup: a loop or a
    // macro replaying the token looks the name up without hashing it again.
    mutable const void* symbol = nullptr;
    mutable uint32_t symbolTable = 0; // the table `symbol` is in (0: none)

    // A string_view, not a const char*: a literal's length is known when this
    // is inlined, so a mismatch costs a length compare, not a strlen and a strcmp;
    // the characters are compared here, not by a call of memcmp (symbols are
    // a character or two).
    bool is(std::string_view symbol) const { return kind == TokenKind::Symbol && textIs(symbol); }
    bool isWord(std::string_view word) const { return kind == TokenKind::Word && textIs(word); }
    bool textIs(std::string_view s) const {
        if (text.size() != s.size()) return false;
        for (size_t i = 0; i < s.size(); ++i)
            if (text[i] != s[i]) return false;
        return true;
    }
};

// `'sphere'`, `'{'`, `string "abc"`, `'#declare'`, `end of file`: a token for messages.
std::string describe(const Token& token);

// Lexes a whole file. The last token is always EndOfFile. Malformed input
// gives Error tokens and lexing carries on after them. `strict` (the .drt
// dialect) makes a number run into a word (`12ab`), an exponent without digits
// and an unknown string escape errors; POV-Ray reads them as a number then a
// word, and keeps the escaped character.
std::vector<Token> lex(const std::string& text, int fileId, bool strict);

// A vector of plain number literals, `<1, -2.5, 3e2>` (2 to 5 components),
// scanned without tokens: its components and the place of its '<'.
struct LiteralVector {
    double v[5] = {0, 0, 0, 0, 0};
    int size = 0;
    SourceLoc loc, end; // of its '<' and its '>'
    // As vectorExpr() reads it: 2 components have z = 0, 4 or 5 keep x, y, z.
    Vec3 xyz() const { return {v[0], v[1], size > 2 ? v[2] : 0.0}; }
};

// The tokens of one file, lexed as they are asked for (the same tokens, in
// the same order, as lex()). Indices stay valid: tokens are kept in blocks
// that never move.
class TokenStream {
public:
    static constexpr size_t kBlockBits = 10;
    static constexpr size_t kBlock = size_t(1) << kBlockBits;
    // The text of file `fileId` in `files` (looked up at each use: the table may grow).
    TokenStream(const SourceFiles& files, int fileId, bool strict);
    // A text of its own.
    TokenStream(std::string text, int fileId, bool strict);
    ~TokenStream();
    TokenStream(const TokenStream&) = delete;
    TokenStream& operator=(const TokenStream&) = delete;

    // Token `i`, lexing up to it; past the end of the file, the EndOfFile token.
    const Token& operator[](size_t i) const;
    // Tokens made so far.
    size_t lexed() const { return count_; }
    int fileId() const { return fileId_; }

    // Forgets tokens [i, lexed()) so the text after token i-1 is read again;
    // only the last few tokens can be forgotten (false otherwise).
    bool rewind(size_t i);

    // Frees the tokens before index `before` that no kept range holds, a block
    // of kBlock tokens at a time (the reader calls it with what it can no longer
    // go back to: a scene of a million objects need not hold its tokens). A
    // freed token read again is a reader bug: std::logic_error.
    void release(size_t before);
    // Tokens [first, last) stay readable whatever release() is given (a macro's
    // body, replayed at each call).
    void keep(size_t first, size_t last);
    // Whether token i can be read (made, or still to be made, and not freed).
    bool available(size_t i) const { return (i >> kBlockBits) >= blocks_.size() || blocks_[i >> kBlockBits]; }
    // Blocks freed so far (for tests and measurements).
    size_t releasedBlocks() const { return releasedBlocks_; }

    // --- Scanning at the frontier (the text after the last token made). Each
    // scan either consumes what it names and returns true, or consumes nothing
    // and returns false; blanks and comments before it are skipped either way
    // only when it succeeds.
    struct Mark {
        size_t pos = 0;
        int line = 1, column = 1;
    };
    Mark mark() const;
    void reset(Mark m);
    // The symbol character `c` (`{`, `}`, `,`, `<`, ...), alone: not the start of `<=`.
    bool symbol(char c);
    // The word `w`, whole.
    bool word(const char* w);
    // The next character after blanks and comments, not consumed ('\0' at the end or on a bad comment).
    char peekChar();
    // `<n, n [, n...]>` of 2 to 5 optionally signed number literals, separated by
    // commas, followed by a blank or a character that cannot continue an
    // expression (`,` `}` `<` `#`, a letter); with `requireCommas` false,
    // components may also be separated by blanks, as POV-Ray allows.
    bool vector(LiteralVector& out);
    // A list item: an optional ',' then vector().
    bool item(LiteralVector& out);
    // A plain unsigned number literal followed by `,` or `}` (after blanks).
    bool number(double& out, SourceLoc& loc);
    // The place of the next character after blanks (for messages).
    SourceLoc here();

private:
    class Scanner;
    void lexOne() const;
    [[noreturn]] static void releasedTokenRead(size_t i);
    const std::string& text() const;

    const SourceFiles* files_ = nullptr;
    std::string own_;
    int fileId_;
    std::unique_ptr<Scanner> scanner_;
    mutable std::vector<std::unique_ptr<Token[]>> blocks_;
    mutable size_t count_ = 0;
    mutable bool ended_ = false; // the EndOfFile token is made
    // Where the last few tokens started, for rewind().
    static constexpr size_t kRing = 16;
    mutable Mark starts_[kRing];
    std::vector<std::pair<size_t, size_t>> kept_; // keep()'s ranges
    size_t releasedBefore_ = 0; // blocks below this one were freed or are kept
    size_t releasedBlocks_ = 0;
};

} // namespace drt::lang
