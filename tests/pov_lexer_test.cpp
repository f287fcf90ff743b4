// The POV-Ray lexer: tokens, comments, strings, numbers, locations.
#include "pov/lexer.h"

#include <gtest/gtest.h>

namespace drt::pov {
namespace {

std::vector<Tok> lex(const std::string& text) { return lexPov(text, 0); }

TEST(PovLexer, KindsTextAndLocations) {
    const auto t = lex("#declare A = <1, 2.5e1>; // c\n  sphere{ }");
    ASSERT_EQ(t.size(), 13u);
    EXPECT_EQ(t[0].kind, TokKind::Directive);
    EXPECT_EQ(t[0].text, "declare");
    EXPECT_EQ(t[1].kind, TokKind::Word);
    EXPECT_EQ(t[1].text, "A");
    EXPECT_TRUE(t[2].is("="));
    EXPECT_TRUE(t[3].is("<"));
    EXPECT_EQ(t[4].kind, TokKind::Number);
    EXPECT_DOUBLE_EQ(t[4].number, 1);
    EXPECT_DOUBLE_EQ(t[6].number, 25);
    EXPECT_TRUE(t[7].is(">"));
    EXPECT_TRUE(t[8].is(";"));
    EXPECT_TRUE(t[9].isWord("sphere"));
    EXPECT_EQ(t[9].loc.line, 2);
    EXPECT_EQ(t[9].loc.column, 3);
    EXPECT_EQ(t.back().kind, TokKind::EndOfFile);
}

TEST(PovLexer, TwoCharacterOperators) {
    const auto t = lex("<= >= != < > ! = ? : & | .");
    const char* expected[] = {"<=", ">=", "!=", "<", ">", "!", "=", "?", ":", "&", "|", "."};
    for (size_t i = 0; i < 12; ++i) EXPECT_TRUE(t[i].is(expected[i])) << i << " " << t[i].text;
}

TEST(PovLexer, NestedBlockCommentsAndLineComments) {
    const auto t = lex("a /* x /* y */ z */ b // c\nd");
    ASSERT_EQ(t.size(), 4u);
    EXPECT_EQ(t[0].text, "a");
    EXPECT_EQ(t[1].text, "b");
    EXPECT_EQ(t[2].text, "d");
    EXPECT_EQ(t[2].loc.line, 2);
}

TEST(PovLexer, StringsWithEscapes) {
    const auto t = lex(R"("a\"b\\c\n")");
    ASSERT_EQ(t[0].kind, TokKind::String);
    EXPECT_EQ(t[0].text, "a\"b\\c\n");
}

TEST(PovLexer, NumbersWithoutLeadingOrTrailingDigits) {
    const auto t = lex(".5 1. 3e-2 V.x");
    EXPECT_DOUBLE_EQ(t[0].number, 0.5);
    EXPECT_DOUBLE_EQ(t[1].number, 1.0);
    EXPECT_DOUBLE_EQ(t[2].number, 0.03);
    EXPECT_TRUE(t[3].isWord("V"));
    EXPECT_TRUE(t[4].is("."));
    EXPECT_TRUE(t[5].isWord("x"));
}

TEST(PovLexer, ErrorsCarryTheirLocation) {
    auto t = lex("a\n  \"open");
    EXPECT_EQ(t[1].kind, TokKind::Error);
    EXPECT_EQ(t[1].text, "unterminated string");
    EXPECT_EQ(t[1].loc.line, 2);
    EXPECT_EQ(t[1].loc.column, 3);
    t = lex("x /* never closed");
    EXPECT_EQ(t[1].kind, TokKind::Error);
    EXPECT_EQ(t[1].text, "unterminated comment");
    t = lex("a $ b");
    EXPECT_EQ(t[1].kind, TokKind::Error);
    EXPECT_EQ(t[1].loc.column, 3);
    EXPECT_TRUE(t[2].isWord("b")); // lexing carries on
}

TEST(PovLexer, DirectiveWithBlankAfterHash) {
    const auto t = lex("# declare");
    EXPECT_EQ(t[0].kind, TokKind::Directive);
    EXPECT_EQ(t[0].text, "declare");
}

} // namespace
} // namespace drt::pov
