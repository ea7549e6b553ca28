#include "parser/lexer.h"

#include <gtest/gtest.h>

#include <cfloat>
#include <vector>

namespace darc {
namespace {

std::vector<Token> lex_all(const std::string& text) {
  Lexer lexer(text, std::make_shared<const std::string>("test.rib"));
  std::vector<Token> tokens;
  while (true) {
    Token t = lexer.next();
    if (t.kind == TokenKind::End) break;
    tokens.push_back(std::move(t));
  }
  return tokens;
}

double lex_number(const std::string& spelling) {
  const auto tokens = lex_all(spelling);
  EXPECT_EQ(tokens.size(), 1u) << spelling;
  if (tokens.size() != 1) return -12345;
  EXPECT_EQ(tokens[0].kind, TokenKind::Number) << spelling << ": " << tokens[0].text;
  return tokens[0].number;
}

TEST(Lexer, EveryRealWorldNumberSpellingMatchesStrtod) {
  const char* spellings[] = {".5",         "-.35", "+2", "5.",   "-3e-2", "1E+3",         "4.000000",
                             "3.04999995", "0",    "-0", "1e-5", "255",   "-1.99124e-15", "0.29552020666133966"};
  for (const char* s : spellings) {
    EXPECT_EQ(lex_number(s), std::strtod(s, nullptr)) << s;
  }
}

TEST(Lexer, NumbersOutsideFloatRangeAndNanSpellingsAreErrors) {
  for (const char* s : {"1e999", "-1e39", "3.5e38", "1e-400", "-nan", "+inf", "-inf", "1.2.3", "-", ".", "++2", "1e"}) {
    const auto tokens = lex_all(s);
    ASSERT_EQ(tokens.size(), 1u) << s;
    EXPECT_EQ(tokens[0].kind, TokenKind::Error) << s;
  }
  // Largest float still fits.
  EXPECT_EQ(lex_number("3.4028234e38"), 3.4028234e38);
}

TEST(Lexer, TokenKindsAndCommentsAsWhitespace) {
  const auto tokens = lex_all("##RenderMan RIB\nWorldBegin # comment \"not a string\n[1 \"a\"]#x\n]");
  ASSERT_EQ(tokens.size(), 6u);
  EXPECT_EQ(tokens[0].kind, TokenKind::Word);
  EXPECT_EQ(tokens[0].text, "WorldBegin");
  EXPECT_EQ(tokens[1].kind, TokenKind::ArrayBegin);
  EXPECT_EQ(tokens[2].kind, TokenKind::Number);
  EXPECT_EQ(tokens[3].kind, TokenKind::String);
  EXPECT_EQ(tokens[3].text, "a");
  EXPECT_EQ(tokens[4].kind, TokenKind::ArrayEnd);
  EXPECT_EQ(tokens[5].kind, TokenKind::ArrayEnd);
}

TEST(Lexer, AdjacentTokensWithoutSpaces) {
  const auto tokens = lex_all("Color[1 0 .5]\"P\"[0]");
  ASSERT_EQ(tokens.size(), 10u);
  EXPECT_EQ(tokens[0].text, "Color");
  EXPECT_EQ(tokens[4].number, 0.5);
  EXPECT_EQ(tokens[6].text, "P");
}

TEST(Lexer, StringEscapes) {
  const auto tokens = lex_all(R"("a\"b" "c\\d" "n\nt\tr\r" "C:\temp\x.rib" "C:\dir")");
  ASSERT_EQ(tokens.size(), 5u);
  EXPECT_EQ(tokens[0].text, "a\"b");
  EXPECT_EQ(tokens[1].text, "c\\d");
  EXPECT_EQ(tokens[2].text, "n\nt\tr\r");
  // \t is an escape even in a path; \x and \d are unknown and stay verbatim.
  EXPECT_EQ(tokens[3].text, "C:\temp\\x.rib");
  EXPECT_EQ(tokens[4].text, "C:\\dir");
}

TEST(Lexer, PositionsAreOneBasedAndCrlfIsOneLineBreak) {
  const auto tokens = lex_all("A\r\n  B\rC\n\t\"s\" D");
  ASSERT_EQ(tokens.size(), 5u);
  EXPECT_EQ(tokens[0].line, 1);
  EXPECT_EQ(tokens[0].column, 1);
  EXPECT_EQ(tokens[1].line, 2);
  EXPECT_EQ(tokens[1].column, 3);
  EXPECT_EQ(tokens[2].line, 3);
  EXPECT_EQ(tokens[2].column, 1);
  EXPECT_EQ(tokens[3].line, 4);
  EXPECT_EQ(tokens[3].column, 2);
  EXPECT_EQ(tokens[4].line, 4);
  EXPECT_EQ(tokens[4].column, 6);
}

TEST(Lexer, MultiLineStringAdvancesLines) {
  const auto tokens = lex_all("\"a\r\nb\" X");
  ASSERT_EQ(tokens.size(), 2u);
  EXPECT_EQ(tokens[1].line, 2);
  EXPECT_EQ(tokens[1].column, 4);
}

TEST(Lexer, UnterminatedStringIsAnErrorAtItsStartAndStops) {
  const auto tokens = lex_all("Surface\n  \"plastic [1 2 3]\nWorldEnd");
  ASSERT_EQ(tokens.size(), 2u);
  EXPECT_EQ(tokens[1].kind, TokenKind::Error);
  EXPECT_EQ(tokens[1].line, 2);
  EXPECT_EQ(tokens[1].column, 3);
}

TEST(Lexer, BinaryByteStopsReading) {
  const auto tokens = lex_all("WorldBegin\n Sphere \x81\x02 1 2 3\nWorldEnd");
  ASSERT_EQ(tokens.size(), 3u);
  EXPECT_EQ(tokens[2].kind, TokenKind::Error);
  EXPECT_EQ(tokens[2].text, "binary RIB is not supported");
  EXPECT_EQ(tokens[2].line, 2);
  EXPECT_EQ(tokens[2].column, 9);
}

TEST(Lexer, HighBytesInsideStringsAndCommentsAreText) {
  const auto tokens = lex_all("# caf\xc3\xa9\n\"na\xc3\xafve.tif\"");
  ASSERT_EQ(tokens.size(), 1u);
  EXPECT_EQ(tokens[0].kind, TokenKind::String);
  EXPECT_EQ(tokens[0].text, "na\xc3\xafve.tif");
}

TEST(Lexer, PeekDoesNotConsume) {
  Lexer lexer("A B", std::make_shared<const std::string>("x"));
  EXPECT_EQ(lexer.peek().text, "A");
  EXPECT_EQ(lexer.peek().text, "A");
  EXPECT_EQ(lexer.next().text, "A");
  EXPECT_EQ(lexer.next().text, "B");
  EXPECT_EQ(lexer.next().kind, TokenKind::End);
  EXPECT_EQ(lexer.next().kind, TokenKind::End);
}

}  // namespace
}  // namespace darc
