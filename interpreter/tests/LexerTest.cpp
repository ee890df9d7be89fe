// Lexer: token kinds and values, number and string forms, indentation, line joining, errors.
#include "interpreter/Lexer.hpp"

#include <gtest/gtest.h>

namespace stella {
namespace {

std::vector<Token> lex(const std::string& text, std::vector<Diagnostic>* errors = nullptr) {
  static std::vector<std::shared_ptr<const SourceFile>> keep; // tokens view the file's text
  keep.push_back(SourceFile::fromText("t.comm", text));
  Lexer lexer(keep.back());
  std::vector<Token> out;
  for (;;) {
    out.push_back(lexer.next());
    if (out.back().kind == TokenKind::EndOfFile) {
      break;
    }
  }
  if (errors != nullptr) {
    *errors = lexer.errors();
  }
  return out;
}

std::vector<TokenKind> kinds(const std::vector<Token>& tokens) {
  std::vector<TokenKind> out;
  for (const auto& t : tokens) {
    out.push_back(t.kind);
  }
  return out;
}

TEST(Lexer, NumbersInEveryForm) {
  auto t = lex("1 1. .5 1.E-6 2.1e5 1_000 0x1F 3j");
  ASSERT_EQ(t.size(), 10u); // 8 numbers, NEWLINE, EOF
  EXPECT_EQ(t[0].kind, TokenKind::Int);
  EXPECT_EQ(t[0].intValue, 1);
  EXPECT_EQ(t[1].kind, TokenKind::Real);
  EXPECT_DOUBLE_EQ(t[1].realValue, 1.0);
  EXPECT_DOUBLE_EQ(t[2].realValue, 0.5);
  EXPECT_DOUBLE_EQ(t[3].realValue, 1e-6);
  EXPECT_DOUBLE_EQ(t[4].realValue, 2.1e5);
  EXPECT_EQ(t[5].intValue, 1000);
  EXPECT_EQ(t[6].intValue, 31);
  EXPECT_EQ(t[7].kind, TokenKind::Imaginary);
}

TEST(Lexer, LocationsAreOneBasedLineAndColumn) {
  auto t = lex("A = 1\n  # comment\nBB = (2,\n      3)\n");
  // A = 1 NEWLINE BB = ( 2 , 3 ) NEWLINE EOF
  EXPECT_EQ(t[0].pos.line, 1);
  EXPECT_EQ(t[0].pos.column, 1);
  EXPECT_EQ(t[4].text, "BB");
  EXPECT_EQ(t[4].pos.line, 3);
  EXPECT_EQ(t[4].pos.length, 2);
  EXPECT_EQ(t[9].text, "3");
  EXPECT_EQ(t[9].pos.line, 4);
  EXPECT_EQ(t[9].pos.column, 7);
}

TEST(Lexer, IndentAndDedent) {
  auto t = lex("if x:\n    y = 1\n    if z:\n        w = 2\nv = 3\n");
  std::vector<TokenKind> k = kinds(t);
  EXPECT_EQ(std::count(k.begin(), k.end(), TokenKind::Indent), 2);
  EXPECT_EQ(std::count(k.begin(), k.end(), TokenKind::Dedent), 2);
}

TEST(Lexer, BracketsJoinLinesAndBackslashContinues) {
  auto t = lex("A = f(1,\n\n  2)\nB = 1 + \\\n    2\n");
  std::vector<TokenKind> k = kinds(t);
  EXPECT_EQ(std::count(k.begin(), k.end(), TokenKind::Newline), 2);
  EXPECT_EQ(std::count(k.begin(), k.end(), TokenKind::Indent), 0);
}

TEST(Lexer, StringForms) {
  auto t = lex("'a\\tb' \"c'd\" '''x\ny''' r'\\n' u'u' f'{x}'");
  EXPECT_EQ(t[0].value, "a\tb");
  EXPECT_EQ(t[1].value, "c'd");
  EXPECT_EQ(t[2].value, "x\ny");
  EXPECT_EQ(t[3].value, "\\n");
  EXPECT_EQ(t[4].value, "u");
  EXPECT_TRUE(t[5].fString);
}

TEST(Lexer, SemicolonAndCodingLine) {
  auto t = lex("# -*- coding: utf-8 -*-\nDEBUT();\n");
  EXPECT_EQ(t[0].text, "DEBUT");
  EXPECT_EQ(t[3].kind, TokenKind::Semicolon);
}

TEST(Lexer, MixedTabsAndSpacesAreRefused) {
  std::vector<Diagnostic> errors;
  lex("if x:\n        a = 1\n\tb = 2\n", &errors);
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors[0].id, "SYNTAX_5");
  EXPECT_EQ(errors[0].location.line, 3);
}

TEST(Lexer, UnterminatedStringAndBadCharacter) {
  std::vector<Diagnostic> errors;
  lex("a = 'open\nb = $\n", &errors);
  ASSERT_EQ(errors.size(), 2u);
  EXPECT_EQ(errors[0].id, "SYNTAX_2");
  EXPECT_EQ(errors[1].id, "SYNTAX_3");
  EXPECT_EQ(errors[1].location.line, 2);
  EXPECT_EQ(errors[1].location.column, 5);
}

TEST(Lexer, UnclosedBracketIsReportedAtTheBracket) {
  std::vector<Diagnostic> errors;
  lex("A = f(1,\n  2\n", &errors);
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors[0].id, "SYNTAX_8");
  EXPECT_EQ(errors[0].location.column, 6);
}

TEST(Lexer, TooLargeIntegerIsAnError) {
  std::vector<Diagnostic> errors;
  lex("a = 123456789012345678901234567890\n", &errors);
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors[0].id, "SYNTAX_9");
}

} // namespace
} // namespace stella
