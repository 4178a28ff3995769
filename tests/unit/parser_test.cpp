#include "kerf/converter/nc/program.h"

#include "converter_support.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include "../corpus.h"

#include <charconv>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <optional>
#include <random>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

using namespace kerf::converter;

namespace {

Program parse(const SourceFile& src, Diagnostics& d) { return parseProgram(src, d); }

/// Every block's words in order, a plain block's as the parse kept them or, once given back,
/// parsed again (WordReader).
std::vector<Word> allWords(const Program& p) {
  WordReader reader(p);
  std::vector<Word> out;
  for (const Block& b : p.blocks) {
    const auto words = reader.words(b);
    out.insert(out.end(), words.begin(), words.end());
  }
  return out;
}

/// The same words: letter, value, point, kind, corner, column and length.
::testing::AssertionResult sameWords(const std::vector<Word>& a, const std::vector<Word>& b) {
  if (a.size() != b.size()) return ::testing::AssertionFailure() << a.size() << " words against " << b.size();
  auto fields = [](const Word& w) {
    return std::tuple(w.letter, w.value, w.hasPoint, w.kind, w.corner, w.length, w.offset);
  };
  for (std::size_t k = 0; k < a.size(); ++k)
    if (fields(a[k]) != fields(b[k]))
      return ::testing::AssertionFailure() << "word " << k << " at offset " << a[k].offset << " differs";
  return ::testing::AssertionSuccess();
}

TEST(parser_test, words_keep_offset_line_and_column) {
  SourceFile src("p.nc", "%\nO1234\nN10 G01X10.5Y-2.5 (cut)\n  g2 x1 y2 i3 j4;comment\n%\nG01 X99\n");
  Diagnostics d;
  const Program p = parse(src, d);
  EXPECT_FALSE(d.hasErrors());
  ASSERT_EQ(p.blocks.size(), 3u);  // O1234, N10..., g2...; the text after the closing % is ignored
  WordReader reader(p);
  const auto words = reader.words(p.blocks[1]);
  ASSERT_EQ(words.size(), 4u);
  EXPECT_EQ(words[2].letter, 'X');
  EXPECT_DOUBLE_EQ(words[2].value, 10.5);
  const SourceLocation loc = src.locate(words[2].offset);
  EXPECT_EQ(loc.line, 3u);
  EXPECT_EQ(loc.column, 8u);
  EXPECT_EQ(words[3].value, -2.5);
  // Lower-case letters are read as upper case; the text itself is untouched.
  const auto lower = p.wordsOf(p.blocks[2]);
  EXPECT_EQ(lower[0].letter, 'G');
  EXPECT_EQ(src.text().substr(lower[0].offset, 2), "g2");
}

TEST(parser_test, numbers_are_correctly_rounded) {
  SourceFile src("p.nc", "X0.1 Y-000000.1300 I123456.789012 J.5 R5.\n");
  Diagnostics d;
  const Program p = parse(src, d);
  EXPECT_TRUE(p.words.empty());  // a plain block's words are kept apart (Program::plainWords)
  const std::vector<Word> words = allWords(p);
  ASSERT_EQ(words.size(), 5u);
  EXPECT_EQ(words[0].value, 0.1);
  EXPECT_EQ(words[1].value, -0.13);
  EXPECT_EQ(words[2].value, 123456.789012);
  EXPECT_EQ(words[3].value, 0.5);
  EXPECT_TRUE(words[4].hasPoint);
  EXPECT_EQ(words[4].value, 5.0);
}

// The drawing and curve readers' numbers: one finite number with blanks around it, nothing else.
TEST(parser_test, a_number_field_is_one_finite_number) {
  double v = 0;
  EXPECT_TRUE(parseNumberField("  +12.5\t\r", v));
  EXPECT_EQ(v, 12.5);
  EXPECT_TRUE(parseNumberField("-1e-3", v));
  EXPECT_EQ(v, -0.001);
  for (const char* bad : {"", "  ", "+", "1.5 2", "1,5", "++1", "0x10", "inf", "nan", "1e999"})
    EXPECT_FALSE(parseNumberField(bad, v)) << "'" << bad << "'";
}

TEST(parser_test, numbers_agree_with_strtod_up_to_15_significant_digits) {
  // Random numbers in the forms the scanner treats apart: signs, leading zeros before and after
  // the point, no integer part, no fraction, a bare point; strtod (correctly rounded) is the oracle.
  std::mt19937 rng(20261124);
  auto digits = [&](int n, bool firstNonZero) {
    std::string t;
    for (int k = 0; k < n; ++k) t += static_cast<char>('0' + (k == 0 && firstNonZero ? 1 + rng() % 9 : rng() % 10));
    return t;
  };
  std::string text;
  std::vector<std::string> written;
  for (int trial = 0; trial < 4000; ++trial) {
    std::string number = std::string(rng() % 3 == 0 ? "-" : rng() % 5 == 0 ? "+" : "") + std::string(rng() % 3, '0');
    const int whole = static_cast<int>(rng() % 8), places = static_cast<int>(rng() % 8);
    number += digits(whole, true);
    if (rng() % 4 != 0) number += "." + std::string(rng() % 3, '0') + digits(places, false);
    if (number.find_first_of("0123456789") == std::string::npos) number += "7";
    written.push_back(number);
    text += "X" + number + "\n";
  }
  SourceFile src("p.nc", text);
  Diagnostics d;
  const Program p = parse(src, d);
  EXPECT_FALSE(d.hasErrors());
  const std::vector<Word> words = allWords(p);
  ASSERT_EQ(words.size(), written.size());
  for (std::size_t k = 0; k < written.size(); ++k) {
    EXPECT_EQ(words[k].value, std::strtod(written[k].c_str(), nullptr)) << written[k];
    EXPECT_EQ(words[k].hasPoint, written[k].find('.') != std::string::npos) << written[k];
  }
}

TEST(parser_test, settings_are_kept_verbatim) {
  SourceFile src("p.nc", "H001 = +000000.1300;\nC000 = 001 002 003 ;\nE001= 1 2\nG01 X1.\n");
  Diagnostics d;
  const Program p = parse(src, d);
  EXPECT_FALSE(d.hasErrors());
  ASSERT_EQ(p.settings.size(), 3u);
  EXPECT_EQ(p.settings[0].name, "H001");
  EXPECT_EQ(p.settings[0].value, "+000000.1300");
  EXPECT_EQ(p.settings[1].value, "001 002 003");
  EXPECT_EQ(p.settings[2].name, "E001");
  EXPECT_EQ(p.blocks.size(), 1u);
}

TEST(parser_test, block_delete_is_marked) {
  SourceFile src("p.nc", "/G01 X1.\nG01 X2.\n");
  Diagnostics d;
  const Program p = parse(src, d);
  ASSERT_EQ(p.blocks.size(), 2u);
  EXPECT_TRUE(p.blocks[0].blockDelete);
  EXPECT_FALSE(p.blocks[1].blockDelete);
}

TEST(parser_test, crlf_lines_and_spaces_between_letter_and_number) {
  SourceFile src("p.nc", "G01 X 10.\r\nY 5.\r\n");
  Diagnostics d;
  const Program p = parse(src, d);
  EXPECT_FALSE(d.hasErrors());
  const std::vector<Word> words = allWords(p);
  ASSERT_EQ(words.size(), 3u);
  EXPECT_EQ(words[1].value, 10.0);
  EXPECT_EQ(src.lineText(1), "G01 X 10.");
}

TEST(parser_test, integer_statistics_for_the_micrometre_warning) {
  SourceFile src("p.nc", "G92 X115000 Y-10000\nG01 X-9900 Y0\n");
  Diagnostics d;
  const Program p = parse(src, d);
  EXPECT_FALSE(p.anyDecimalPoint);
  EXPECT_EQ(p.largestInteger, 115000.0);
}

TEST(parser_test, one_error_per_block_and_parsing_goes_on) {
  SourceFile src("p.nc", "G01 X1,5 Y$ Z%\nG01 X2.\nG01 Y1e5\n");
  Diagnostics d;
  const Program p = parse(src, d);
  EXPECT_EQ(d.errorCount(), 2u);
  ASSERT_EQ(p.blocks.size(), 3u);
  EXPECT_TRUE(p.blocks[0].hasError);
  EXPECT_FALSE(p.blocks[1].hasError);
}

TEST(parser_test, a_line_longer_than_a_block_holds_is_an_error_and_not_read) {
  // A block's length is 16 bits (Block::kMaxLength): a longer line is reported at its first
  // character too many and not read; the lines around it are read as usual. One character less
  // is read.
  std::string line = "G01";
  while (line.size() <= Block::kMaxLength) line += " G01";
  SourceFile src("p.nc", "G01 X1.\n" + line + "\nG01 X2.\n");
  Diagnostics d;
  const Program p = parse(src, d);
  ASSERT_EQ(d.errorCount(), 1u);
  EXPECT_EQ(d.all().front().code, Code::BlockTooLong);
  EXPECT_EQ(src.locate(d.all().front().span.offset).line, 2u);
  EXPECT_EQ(src.locate(d.all().front().span.offset).column, Block::kMaxLength + 1);
  ASSERT_EQ(p.blocks.size(), 2u);
  EXPECT_EQ(p.lineOf(p.blocks[1]), 3u);
  EXPECT_EQ(WordReader(p).words(p.blocks[1])[1].letter, 'X');

  std::string fits = "G01";
  while (fits.size() < Block::kMaxLength) fits += " G01";  // 3 + 4k characters: 65,535 at k = 16,383
  ASSERT_EQ(fits.size(), Block::kMaxLength);
  SourceFile fitting("q.nc", fits + "\n");
  Diagnostics fd;
  const Program q = parse(fitting, fd);
  EXPECT_EQ(fd.errorCount(), 0u) << (fd.all().empty() ? "" : fd.all().front().message);
  ASSERT_EQ(q.blocks.size(), 1u);
  EXPECT_EQ(q.blocks[0].length, Block::kMaxLength);
}

TEST(diagnostics_test, long_lines_are_shown_as_a_window_around_the_column) {
  const std::string line = "G01 X1. (" + std::string(5000, 'a') + ") B5";
  SourceFile src("p.nc", line + "\n");
  Diagnostics d;
  parseProgram(src, d);
  ASSERT_EQ(d.errorCount(), 1u);
  const std::string text = formatDiagnostic(d.all()[0]);
  EXPECT_LT(text.size(), 400u);
  EXPECT_NE(text.find("...aaaa"), std::string::npos);
  // The caret still sits under the B.
  const auto lines = [&] {
    std::vector<std::string> v;
    std::size_t at = 0;
    for (std::size_t nl; (nl = text.find('\n', at)) != std::string::npos; at = nl + 1)
      v.push_back(text.substr(at, nl - at));
    return v;
  }();
  ASSERT_GE(lines.size(), 3u);
  EXPECT_EQ(lines[1][lines[2].find('^')], 'B');
}

TEST(parser_test, random_bytes_never_crash_and_always_terminate) {
  std::mt19937 rng(99);
  std::uniform_int_distribution<int> byte(0, 255), len(0, 400);
  for (int i = 0; i < 2000; ++i) {
    std::string text(static_cast<std::size_t>(len(rng)), '\0');
    for (char& c : text) c = static_cast<char>(byte(rng));
    auto r = kerf::test::run(text, {}, true);
    // Every diagnostic points inside the text and says something; every move is finite.
    for (const auto& d : r->diags.all()) {
      EXPECT_FALSE(d.message.empty());
      if (!d.span.isWholeFile()) {
        EXPECT_LE(d.span.offset + d.span.length, text.size());
      }
    }
    for (const auto& m : r->path().moves) {
      EXPECT_TRUE(m.lower.start.allFinite());
      EXPECT_TRUE(m.lower.end.allFinite());
    }
  }
}

TEST(parser_test, upper_side_of_a_4_axis_block) {
  // xyuv-abs: the upper side starts at a second motion word after a coordinate, or at U/V; its
  // I J may repeat the lower side's.
  SourceFile src("p.nc",
                 "G2 X10. Y5. I5. J0 G2 U10. V5. I5. J0\nG1 X1. U2. V3.\nG01 X1. : G02 X2. Y0 I1. J0\nG1 X1.\n");
  Diagnostics d;
  const Program p = parse(src, d);
  EXPECT_FALSE(d.hasErrors());
  ASSERT_EQ(p.blocks.size(), 4u);
  EXPECT_EQ(p.blocks[0].upperFrom, 5u);
  WordReader reader(p);
  EXPECT_EQ(reader.upperWords(p.blocks[0]).front().letter, 'G');
  EXPECT_EQ(p.blocks[1].upperFrom, 2u);
  EXPECT_TRUE(p.blocks[2].colon);
  EXPECT_EQ(p.blocks[2].upperFrom, 2u);
  EXPECT_EQ(reader.upperWords(p.blocks[2]).size(), 5u);
  EXPECT_EQ(p.blocks[3].upperFrom, p.blocks[3].wordCount);  // no upper side
}

TEST(parser_test, repeats_on_one_side_and_a_second_colon_are_errors) {
  SourceFile src("p.nc", "G1 X1. X2.\nG1 X1. : X2. : X3.\n");
  Diagnostics d;
  parse(src, d);
  ASSERT_EQ(d.errorCount(), 2u);
  EXPECT_EQ(d.all()[0].code, Code::RepeatedWord);
  EXPECT_EQ(src.locate(d.all()[1].span.offset).column, 14u);
}

TEST(parser_test, plane_heights_outside_the_words) {
  SourceFile src("p.nc", "TN5. TP25.\n(AXIS,XY_Z_POS,0)\n( axis, uv_z_pos, 40.5 )\n(AXIS,UV_Z_POS,abc)\n");
  Diagnostics d;
  const Program p = parse(src, d);
  ASSERT_EQ(p.heights.size(), 4u);
  EXPECT_EQ(p.heights[0].kind, HeightWord::Kind::SodickLowerPlane);
  EXPECT_EQ(p.heights[0].value, 5.0);
  EXPECT_EQ(p.heights[1].kind, HeightWord::Kind::SodickProgramPlane);
  EXPECT_EQ(p.heights[1].value, 25.0);
  EXPECT_EQ(p.heights[3].kind, HeightWord::Kind::LinuxCncUvPlane);
  EXPECT_EQ(p.heights[3].value, 40.5);
  ASSERT_EQ(d.errorCount(), 1u);  // the height that is not a number, at its comment
  EXPECT_EQ(src.locate(d.all()[0].span.offset).line, 4u);
}

}  // namespace

