// The lexer of both dialects: token kinds, slices, locations, comments, every
// lexical error, and the POV-Ray dialect's leniency.
#include "lang/lexer.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <vector>

namespace drt::lang {
namespace {

std::vector<Token> lexAll(const std::string& text, bool strict = true) { return lex(text, 0, strict); }

TEST(Lexer, PunctuationAndWords) {
    const auto t = lexAll("sphere { <1, 2.5, -3> }; (a) [b] + - * / =");
    const std::vector<const char*> symbols{"{", "<", "",  ",", "", ",", "-", "", ">", "}", ";", "(", "", ")",
                                           "[", "",  "]", "+", "-", "*", "/", "="};
    ASSERT_EQ(t.size(), symbols.size() + 2);
    EXPECT_TRUE(t[0].isWord("sphere"));
    for (size_t i = 0; i < symbols.size(); ++i) {
        const Token& token = t[i + 1];
        if (*symbols[i]) EXPECT_TRUE(token.is(symbols[i])) << "token " << i + 1 << " " << token.text;
        else EXPECT_TRUE(token.kind == TokenKind::Number || token.kind == TokenKind::Word) << "token " << i + 1;
    }
    EXPECT_DOUBLE_EQ(t[5].number, 2.5);
    EXPECT_EQ(t.back().kind, TokenKind::EndOfFile);
}

TEST(Lexer, TwoCharacterOperators) {
    const auto t = lexAll("<= >= != < > ! = ? : & | .");
    const char* expected[] = {"<=", ">=", "!=", "<", ">", "!", "=", "?", ":", "&", "|", "."};
    for (size_t i = 0; i < 12; ++i) EXPECT_TRUE(t[i].is(expected[i])) << i << " " << t[i].text;
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

TEST(Lexer, AComponentAfterANameIsNotANumber) {
    const auto t = lexAll("V.x 1.x");
    EXPECT_TRUE(t[0].isWord("V"));
    EXPECT_TRUE(t[1].is("."));
    EXPECT_TRUE(t[2].isWord("x"));
    EXPECT_DOUBLE_EQ(t[3].number, 1.0);
    EXPECT_TRUE(t[4].is("."));
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
    const auto t = lexAll(R"("a\"b\\c\n\t\r")");
    ASSERT_EQ(t[0].kind, TokenKind::String);
    EXPECT_EQ(t[0].text, "a\"b\\c\n\t\r");
}

TEST(Lexer, AByteOrderMarkStartingTheFileIsSkipped) {
    const auto t = lexAll("\xEF\xBB\xBFsphere");
    ASSERT_EQ(t.size(), 2u);
    EXPECT_TRUE(t[0].isWord("sphere"));
    EXPECT_EQ(t[0].loc.column, 1);
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
    const auto t = lexAll("sphere \"s\" #declare {");
    EXPECT_EQ(describe(t[0]), "'sphere'");
    EXPECT_EQ(describe(t[1]), "string \"s\"");
    EXPECT_EQ(describe(t[2]), "'#declare'");
    EXPECT_EQ(describe(t[3]), "'{'");
    EXPECT_EQ(describe(t[4]), "end of file");
}

// POV-Ray reads `12ab` as a number and a word, `1e+` as 1, `e`, `+`, and keeps
// an unknown escape's character; the .drt dialect calls them errors (below).
TEST(Lexer, PovRayDialectIsLenient) {
    const auto t = lexAll("12ab 1e+ \"a\\qb\"", false);
    EXPECT_DOUBLE_EQ(t[0].number, 12);
    EXPECT_TRUE(t[1].isWord("ab"));
    EXPECT_DOUBLE_EQ(t[2].number, 1);
    EXPECT_TRUE(t[3].isWord("e"));
    EXPECT_TRUE(t[4].is("+"));
    EXPECT_EQ(t[5].kind, TokenKind::String);
    EXPECT_EQ(t[5].text, "aqb");
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

// POV-Ray reads a '#' with no directive name as nothing (language/image_size.pov
// has `look_at <0,2,0>#`); in .drt it stays an error. Many in a row end too.
TEST(Lexer, ALoneHashIsSkippedInPovAndAnErrorInDrt) {
    const auto pov = lexAll("look_at <0,2,0>#\n}", false);
    ASSERT_EQ(pov.size(), 10u);
    for (const Token& t : pov) EXPECT_NE(t.kind, TokenKind::Error) << t.text;
    EXPECT_TRUE(pov[7].is(">"));
    EXPECT_TRUE(pov[8].is("}"));
    EXPECT_EQ(pov[8].loc.line, 2);
    const auto drt = lexAll("look_at <0,2,0>#\n}", true);
    EXPECT_EQ(drt[8].kind, TokenKind::Error);
    const auto many = lexAll(std::string(200000, '#') + "\nx", false);
    ASSERT_EQ(many.size(), 2u);
    EXPECT_TRUE(many[0].isWord("x"));
}

TEST(Lexer, LexingCarriesOnAfterAnError) {
    const auto t = lexAll("a $ b", false);
    EXPECT_EQ(t[1].kind, TokenKind::Error);
    EXPECT_EQ(t[1].loc.column, 3);
    EXPECT_TRUE(t[2].isWord("b"));
}

TEST(Lexer, ArbitraryBytesAlwaysReachTheEnd) {
    std::string text;
    uint32_t state = 12345;
    for (int i = 0; i < 5000; ++i) {
        state = state * 1664525u + 1013904223u; // LCG: a fixed, reproducible byte soup
        text += static_cast<char>(state >> 24);
    }
    for (bool strict : {true, false}) {
        const auto t = lexAll(text, strict);
        EXPECT_EQ(t.back().kind, TokenKind::EndOfFile);
    }
}

} // namespace
} // namespace drt::lang

namespace drt::lang {
namespace {

TEST(TokenStream, ReleaseFreesWholeBlocksBeforeTheMarkButKeepsKeptRanges) {
    std::string text;
    for (int i = 0; i < 5000; ++i) text += "w" + std::to_string(i) + " ";
    TokenStream tokens(text, 0, true);
    ASSERT_EQ(tokens[4999].text, "w4999");
    tokens.keep(1500, 1600); // inside the second block, [1024, 2048)
    tokens.release(4000);    // blocks [0, 1024) and [2048, 3072) go; [3072, 4096) holds token 4000
    EXPECT_EQ(tokens.releasedBlocks(), 2u);
    EXPECT_FALSE(tokens.available(10));
    EXPECT_FALSE(tokens.available(2100));
    EXPECT_TRUE(tokens.available(1024));
    EXPECT_TRUE(tokens.available(3500));
    EXPECT_THROW(tokens[10], std::logic_error);
    EXPECT_THROW(tokens[3071], std::logic_error);
    EXPECT_EQ(tokens[1500].text, "w1500");
    EXPECT_EQ(tokens[1024].text, "w1024");
    EXPECT_EQ(tokens[3072].text, "w3072");
    // Releasing again, or less, frees nothing more; the frontier's block always stays.
    tokens.release(100);
    tokens.release(1u << 20);
    EXPECT_EQ(tokens.releasedBlocks(), 3u); // [3072, 4096) too; [4096, ...) holds the last token made
    EXPECT_EQ(tokens[4999].text, "w4999");
    EXPECT_EQ(tokens[5000].kind, TokenKind::EndOfFile);
    EXPECT_FALSE(tokens.rewind(10));
}

TEST(TokenStream, MacrosAndLoopsStillReplayAfterTheReaderReleasedTokens) {
    // A macro defined first and called last, after tens of thousands of
    // tokens the reader has freed; a #while whose body spans several blocks
    // goes back to its condition on each pass.
    for (const bool pov : {true, false}) {
        std::string scene = "#macro Report(X) #warning str(X, 0, 0) #end\n";
        for (int i = 0; i < 4000; ++i) scene += "#declare A" + std::to_string(i) + " = " + std::to_string(i) + ";\n";
        scene += "#declare N = 0;\n#declare S = 0;\n#while (N < 3)\n";
        for (int i = 0; i < 600; ++i) scene += "#declare S = S + 1;\n";
        scene += "#declare N = N + 1;\n#end\n";
        scene += "Report(S) Report(A3999 + N)\n";
        const auto run = test::readSceneText(scene, pov);
        EXPECT_FALSE(run->diags.hasErrors()) << (pov ? "pov" : "drt");
        ASSERT_EQ(run->messages.size(), 2u) << (pov ? "pov" : "drt");
        EXPECT_EQ(run->messages[0], "1800");
        EXPECT_EQ(run->messages[1], "4002");
    }
}

} // namespace
} // namespace drt::lang
