// The .drt lexer: token kinds, slices, locations, comments and every lexical error.
#include "lang/lexer.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <vector>

namespace drt {
namespace {

std::vector<Token> lexAll(const std::string& text) {
    Lexer lexer(text, 0);
    std::vector<Token> tokens;
    for (int guard = 0; guard < 10000; ++guard) {
        tokens.push_back(lexer.next());
        if (tokens.back().kind == TokenKind::EndOfFile) break;
    }
    return tokens;
}

TEST(Lexer, PunctuationAndWords) {
    const auto t = lexAll("sphere { <1, 2.5, -3> }; (a) [b] + - * / =");
    const std::vector<TokenKind> kinds{
        TokenKind::Identifier, TokenKind::LeftBrace,   TokenKind::LeftAngle,    TokenKind::Number,
        TokenKind::Comma,      TokenKind::Number,      TokenKind::Comma,        TokenKind::Minus,
        TokenKind::Number,     TokenKind::RightAngle,  TokenKind::RightBrace,   TokenKind::Semicolon,
        TokenKind::LeftParen,  TokenKind::Identifier,  TokenKind::RightParen,   TokenKind::LeftBracket,
        TokenKind::Identifier, TokenKind::RightBracket, TokenKind::Plus,        TokenKind::Minus,
        TokenKind::Star,       TokenKind::Slash,       TokenKind::Equals,       TokenKind::EndOfFile};
    ASSERT_EQ(t.size(), kinds.size());
    for (size_t i = 0; i < kinds.size(); ++i) EXPECT_EQ(t[i].kind, kinds[i]) << "token " << i;
    EXPECT_EQ(t[0].text, "sphere");
    EXPECT_DOUBLE_EQ(t[5].number, 2.5);
}

TEST(Lexer, NumbersWithExponents) {
    const auto t = lexAll("1 2.5 .5 3. 1e3 2.5E-2 4e+1");
    const std::vector<double> values{1, 2.5, 0.5, 3, 1000, 0.025, 40};
    ASSERT_EQ(t.size(), values.size() + 1);
    for (size_t i = 0; i < values.size(); ++i) {
        EXPECT_EQ(t[i].kind, TokenKind::Number);
        EXPECT_DOUBLE_EQ(t[i].number, values[i]);
    }
}

TEST(Lexer, LocationsAreLineAndColumn) {
    const auto t = lexAll("a\n  bb\n\tc");
    EXPECT_EQ(t[0].loc.line, 1);
    EXPECT_EQ(t[0].loc.column, 1);
    EXPECT_EQ(t[1].loc.line, 2);
    EXPECT_EQ(t[1].loc.column, 3);
    EXPECT_EQ(t[2].loc.line, 3);
    EXPECT_EQ(t[2].loc.column, 2);
    EXPECT_EQ(t[0].loc.file, 0);
}

TEST(Lexer, CommentsAreSkippedAndBlockCommentsNest) {
    const auto t = lexAll("a // line comment\n/* block /* nested */ still */ b");
    ASSERT_EQ(t.size(), 3u);
    EXPECT_EQ(t[0].text, "a");
    EXPECT_EQ(t[1].text, "b");
    EXPECT_EQ(t[1].loc.line, 2);
}

TEST(Lexer, StringsResolveEscapes) {
    const auto t = lexAll(R"("a\"b\\c\n")");
    ASSERT_EQ(t[0].kind, TokenKind::String);
    EXPECT_EQ(t[0].text, "a\"b\\c\n");
}

TEST(Lexer, DirectivesCarryTheirWord) {
    const auto t = lexAll("#declare X #include \"f\" # local");
    EXPECT_EQ(t[0].kind, TokenKind::Directive);
    EXPECT_EQ(t[0].text, "declare");
    EXPECT_EQ(t[2].kind, TokenKind::Directive);
    EXPECT_EQ(t[2].text, "include");
    EXPECT_EQ(t[4].kind, TokenKind::Directive);
    EXPECT_EQ(t[4].text, "local");
}

TEST(Lexer, DescribeNamesTokensForMessages) {
    const auto t = lexAll("sphere \"s\" #declare");
    EXPECT_EQ(describe(t[0]), "'sphere'");
    EXPECT_EQ(describe(t[1]), "string \"s\"");
    EXPECT_EQ(describe(t[2]), "'#declare'");
    EXPECT_EQ(describe(t[3]), "end of file");
}

struct LexError {
    const char* source;
    const char* message;
    int line, column;
};

class LexerErrors : public testing::TestWithParam<LexError> {};

TEST_P(LexerErrors, ReportsMessageAndLocationThenContinues) {
    const LexError& e = GetParam();
    const auto t = lexAll(e.source);
    const Token* error = nullptr;
    for (const Token& token : t)
        if (token.kind == TokenKind::Error) {
            error = &token;
            break;
        }
    ASSERT_NE(error, nullptr);
    EXPECT_EQ(error->text, e.message);
    EXPECT_EQ(error->loc.line, e.line);
    EXPECT_EQ(error->loc.column, e.column);
    EXPECT_EQ(t.back().kind, TokenKind::EndOfFile); // never stuck
}

INSTANTIATE_TEST_SUITE_P(
    All, LexerErrors,
    testing::Values(LexError{"x 1e+", "malformed number: exponent has no digits", 1, 3},
                    LexError{"\n 12ab", "malformed number '12a'", 2, 2},
                    LexError{"1e999", "number '1e999' is out of range", 1, 1},
                    LexError{"a \"abc", "unterminated string", 1, 3},
                    LexError{"\"abc\ndef\"", "unterminated string", 1, 1},
                    LexError{"\"a\\qb\" c", "unknown escape '\\q' in string", 1, 3},
                    LexError{"a /* b /* c */", "unterminated comment", 1, 3},
                    LexError{"# 5", "expected a directive name after '#'", 1, 1},
                    LexError{"a @ b", "unexpected character '@'", 1, 3},
                    LexError{"a \x01", "unexpected byte 1", 1, 3}),
    [](const testing::TestParamInfo<LexError>& info) {
        return test::testNameOf(std::string(info.param.message) + " at " + std::to_string(info.param.line) + " " +
                                std::to_string(info.param.column));
    });

TEST(Lexer, ArbitraryBytesAlwaysReachTheEnd) {
    std::string text;
    uint32_t state = 12345;
    for (int i = 0; i < 5000; ++i) {
        state = state * 1664525u + 1013904223u; // LCG: a fixed, reproducible byte soup
        text += static_cast<char>(state >> 24);
    }
    const auto t = lexAll(text);
    EXPECT_EQ(t.back().kind, TokenKind::EndOfFile);
}

} // namespace
} // namespace drt