namespace {

using kerf::converter::BlockKind;
using kerf::converter::ParseOptions;
using kerf::converter::WordValue;

std::string lettersOf(const Program& p, const kerf::converter::Block& b, bool upperSide) {
  std::string out;
  WordReader reader(p);
  for (const auto& w : upperSide ? reader.upperWords(b) : reader.lowerWords(b)) out += w.letter;
  return out;
}

}  // namespace

TEST(parser_test, lines_end_at_lf_cr_lf_or_a_lone_cr) {
  for (const char* text :
       {"G1 X1.\nG1 Y2.\nM2\n", "G1 X1.\r\nG1 Y2.\r\nM2\r\n", "G1 X1.\rG1 Y2.\rM2\r", "G1 X1.\nG1 Y2.\nM2"}) {
    SourceFile src("p.nc", text);
    Diagnostics d;
    const Program p = parse(src, d);
    EXPECT_FALSE(d.hasErrors());
    ASSERT_EQ(p.blocks.size(), 3u) << text;
    EXPECT_EQ(p.lineOf(p.blocks[2]), 3u);
    EXPECT_EQ(src.lineText(2), "G1 Y2.");
  }
}

TEST(parser_test, the_line_of_an_offset_is_the_same_with_any_hint) {
  // SourceFile::lineOf(offset, hint) tries the hint's line and the next first (the interpreter asks
  // in order): from any hint — none, stale, past the end, behind or ahead — it answers locate's
  // line and leaves the hint there. Empty lines, a last line without a break, and every break.
  for (const char* text : {"G1 X1.\n\nG1 Y2.\r\n\r\nM2", "a\rb\r\rc\n", "\n\n\n", "G1 X1."}) {
    const SourceFile src("p.nc", text);
    const auto size = static_cast<std::uint32_t>(src.text().size());
    for (std::uint32_t offset = 0; offset < size; ++offset) {
      const std::uint32_t line = src.locate(offset).line;
      EXPECT_EQ(src.lineOf(offset), line);
      for (std::uint32_t start = 0; start <= src.lineCount() + 2; ++start) {
        std::uint32_t hint = start;
        EXPECT_EQ(src.lineOf(offset, hint), line) << text << " offset " << offset << " hint " << start;
        EXPECT_EQ(hint, line);
      }
    }
  }
}

TEST(parser_test, a_byte_order_mark_is_not_part_of_the_program) {
  SourceFile src("p.nc", "\xEF\xBB\xBFG1 X1.\nM2\n");
  Diagnostics d;
  const Program p = parse(src, d);
  EXPECT_FALSE(d.hasErrors());
  ASSERT_EQ(p.blocks.size(), 2u);
  const std::vector<Word> words = allWords(p);
  EXPECT_EQ(words.front().letter, 'G');
  EXPECT_EQ(src.locate(words.front().offset).column, 4u);  // columns still count the file's bytes
}

TEST(parser_test, single_motion_blocks_take_any_word_order) {
  // RS274 gives word order no meaning: U V belong to the upper side wherever they stand; a second
  // I J goes with them (cnc3's `G2 X Y I J U V I J`).
  SourceFile src("p.nc", "X10. U11. Y5. V6. G1\nG2 X1. Y0 I1. J0 U2. V0 I2. J0\nG1 X10. Y15. G2 U15. V-5. R10.\n");
  Diagnostics d;
  const Program p = parse(src, d);
  EXPECT_FALSE(d.hasErrors());
  ASSERT_EQ(p.blocks.size(), 3u);
  EXPECT_EQ(lettersOf(p, p.blocks[0], false), "XYG");
  EXPECT_EQ(lettersOf(p, p.blocks[0], true), "UV");
  EXPECT_FALSE(p.blocks[0].twoMotions);
  EXPECT_EQ(lettersOf(p, p.blocks[1], false), "GXYIJ");
  EXPECT_EQ(lettersOf(p, p.blocks[1], true), "UVIJ");
  EXPECT_TRUE(p.blocks[2].twoMotions);
  EXPECT_EQ(lettersOf(p, p.blocks[2], true), "GUVR");
}

TEST(parser_test, values_known_only_at_the_machine) {
  SourceFile src("p.nc", "G28 X Y U V\nG80 Y+\nG00 XH111 + H112 Y-H113\nG01 X#100 Y[#1 + 2.5]\n");
  Diagnostics d;
  const Program p = parse(src, d);
  EXPECT_FALSE(d.hasErrors()) << kerf::test::dump(d);
  WordReader reader(p);
  auto kindOf = [&](std::size_t block, char letter) {
    for (const auto& w : reader.words(p.blocks[block]))
      if (w.letter == letter) return w.kind;
    return WordValue::Number;
  };
  EXPECT_EQ(kindOf(0, 'X'), WordValue::Bare);
  EXPECT_EQ(kindOf(0, 'V'), WordValue::Bare);
  EXPECT_EQ(kindOf(1, 'Y'), WordValue::Direction);
  EXPECT_EQ(kindOf(2, 'X'), WordValue::Register);
  EXPECT_EQ(kindOf(2, 'Y'), WordValue::Register);
  EXPECT_EQ(kindOf(3, 'X'), WordValue::Macro);
  EXPECT_EQ(kindOf(3, 'Y'), WordValue::Macro);
  // Outside G28 / G30 a letter alone is still an error.
  SourceFile bare("b.nc", "G01 X Y\n");
  Diagnostics e;
  parse(bare, e);
  ASSERT_TRUE(e.hasErrors());
  EXPECT_EQ(e.all()[0].code, Code::ExpectedNumber);
}

TEST(parser_test, sodick_calls_and_macro_b_are_statements_not_syntax_errors) {
  SourceFile src("p.nc",
                 "QAIC(2,1,0.1250,001.0);\nQ99()LH114;\n#100 = 0\nWHILE[#100 LT 2]DO1\n#100 = #100 + 1\nEND1\n"
                 "IF [#1 EQ 0] GOTO 10\nG01 X1.\n");
  Diagnostics d;
  const Program p = parse(src, d);
  ASSERT_EQ(p.blocks.size(), 8u);
  EXPECT_EQ(p.blocks[0].kind, BlockKind::MacroCall);
  EXPECT_EQ(p.blocks[1].kind, BlockKind::MacroCall);
  for (int k = 2; k < 7; ++k) EXPECT_EQ(p.blocks[static_cast<std::size_t>(k)].kind, BlockKind::MacroB) << k;
  EXPECT_EQ(p.blocks[7].kind, BlockKind::Words);
  // One diagnostic for all five macro lines, at the first.
  ASSERT_EQ(d.errorCount(), 1u);
  EXPECT_EQ(d.all()[0].code, Code::MacroStatement);
  EXPECT_EQ(src.locate(d.all()[0].span.offset).line, 3u);
  EXPECT_NE(d.all()[0].message.find("5 macro lines, on lines 3 to 7"), std::string::npos) << d.all()[0].message;
}

TEST(parser_test, a_decimal_comma_says_which_number_it_probably_means) {
  SourceFile src("p.nc", "G01 X10. F12,9285\n");
  Diagnostics d;
  parse(src, d);
  ASSERT_EQ(d.errorCount(), 1u);
  EXPECT_EQ(d.all()[0].code, Code::DecimalComma);
  EXPECT_EQ(d.all()[0].help, "did you mean F12.9285?");
}

TEST(parser_test, a_semicolon_ends_the_block_where_the_profile_says_so) {
  const char* text = "G01 X1.; G01 X2.;\nG01 X3.; a remark\n";
  SourceFile src("p.nc", text);
  Diagnostics d;
  EXPECT_EQ(parse(src, d).blocks.size(), 2u);  // ';' starts a comment
  ParseOptions sodick;
  sodick.semicolonEndsBlock = true;
  Diagnostics e;
  const Program p = kerf::converter::parseProgram(src, e, sodick);
  EXPECT_FALSE(e.hasErrors()) << kerf::test::dump(e);
  EXPECT_EQ(p.blocks.size(), 3u);  // ';' ends blocks; a remark after it stays a remark
}

TEST(parser_test, the_second_plane_named_u_z_is_read_as_u_v_only_when_asked) {
  SourceFile src("p.nc", "G01 X1. U2. Y3. Z4.\n");
  ParseOptions uz;
  uz.upperAxesUZ = true;
  Diagnostics d;
  const Program p = kerf::converter::parseProgram(src, d, uz);
  EXPECT_EQ(lettersOf(p, p.blocks[0], true), "UV");
  Diagnostics e;
  const Program plain = parse(src, e);
  EXPECT_EQ(lettersOf(plain, plain.blocks[0], true), "U");
}

TEST(parser_test, a_percent_line_opens_the_program_and_a_later_one_closes_it) {
  const std::string body = "G01 X1. Y2.\nG01 X3.\n";
  const std::vector<std::tuple<std::string, std::string, std::size_t>> texts = {
      {"words only", body, 2},
      {"opened by %", "%\n" + body, 2},
      {"closed by %: what follows is not read", "%\n" + body + "%\nG01 X$\nG01 Y1.\n", 2},
      {"blank lines, then %", "\n\n%\n" + body + "%\nG01 X$\n", 2},
      {"a % line alone", "\n%\n", 0},
  };
  for (const auto& [what, text, blocks] : texts) {
    const SourceFile src("p.nc", text);
    Diagnostics d;
    const Program p = parseProgram(src, d);
    EXPECT_EQ(p.blocks.size(), blocks) << what;
    EXPECT_EQ(d.errorCount(), 0u) << what;
  }
}

TEST(source_test, lines_start_after_every_line_feed_wherever_it_falls_in_a_word) {
  // Texts of random lengths (not multiples of 8), line feeds anywhere (first byte, last byte,
  // runs of them), bytes around the line feed's (0x0A) and with the top bit set: the line starts
  // are exactly the bytes after each line feed.
  std::mt19937 rng(7);
  const char alphabet[] = {'\n', '\n', 'G', '1', ' ', '\x0B', '\x09', '\x8A', '\x0A', '\xFF', '\x00', 'X'};
  std::uniform_int_distribution<int> pick(0, sizeof alphabet - 1), length(0, 300);
  for (int trial = 0; trial < 400; ++trial) {
    std::string text(static_cast<std::size_t>(length(rng)), ' ');
    for (char& c : text) c = alphabet[pick(rng)];
    std::vector<std::uint32_t> starts{0};
    for (std::size_t i = 0; i < text.size(); ++i)
      if (text[i] == '\n') starts.push_back(static_cast<std::uint32_t>(i + 1));
    const SourceFile src("t.nc", text);
    ASSERT_EQ(src.lineCount(), starts.size()) << "trial " << trial;
    for (std::uint32_t line = 1; line <= starts.size(); ++line)
      ASSERT_EQ(src.lineRange(line).first, starts[line - 1]) << "trial " << trial << " line " << line;
  }
  // A long text of feeds alone: one start after every byte.
  {
    const std::string feeds((std::size_t{1} << 20) + 3, '\n');
    const SourceFile src("feeds.nc", feeds);
    ASSERT_EQ(src.lineCount(), feeds.size() + 1);
    for (const std::uint32_t line : {1u, 2u, 777u, static_cast<std::uint32_t>(feeds.size() + 1)})
      EXPECT_EQ(src.lineRange(line).first, line - 1) << line;
  }
  // Texts of several MiB: runs of feeds, a tail after the last whole word, a feed at the end.
  for (const std::size_t size : {std::size_t{3} << 20, (std::size_t{5} << 20) + 7}) {
    std::string text(size, 'X');
    std::uniform_int_distribution<std::size_t> at(0, size - 1);
    for (int k = 0; k < 20000; ++k) text[at(rng)] = '\n';
    for (std::size_t run : {size / 3, 2 * size / 3}) text.replace(run - 4, 9, 9, '\n');
    text[size - 1] = '\n';
    std::vector<std::uint32_t> starts{0};
    for (std::size_t i = 0; i < text.size(); ++i)
      if (text[i] == '\n') starts.push_back(static_cast<std::uint32_t>(i + 1));
    const SourceFile src("big.nc", text);
    ASSERT_EQ(src.lineCount(), starts.size()) << size;
    for (std::uint32_t line = 1; line <= starts.size(); ++line)
      ASSERT_EQ(src.lineRange(line).first, starts[line - 1]) << size << " line " << line;
  }
  // A carriage return far into a long text: CR LF ends one line, a lone CR one too.
  std::string text(std::size_t{3} << 20, 'X');
  for (std::size_t at = 1000; at < text.size(); at += 997) text[at] = '\n';
  text.replace(std::size_t{5} << 19, 2, "\r\n");
  text[(std::size_t{11} << 18) + 1] = '\r';
  std::vector<std::uint32_t> starts{0};
  for (std::size_t i = 0; i < text.size(); ++i)
    if (text[i] == '\n' || (text[i] == '\r' && text[i + 1] != '\n'))
      starts.push_back(static_cast<std::uint32_t>(i + 1));
  const SourceFile src("crlf.nc", text);
  ASSERT_EQ(src.lineCount(), starts.size());
  for (std::uint32_t line = 1; line <= starts.size(); ++line)
    ASSERT_EQ(src.lineRange(line).first, starts[line - 1]) << "line " << line;
}

// Block::plain marks the blocks the whole-program scans may pass by: motion codes G00-G03 and X Y
// I J R F only, numbers, upper case, one side.
TEST(parser_test, plain_blocks_hold_only_motion_codes_and_coordinates) {
  Diagnostics d;
  const SourceFile src("p.nc",
                       "G01 X1. Y2.\nG2 X3 Y4 I1 J0 F100\nX5 R2\nN10 G01 X1\ng01 x1\nG01 X1 : U1\nG92 X0 Y0\n"
                       "G01 X#100\nG1.5 X1\nG04 X1\nM02\nG01 X1 V2\nG3 X1 Y1 I1 J1 G1 U1 V1\nT1 X1\n");
  const Program p = parseProgram(src, d);
  const std::vector<bool> expected = {true,  true,  true,  false, false, false, false,
                                      false, false, false, false, false, false, false};
  ASSERT_EQ(p.blocks.size(), expected.size());
  for (std::size_t k = 0; k < expected.size(); ++k)
    EXPECT_EQ(p.blocks[k].plain, expected[k]) << "line " << p.lineOf(p.blocks[k]);
}

// Program::notPlain lists the blocks that are not plain, in order, which the scans for evidence,
// labels and calls go through instead of every block.
TEST(parser_test, the_blocks_that_are_not_plain_are_listed_in_order) {
  std::mt19937 rng(99);
  std::string text = "%\nO1 (long)\nG90 G21\n";
  for (int line = 0; line < 40000; ++line) {
    switch (rng() % 9) {
      case 0: text += "G92 X0 Y0\n"; break;
      case 1: text += "N" + std::to_string(line) + " G01 X1\n"; break;
      case 2: text += "M00\n"; break;
      case 3: text += "(comment only)\n"; break;
      default: text += "G01 X" + std::to_string(rng() % 1000) + ".5 Y-" + std::to_string(rng() % 1000) + ".25\n";
    }
  }
  text += "M02\n%\n";
  ASSERT_GT(text.size(), std::size_t{400} << 10);
  Diagnostics d;
  const SourceFile src("long.nc", text);
  const Program p = parseProgram(src, d);
  std::vector<std::uint32_t> expected;
  for (std::size_t k = 0; k < p.blocks.size(); ++k)
    if (!p.blocks[k].plain) expected.push_back(static_cast<std::uint32_t>(k));
  EXPECT_GT(expected.size(), 10000u);
  EXPECT_LT(expected.size(), p.blocks.size() - 10000);
  EXPECT_EQ(p.notPlain, expected);
}

namespace {

std::string readAll(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace

// The parse keeps a plain block's words apart (Program::plainWords), whichever road read it, and
// WordReader parses the block again where they were given back. Over every sample and real
// program, each plain block's words, as kept and as parsed again, equal the words the parser makes
// of the same text when the block is not plain (an M word added at its end).
TEST(parser_test, plain_blocks_read_again_as_the_parse_read_them) {
  namespace fs = std::filesystem;
  std::vector<fs::path> files;
  const fs::path realworld = kerf::test::realworldDir();
  for (const fs::path& folder :
       {fs::path(KERF_SAMPLES_DIR), realworld / "iso2d", realworld / "xyuv", realworld / "polar"})
    if (fs::is_directory(folder))
      for (const auto& f : fs::directory_iterator(folder))
        if (f.is_regular_file() && f.path().extension() != ".dxf") files.push_back(f.path());
  std::size_t checked = 0;
  for (const fs::path& file : files) {
    SourceFile src(file.string(), readAll(file));
    Diagnostics d;
    const Program p = parse(src, d);
    WordReader reader(p);
    const std::vector<Word> kept = allWords(p);
    p.plainWords.giveBackBefore(std::numeric_limits<std::uint32_t>::max());
    ASSERT_TRUE(sameWords(allWords(p), kept)) << file << ": the words parsed again and those kept";
    for (const Block& b : p.blocks) {
      if (!b.plain) continue;
      const std::string text = std::string(p.textOf(b)) + " M0";
      SourceFile alone("block.nc", text);
      Diagnostics ad;
      const Program q = parse(alone, ad);
      ASSERT_EQ(q.blocks.size(), 1u) << file << ":" << p.lineOf(b);
      ASSERT_FALSE(q.blocks[0].plain);
      const auto again = reader.words(b);
      const auto parsed = q.wordsOf(q.blocks[0]);
      ASSERT_EQ(again.size() + 1, parsed.size()) << file << ":" << p.lineOf(b);
      for (std::size_t k = 0; k < again.size(); ++k) {
        EXPECT_EQ(again[k].letter, parsed[k].letter) << file << ":" << p.lineOf(b);
        EXPECT_EQ(again[k].value, parsed[k].value) << file << ":" << p.lineOf(b);
        EXPECT_EQ(again[k].hasPoint, parsed[k].hasPoint) << file << ":" << p.lineOf(b);
        EXPECT_EQ(again[k].kind, parsed[k].kind) << file << ":" << p.lineOf(b);
        EXPECT_EQ(again[k].length, parsed[k].length) << file << ":" << p.lineOf(b);
        EXPECT_EQ(again[k].offset - b.offset, parsed[k].offset) << file << ":" << p.lineOf(b);
        // A G word of a plain block names G00-G03 and carries its code (the table's first four:
        // 1 + the number), on both roads.
        const unsigned code = again[k].letter == 'G' ? static_cast<unsigned>(parsed[k].value) + 1 : 0U;
        EXPECT_EQ(again[k].motionCode, code) << file << ":" << p.lineOf(b);
        EXPECT_EQ(parsed[k].motionCode, code) << file << ":" << p.lineOf(b);
      }
      ++checked;
    }
  }
  KERF_NEEDS_CORPUS();  // the samples were checked; the count below is the corpus's
  EXPECT_GT(checked, 1000u) << "too few plain blocks to hold the reader to the parse";
}

// A word's value is the double nearest its decimal: the parser's short conversion (whole digits
// over a power of ten) and std::from_chars agree on numbers of every length, point position and
// sign, up to 18 digits before the point and 25 after.
TEST(parser_test, numbers_convert_as_from_chars_converts_them) {
  std::mt19937_64 rng(2026);
  std::string text;
  std::vector<std::string> numbers;
  for (int k = 0; k < 20000; ++k) {
    const int before = static_cast<int>(rng() % 10);  // K0105 refuses 10 and more
    const int after = static_cast<int>(rng() % 26);
    std::string n;
    for (int d = 0; d < before; ++d) n += static_cast<char>('0' + rng() % 10);
    if (after > 0 || rng() % 2 == 0) n += '.';
    for (int d = 0; d < after; ++d) n += static_cast<char>('0' + (rng() % 4 == 0 ? 9 : rng() % 10));
    if (n.find_first_of("0123456789") == std::string::npos) n += '5';
    numbers.push_back(n);
    text += (rng() % 2 ? "G01 X-" : "G01 X") + n + " M0\n";  // not plain: the parse converts
    text += (rng() % 2 ? "Y-" : "Y") + n + "\n";             // plain: the short road converts
  }
  Diagnostics d;
  const SourceFile src("numbers.nc", text);
  const Program p = parse(src, d);
  ASSERT_FALSE(d.hasErrors()) << d.all().front().message;
  const std::vector<Word> words = allWords(p);
  std::size_t compared = 0;
  for (const Word& w : words) {
    if (w.letter != 'X' && w.letter != 'Y') continue;
    const std::string_view written = src.text().substr(w.offset + 1, w.length - 1);
    const bool negative = written.front() == '-';
    std::string digits(negative ? written.substr(1) : written);
    if (digits.back() == '.') digits.pop_back();
    double expected = 0.0;
    std::from_chars(digits.data(), digits.data() + digits.size(), expected, std::chars_format::fixed);
    if (negative) expected = -expected;
    ASSERT_EQ(w.value, expected) << written;
    ++compared;
  }
  EXPECT_EQ(compared, 2 * numbers.size());
  // The plain blocks' words, kept by the parse, and parsed again once given back.
  EXPECT_NE(p.plainWords.find(p.blocks.back().firstWord), nullptr);
  p.plainWords.giveBackBefore(std::numeric_limits<std::uint32_t>::max());
  EXPECT_EQ(p.plainWords.find(p.blocks.back().firstWord), nullptr);
  EXPECT_TRUE(sameWords(allWords(p), words));
}

namespace {

/// The text with " (c)" at the end of every line: a comment the parser's short road for plain
/// blocks does not take, so every block goes through the word loop.
std::string withCommentOnEveryLine(const std::string& text) {
  std::string out;
  std::size_t from = 0;
  while (from < text.size()) {
    const std::size_t nl = text.find('\n', from);
    const std::size_t to = nl == std::string::npos ? text.size() : nl;
    out += text.substr(from, to - from) + " (c)\n";
    from = to + 1;
  }
  return out;
}

}  // namespace

// The short road for plain blocks and the word loop read a block the same: the same blocks, words,
// evidence and diagnostics, over random near-plain lines (letters in and out of the plain set,
// lower case, signs, points, exponents, commas, repeated words, a second motion word, ';').
TEST(parser_test, the_short_road_for_plain_blocks_reads_as_the_word_loop) {
  const std::string pieces[] = {"G01", "G1",   "G02", "G3", "G4",  "G0",   "G-1", "G1.",  "X",   "Y",
                                "I",   "J",    "R",   "F",  "U",   "x",    "M",   "1",    "-2.", "+.5",
                                "12",  "0.25", ".",   "e3", ",5",  "9999", "1e",  " ",    " ",   " ",
                                ";",   "G",    "-",   "Z",  "X1.", "Y-3",  "I.5", "J0.0", "R-2", "F100"};
  for (const bool semicolonEndsBlock : {false, true}) {
    std::mt19937 rng(semicolonEndsBlock ? 7 : 8);
    std::string text;
    for (int line = 0; line < 20000; ++line) {
      const int n = 1 + static_cast<int>(rng() % 8);
      for (int k = 0; k < n; ++k) text += pieces[rng() % std::size(pieces)];
      text += '\n';
    }
    ParseOptions options;
    options.semicolonEndsBlock = semicolonEndsBlock;
    const SourceFile fast("fast.nc", text);
    const SourceFile loop("loop.nc", withCommentOnEveryLine(text));
    Diagnostics fd, ld;
    const Program fp = parseProgram(fast, fd, options);
    const Program lp = parseProgram(loop, ld, options);
    // The comment adds a block of its own after a ';' that ends blocks, and lengthens the last
    // block of a line: compare the blocks with words.
    auto withWords = [](const Program& p) {
      std::vector<Block> out;
      for (const Block& b : p.blocks)
        if (b.wordCount > 0 || b.hasError) out.push_back(b);
      return out;
    };
    const std::vector<Block> fb = withWords(fp), lb = withWords(lp);
    ASSERT_EQ(fb.size(), lb.size());
    WordReader fr(fp), lr(lp);
    std::size_t plain = 0;
    for (std::size_t k = 0; k < fb.size(); ++k) {
      const Block &a = fb[k], &b = lb[k];
      const std::uint32_t aLine = fast.lineRange(fp.lineOf(a)).first, bLine = loop.lineRange(lp.lineOf(b)).first;
      ASSERT_EQ(fp.lineOf(a), lp.lineOf(b));
      EXPECT_EQ(a.offset - aLine, b.offset - bLine) << "line " << fp.lineOf(a);
      EXPECT_EQ(a.plain, b.plain) << "line " << fp.lineOf(a);
      EXPECT_EQ(a.hasError, b.hasError) << "line " << fp.lineOf(a);
      EXPECT_EQ(a.wordCount, b.wordCount) << "line " << fp.lineOf(a);
      EXPECT_EQ(a.upperFrom, b.upperFrom) << "line " << fp.lineOf(a);
      const std::string_view aText = fp.textOf(a), bText = lp.textOf(b);
      EXPECT_EQ(aText, bText.substr(0, aText.size())) << "line " << fp.lineOf(a);
      plain += a.plain;
      const auto aw = fr.words(a);
      const std::vector<Word> awCopy(aw.begin(), aw.end());
      const auto bw = lr.words(b);
      ASSERT_EQ(awCopy.size(), bw.size()) << "line " << fp.lineOf(a);
      for (std::size_t w = 0; w < bw.size(); ++w) {
        EXPECT_EQ(awCopy[w].letter, bw[w].letter) << "line " << fp.lineOf(a);
        EXPECT_EQ(awCopy[w].value, bw[w].value) << "line " << fp.lineOf(a);
        EXPECT_EQ(awCopy[w].offset - aLine, bw[w].offset - bLine) << "line " << fp.lineOf(a);
      }
    }
    EXPECT_GT(plain, 1000u);
    EXPECT_LT(plain, fb.size() - 1000);
    EXPECT_EQ(fp.anyDecimalPoint, lp.anyDecimalPoint);
    EXPECT_EQ(fp.integerLengthWords, lp.integerLengthWords);
    EXPECT_EQ(fp.largestInteger, lp.largestInteger);
    EXPECT_EQ(fp.largestIntegerWord.letter, lp.largestIntegerWord.letter);
    EXPECT_EQ(fp.largestIntegerWord.value, lp.largestIntegerWord.value);
    EXPECT_EQ(fp.largestIntegerWord.length, lp.largestIntegerWord.length);
    // The codes (a message may name what it read next: the end of the line, or the comment).
    ASSERT_EQ(fd.all().size(), ld.all().size());
    for (std::size_t k = 0; k < fd.all().size(); ++k) EXPECT_EQ(fd.all()[k].code, ld.all()[k].code);
  }
}
