#include "kerf/converter/program.h"
#include "kerf/geometry/memory.h"

#include "converter_support.h"
#include "parse_compare.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <optional>
#include <random>
#include <string>
#include <vector>

using namespace kerf::converter;

namespace {

Program parse(const SourceFile& src, Diagnostics& d) { return parseProgram(src, d); }

TEST(parser, words_keep_offset_line_and_column) {
  SourceFile src("p.nc", "%\nO1234\nN10 G01X10.5Y-2.5 (cut)\n  g2 x1 y2 i3 j4;comment\n%\nG01 X99\n");
  Diagnostics d;
  const Program p = parse(src, d);
  EXPECT_FALSE(d.hasErrors());
  ASSERT_EQ(p.blocks.size(), 3u);  // O1234, N10..., g2...; the text after the closing % is ignored
  const auto words = p.wordsOf(p.blocks[1]);
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

TEST(parser, numbers_are_correctly_rounded) {
  SourceFile src("p.nc", "X0.1 Y-000000.1300 I123456.789012 J.5 R5.\n");
  Diagnostics d;
  const Program p = parse(src, d);
  ASSERT_EQ(p.words.size(), 5u);
  EXPECT_EQ(p.words[0].value, 0.1);
  EXPECT_EQ(p.words[1].value, -0.13);
  EXPECT_EQ(p.words[2].value, 123456.789012);
  EXPECT_EQ(p.words[3].value, 0.5);
  EXPECT_TRUE(p.words[4].hasPoint);
  EXPECT_EQ(p.words[4].value, 5.0);
}

TEST(parser, numbers_agree_with_strtod_up_to_15_significant_digits) {
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
  ASSERT_EQ(p.words.size(), written.size());
  for (std::size_t k = 0; k < written.size(); ++k) {
    EXPECT_EQ(p.words[k].value, std::strtod(written[k].c_str(), nullptr)) << written[k];
    EXPECT_EQ(p.words[k].hasPoint, written[k].find('.') != std::string::npos) << written[k];
  }
}

TEST(parser, settings_are_kept_verbatim) {
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

TEST(parser, block_delete_is_marked) {
  SourceFile src("p.nc", "/G01 X1.\nG01 X2.\n");
  Diagnostics d;
  const Program p = parse(src, d);
  ASSERT_EQ(p.blocks.size(), 2u);
  EXPECT_TRUE(p.blocks[0].blockDelete);
  EXPECT_FALSE(p.blocks[1].blockDelete);
}

TEST(parser, crlf_lines_and_spaces_between_letter_and_number) {
  SourceFile src("p.nc", "G01 X 10.\r\nY 5.\r\n");
  Diagnostics d;
  const Program p = parse(src, d);
  EXPECT_FALSE(d.hasErrors());
  ASSERT_EQ(p.words.size(), 3u);
  EXPECT_EQ(p.words[1].value, 10.0);
  EXPECT_EQ(src.lineText(1), "G01 X 10.");
}

TEST(parser, integer_statistics_for_the_micrometre_warning) {
  SourceFile src("p.nc", "G92 X115000 Y-10000\nG01 X-9900 Y0\n");
  Diagnostics d;
  const Program p = parse(src, d);
  EXPECT_FALSE(p.anyDecimalPoint);
  EXPECT_EQ(p.largestInteger, 115000.0);
}

TEST(parser, one_error_per_block_and_parsing_goes_on) {
  SourceFile src("p.nc", "G01 X1,5 Y$ Z%\nG01 X2.\nG01 Y1e5\n");
  Diagnostics d;
  const Program p = parse(src, d);
  EXPECT_EQ(d.errorCount(), 2u);
  ASSERT_EQ(p.blocks.size(), 3u);
  EXPECT_TRUE(p.blocks[0].hasError);
  EXPECT_FALSE(p.blocks[1].hasError);
}

TEST(parser, a_block_of_more_words_than_a_block_holds_is_an_error_at_the_first_word_too_many) {
  // A block holds Block::kMaxWords words (16-bit counts): the word after them is reported, the
  // block keeps the ones before it, and the next line is read as usual.
  std::string line = "G01";
  for (std::size_t k = 1; k < Block::kMaxWords + 10; ++k) line += " G01";
  SourceFile src("p.nc", line + "\nG01 X2.\n");
  Diagnostics d;
  const Program p = parse(src, d);
  ASSERT_EQ(d.errorCount(), 1u);
  EXPECT_EQ(d.all().front().code, Code::BlockTooLong);
  EXPECT_EQ(d.all().front().span.offset, 4 * Block::kMaxWords);  // "G01 " a word
  ASSERT_EQ(p.blocks.size(), 2u);
  EXPECT_EQ(p.blocks[0].wordCount, Block::kMaxWords);
  EXPECT_TRUE(p.blocks[0].hasError);
  EXPECT_EQ(p.blocks[1].wordCount, 2u);
  EXPECT_EQ(p.wordsOf(p.blocks[1])[1].letter, 'X');
}

TEST(diagnostics, long_lines_are_shown_as_a_window_around_the_column) {
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

TEST(parser, random_bytes_never_crash_and_always_terminate) {
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

TEST(parser, upper_side_of_a_4_axis_block) {
  // xyuv-abs: the upper side starts at a second motion word after a coordinate, or at U/V; its
  // I J may repeat the lower side's.
  SourceFile src("p.nc",
                 "G2 X10. Y5. I5. J0 G2 U10. V5. I5. J0\nG1 X1. U2. V3.\nG01 X1. : G02 X2. Y0 I1. J0\nG1 X1.\n");
  Diagnostics d;
  const Program p = parse(src, d);
  EXPECT_FALSE(d.hasErrors());
  ASSERT_EQ(p.blocks.size(), 4u);
  EXPECT_EQ(p.blocks[0].upperFrom, 5u);
  EXPECT_EQ(p.upperWordsOf(p.blocks[0]).front().letter, 'G');
  EXPECT_EQ(p.blocks[1].upperFrom, 2u);
  EXPECT_TRUE(p.blocks[2].colon);
  EXPECT_EQ(p.blocks[2].upperFrom, 2u);
  EXPECT_EQ(p.upperWordsOf(p.blocks[2]).size(), 5u);
  EXPECT_EQ(p.blocks[3].upperFrom, p.blocks[3].wordCount);  // no upper side
}

TEST(parser, repeats_on_one_side_and_a_second_colon_are_errors) {
  SourceFile src("p.nc", "G1 X1. X2.\nG1 X1. : X2. : X3.\n");
  Diagnostics d;
  parse(src, d);
  ASSERT_EQ(d.errorCount(), 2u);
  EXPECT_EQ(d.all()[0].code, Code::RepeatedWord);
  EXPECT_EQ(src.locate(d.all()[1].span.offset).column, 14u);
}

TEST(parser, plane_heights_outside_the_words) {
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
  for (const auto& w : upperSide ? p.upperWordsOf(b) : p.lowerWordsOf(b)) out += w.letter;
  return out;
}

}  // namespace

TEST(parser, lines_end_at_lf_cr_lf_or_a_lone_cr) {
  for (const char* text :
       {"G1 X1.\nG1 Y2.\nM2\n", "G1 X1.\r\nG1 Y2.\r\nM2\r\n", "G1 X1.\rG1 Y2.\rM2\r", "G1 X1.\nG1 Y2.\nM2"}) {
    SourceFile src("p.nc", text);
    Diagnostics d;
    const Program p = parse(src, d);
    EXPECT_FALSE(d.hasErrors());
    ASSERT_EQ(p.blocks.size(), 3u) << text;
    EXPECT_EQ(p.blocks[2].line, 3u);
    EXPECT_EQ(src.lineText(2), "G1 Y2.");
  }
}

TEST(source, a_released_text_is_read_again_and_a_changed_one_gives_blank_lines) {
  const std::string text = "G1 X1.\r\nG1 Y2.\r\nM2\r\n";
  std::string onDisk = text;  // what reading again gives
  int reads = 0;
  const SourceFile::TextSource readAgain = [&]() -> std::optional<std::string> {
    ++reads;
    return onDisk;
  };
  {
    SourceFile src("p.nc", text);
    src.releaseText(readAgain);
    EXPECT_TRUE(src.released());
    EXPECT_EQ(src.locate(9).line, 2u);  // positions without reading again
    EXPECT_EQ(src.lineCount(), 4u);
    EXPECT_EQ(reads, 0);
    EXPECT_EQ(src.lineText(2), "G1 Y2.");  // read again, once
    EXPECT_EQ(src.text(), text);
    EXPECT_EQ(reads, 1);
    EXPECT_FALSE(src.released());
    EXPECT_FALSE(src.changedOnDisk());
  }
  for (const std::optional<std::string>& changed :
       {std::optional<std::string>("G1 X1.\r\nG1 Y3.\r\nM2\r\n"), std::optional<std::string>("G1 X1.\n"),
        std::optional<std::string>()}) {  // other bytes of the same size, another size, unreadable
    SourceFile src("p.nc", text);
    src.releaseText([&changed]() { return changed; });
    EXPECT_EQ(src.lineText(2), std::string(7, ' '));  // the old length, blank (the CR turned blank)
    EXPECT_TRUE(src.changedOnDisk());
    EXPECT_EQ(src.lineText(3), "   ");
    EXPECT_EQ(src.locate(9).column, 2u);
    // A diagnostic says so rather than quote a blank line.
    Diagnostics d;
    d.error(Code::UnknownGCode, &src, SourceSpan{8, 2}, "unknown G code G1", "a help");
    EXPECT_EQ(formatDiagnostic(d.all()[0]),
              "p.nc:2:1: error: unknown G code G1 [K0201]\n"
              "    (the file changed after it was read: its line is not quoted)\n    help: a help\n");
  }
}

TEST(parser, a_byte_order_mark_is_not_part_of_the_program) {
  SourceFile src("p.nc", "\xEF\xBB\xBFG1 X1.\nM2\n");
  Diagnostics d;
  const Program p = parse(src, d);
  EXPECT_FALSE(d.hasErrors());
  ASSERT_EQ(p.blocks.size(), 2u);
  EXPECT_EQ(p.words.front().letter, 'G');
  EXPECT_EQ(src.locate(p.words.front().offset).column, 4u);  // columns still count the file's bytes
}

TEST(parser, single_motion_blocks_take_any_word_order) {
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

TEST(parser, values_known_only_at_the_machine) {
  SourceFile src("p.nc", "G28 X Y U V\nG80 Y+\nG00 XH111 + H112 Y-H113\nG01 X#100 Y[#1 + 2.5]\n");
  Diagnostics d;
  const Program p = parse(src, d);
  EXPECT_FALSE(d.hasErrors()) << kerf::test::dump(d);
  auto kindOf = [&](std::size_t block, char letter) {
    for (const auto& w : p.wordsOf(p.blocks[block]))
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

TEST(parser, sodick_calls_and_macro_b_are_statements_not_syntax_errors) {
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

TEST(parser, a_decimal_comma_says_which_number_it_probably_means) {
  SourceFile src("p.nc", "G01 X10. F12,9285\n");
  Diagnostics d;
  parse(src, d);
  ASSERT_EQ(d.errorCount(), 1u);
  EXPECT_EQ(d.all()[0].code, Code::DecimalComma);
  EXPECT_EQ(d.all()[0].help, "did you mean F12.9285?");
}

TEST(parser, a_semicolon_ends_the_block_where_the_profile_says_so) {
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

TEST(parser, the_second_plane_named_u_z_is_read_as_u_v_only_when_asked) {
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

namespace {

/// A long text of every kind of line the parser reads: words, upper sides, settings, plane heights,
/// macro statements, syntax errors, integers without a point, comments, blank lines and CR LF ends.
std::string mixedProgram(std::size_t lines, unsigned seed) {
  std::mt19937 rng(seed);
  std::string text;
  for (std::size_t k = 0; k < lines; ++k) {
    const auto pick = rng() % 20;
    const std::string n = std::to_string(rng() % 100000);
    switch (pick) {
      case 0: text += "H" + std::to_string(rng() % 1000) + " = +000000." + n + ";\n"; break;
      case 1: text += "TP" + n + ".5 TN1.\n"; break;
      case 2: text += "#" + std::to_string(rng() % 200) + " = " + n + "\n"; break;
      case 3: text += "G01 X1.$ Y2.\n"; break;                                            // a syntax error
      case 4: text += "G01 X" + n + " Y" + std::to_string(rng() % 900000) + "\n"; break;  // integers
      case 5: text += "(comment " + n + ")\n"; break;
      case 6: text += "\n"; break;
      case 7: text += "G02 X" + n + ". Y1.5 I-2. J0 : U1. V2.\r\n"; break;
      case 8: text += "G01 X1. X2.\n"; break;  // a repeated word
      default: text += "N" + n + " G01 X" + n + ".25 Y-" + n + ".5 F2.\n"; break;
    }
  }
  return text;
}

void expectSameProgram(const Program& a, const Program& b, const std::string& what) {
  EXPECT_EQ(kerf::test::parseDifference(a, b), "") << what;
}

void expectSameDiagnostics(const Diagnostics& a, const Diagnostics& b, const std::string& what) {
  EXPECT_EQ(a.errorCount(), b.errorCount()) << what;
  EXPECT_EQ(a.warningCount(), b.warningCount()) << what;
  EXPECT_EQ(a.dropped(), b.dropped()) << what;
  ASSERT_EQ(a.all().size(), b.all().size()) << what;
  for (std::size_t k = 0; k < a.all().size(); ++k) {
    const Diagnostic &x = a.all()[k], &y = b.all()[k];
    EXPECT_TRUE(x.code == y.code && x.span.offset == y.span.offset && x.message == y.message)
        << what << ": diagnostic " << k << ": " << x.message << " | " << y.message;
  }
}

TEST(parser, parts_parsed_on_several_cores_give_what_one_pass_gives) {
  // Long texts are parsed in parts, one per worker, and joined. What the join must get right: word
  // indices, the statistics of integers, the macro count and its lines, the diagnostics in order
  // (and those past the cap counted), and the '%' frame, whichever part its lines fall in.
  const std::string body = mixedProgram(60000, 7);  // about 1.3 MB
  const std::string head(400000, '\n');             // blank lines: the first part holds no block
  const std::size_t middle = body.find('\n', body.size() * 2 / 3) + 1;
  const std::vector<std::pair<std::string, std::string>> texts = {
      {"words only", body},
      {"opened by %", "%\n" + body},
      {"closed by % in a later part", "%\n" + body.substr(0, middle) + "%\n" + body.substr(middle)},
      {"nothing before a later part's %", head + "%\n" + body + "%\nG01 X1 Y$\n"},
      {"a % line alone in a later part", head + "%\n"},
  };
  for (const auto& [what, text] : texts) {
    ASSERT_GT(text.size(), 256u * 1024u) << what << ": long enough to be parsed in parts";
    const SourceFile src("p.nc", text);
    // The parts write their blocks in place unless ';' ends blocks (a line may then hold several):
    // both ways.
    for (const bool semicolonEndsBlock : {false, true})
      for (const std::size_t cap : {std::size_t{5}, std::size_t{100000}}) {
        ParseOptions options;
        options.semicolonEndsBlock = semicolonEndsBlock;
        Program serial;
        Diagnostics serialDiags(cap);
        {
          const kerf::test::ScopedThreads one("1");
          serial = parseProgram(src, serialDiags, options);
        }
        for (const char* threads : {"2", "3", "8"}) {
          const kerf::test::ScopedThreads t(threads);
          Diagnostics d(cap);
          const Program parts = parseProgram(src, d, options);
          const std::string label = what + ", " + threads + " threads, cap " + std::to_string(cap) +
                                    (semicolonEndsBlock ? ", ';' ends blocks" : "");
          expectSameProgram(serial, parts, label);
          expectSameDiagnostics(serialDiags, d, label);
        }
      }
    if (what == "closed by % in a later part") {  // the blocks after the closing % are not read
      Diagnostics d;
      const Program p = parseProgram(src, d);
      ASSERT_FALSE(p.blocks.empty());
      EXPECT_LT(p.blocks.back().offset, 2 + middle);
      EXPECT_GT(p.blocks.back().offset, middle / 2);
    }
  }
}

}  // namespace

// The bytes a SourceFile keeps: a copy of a string, or written in place by a reader; either way a
// NUL follows the last byte, as in a std::string, and a SourceFile reads them the same.
TEST(source, text_bytes_written_in_place_read_as_the_same_text) {
  const std::string text = "G1 X1.\nG2 X2. Y0 R1.\r\nM2";
  const TextBytes copied(text);
  EXPECT_EQ(copied.view(), text);
  EXPECT_EQ(copied.data()[copied.size()], '\0');
  TextBytes written = TextBytes::ofSize(text.size() + 5);
  std::copy(text.begin(), text.end(), written.writable());
  written.shrink(text.size());  // the file was shorter than its size said
  EXPECT_EQ(written.view(), text);
  EXPECT_EQ(written.data()[written.size()], '\0');
  const SourceFile a("a.nc", copied), b("b.nc", std::move(written));
  ASSERT_EQ(a.lineCount(), 3u);
  ASSERT_EQ(b.lineCount(), 3u);
  for (std::uint32_t line = 1; line <= 3; ++line) EXPECT_EQ(a.lineText(line), b.lineText(line));
  EXPECT_EQ(b.lineText(2), "G2 X2. Y0 R1.");
  EXPECT_EQ(TextBytes().size(), 0u);
  EXPECT_EQ(TextBytes().data()[0], '\0');
}

// The text's hash (source.cpp) reads it in pieces of 1 MiB, each in four lanes of 8 bytes, then
// 8 bytes, then the tail: a change of one byte in any of them, and only a change, is seen when the
// text is read again.
TEST(source, a_change_of_one_byte_anywhere_in_a_long_text_is_seen) {
  auto programOf = [](std::size_t bytes) {
    std::string text;
    for (int k = 0; text.size() < bytes; ++k) text += "G1 X" + std::to_string(k) + ".5\n";
    return text;
  };
  auto seenChanged = [](const std::string& read, const std::string& onDisk) {
    SourceFile src("p.nc", read);
    src.releaseText([&onDisk]() -> std::optional<std::string> { return onDisk; });
    (void)src.lineText(1);
    return src.changedOnDisk();
  };
  const std::string text = programOf(1000) + "M2\n";  // 1000 and more bytes: not a multiple of 32, nor of 8
  ASSERT_NE(text.size() % 8, 0u);
  EXPECT_FALSE(seenChanged(text, text));
  for (std::size_t at = 0; at < text.size(); ++at) {
    std::string changed = text;
    changed[at] = changed[at] == 'X' ? 'Y' : 'X';
    ASSERT_TRUE(seenChanged(text, changed)) << "byte " << at;
  }
  // A text of several pieces: a byte changed in each piece, at its ends and inside, and two pieces
  // swapped, are seen.
  const std::string longText = programOf((std::size_t{3} << 20) + 77);
  EXPECT_FALSE(seenChanged(longText, longText));
  constexpr std::size_t kMiB = std::size_t{1} << 20;
  for (const std::size_t at : {std::size_t{0}, kMiB - 1, kMiB, 2 * kMiB + 5, longText.size() - 1}) {
    std::string changed = longText;
    changed[at] = changed[at] == '1' ? '2' : '1';
    EXPECT_TRUE(seenChanged(longText, changed)) << "byte " << at;
  }
  const std::string swapped = longText.substr(kMiB, kMiB) + longText.substr(0, kMiB) + longText.substr(2 * kMiB);
  ASSERT_EQ(swapped.size(), longText.size());
  EXPECT_TRUE(seenChanged(longText, swapped));
}

TEST(source, lines_start_after_every_line_feed_wherever_it_falls_in_a_word) {
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
  // A long text of feeds alone: one start after every byte, the most the one pass over a text of
  // 1 MiB and more makes room for.
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
  // A carriage return in a later MiB (the starts are found a MiB at a time): CR LF ends one line,
  // a lone CR one too.
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
TEST(parser, plain_blocks_hold_only_motion_codes_and_coordinates) {
  Diagnostics d;
  const SourceFile src("p.nc",
                       "G01 X1. Y2.\nG2 X3 Y4 I1 J0 F100\nX5 R2\nN10 G01 X1\ng01 x1\nG01 X1 : U1\nG92 X0 Y0\n"
                       "G01 X#100\nG1.5 X1\nG04 X1\nM02\nG01 X1 V2\nG3 X1 Y1 I1 J1 G1 U1 V1\nT1 X1\n");
  const Program p = parseProgram(src, d);
  const std::vector<bool> expected = {true,  true,  true,  false, false, false, false,
                                      false, false, false, false, false, false, false};
  ASSERT_EQ(p.blocks.size(), expected.size());
  for (std::size_t k = 0; k < expected.size(); ++k)
    EXPECT_EQ(p.blocks[k].plain, expected[k]) << "line " << p.blocks[k].line;
}

// Lines of plain words are read a short way (parser.cpp, tryPlainLine): on lines near that form
// and not quite in it, it must give what the general way gives — words, blocks, settings and
// diagnostics alike.
TEST(parser, plain_lines_read_the_short_way_give_what_the_general_way_gives) {
  std::mt19937 rng(424242);
  const std::vector<std::string> letters = {"G", "X", "Y", "I", "J", "R", "F", "x", "U", "N", "M", "T", "Z", "H"};
  const std::vector<std::string> numbers = {
      "0",          "1",          "2",   "3",     "01",         "4",  "28",       "12.5",
      "-3.25",      "+7",         ".5",  "5.",    "0.0001",     "-0", "12345678", "1234567.1234567",
      "1.12345678", "1e3",        "1,5", "1.2.3", "2000000000", "",   "#1",       "H1",
      "3-4",        "999999999.9"};
  const std::vector<std::string> gaps = {" ", " ", " ", "  ", "\t", "", " ; x", " (c)", " =", ": "};
  std::string text;
  for (int line = 0; line < 3000; ++line) {
    const int words = 1 + static_cast<int>(rng() % 6);
    if (rng() % 20 == 0) text += "/";
    if (rng() % 25 == 0) text += "  ";
    for (int k = 0; k < words; ++k) {
      const bool plain = rng() % 4 != 0;
      text += letters[plain ? rng() % 7 : rng() % letters.size()];
      text += plain ? numbers[rng() % 14] : numbers[rng() % numbers.size()];
      if (k + 1 < words) text += plain ? " " : gaps[rng() % gaps.size()];
    }
    if (rng() % 10 == 0) text += "  ";
    text += rng() % 15 == 0 ? "\r\n" : "\n";
  }
  SourceFile src("p.nc", text);
  Diagnostics fastDiags(1000000), slowDiags(1000000);
  ParseOptions slowOptions;
  slowOptions.plainLines = false;
  const Program fast = parseProgram(src, fastDiags);
  const Program slow = parseProgram(src, slowDiags, slowOptions);
  ASSERT_EQ(fast.words.size(), slow.words.size());
  for (std::size_t k = 0; k < fast.words.size(); ++k) {
    const Word &a = fast.words[k], &b = slow.words[k];
    ASSERT_TRUE(a.letter == b.letter && a.offset == b.offset && a.length == b.length && a.kind == b.kind &&
                a.hasPoint == b.hasPoint && (a.value == b.value || (a.value != a.value && b.value != b.value)))
        << "word " << k << " on line " << src.locate(a.offset).line;
  }
  ASSERT_EQ(fast.blocks.size(), slow.blocks.size());
  std::size_t plain = 0;
  for (std::size_t k = 0; k < fast.blocks.size(); ++k) {
    const Block &a = fast.blocks[k], &b = slow.blocks[k];
    ASSERT_TRUE(a.firstWord == b.firstWord && a.offset == b.offset && a.length == b.length && a.line == b.line &&
                a.wordCount == b.wordCount && a.upperFrom == b.upperFrom && a.kind == b.kind && a.colon == b.colon &&
                a.twoMotions == b.twoMotions && a.blockDelete == b.blockDelete && a.hasError == b.hasError &&
                a.lowerCase == b.lowerCase && a.unusualValues == b.unusualValues && a.plain == b.plain)
        << "block on line " << a.line;
    plain += a.plain;
  }
  EXPECT_GT(plain, 500u);  // the short way was taken
  EXPECT_LT(plain, fast.blocks.size() - 500);
  EXPECT_EQ(fast.settings.size(), slow.settings.size());
  EXPECT_EQ(fast.anyDecimalPoint, slow.anyDecimalPoint);
  EXPECT_EQ(fast.integerLengthWords, slow.integerLengthWords);
  EXPECT_EQ(fast.largestInteger, slow.largestInteger);
  EXPECT_EQ(fast.largestIntegerWord, slow.largestIntegerWord);
  EXPECT_EQ(fast.notPlain, slow.notPlain);
  ASSERT_EQ(fastDiags.all().size(), slowDiags.all().size());
  for (std::size_t k = 0; k < fastDiags.all().size(); ++k)
    EXPECT_EQ(formatDiagnostic(fastDiags.all()[k]), formatDiagnostic(slowDiags.all()[k]));
}

// Program::notPlain lists the blocks that are not plain, in order, which the scans for evidence,
// labels and calls go through instead of every block: on a text long enough to be parsed in parts
// on every core, whatever the parts, and with no block left out where two parts join.
TEST(parser, the_blocks_that_are_not_plain_are_listed_in_order_across_the_parts) {
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

// A long program that runs straight through gives its parse tree back as the interpreter passes
// it (releaseParsedBefore), the first block's 2 MiB page with it (the moves take it in place of a
// fresh one): the first block is written back and reads as before, the blocks at and after the
// one named stay, and those between read as zeros where the pages are Kerf's own.
TEST(parser, the_parse_given_back_keeps_its_first_block_and_the_rest_from_there) {
  std::string text = "%\nO1 (first)\nG90 G21\n";
  for (int line = 0; line < 120000; ++line)
    text += "G01 X" + std::to_string(line % 997) + ".5 Y-" + std::to_string(line % 113) + ".25\n";
  text += "M02\n%\n";
  Diagnostics d;
  const SourceFile src("long.nc", text);
  const Program p = parseProgram(src, d);
  ASSERT_GT(p.blocks.size() * sizeof(Block), std::size_t{2} << 20);  // the first block's page is whole
  const std::size_t at = 100000;
  const Block first = p.blocks.front(), there = p.blocks[at], last = p.blocks.back();
  const std::string firstText(src.text().substr(first.offset, first.length));
  releaseParsedBefore(p, at);
  EXPECT_EQ(std::memcmp(&p.blocks.front(), &first, sizeof first), 0);
  EXPECT_EQ(src.text().substr(p.blocks.front().offset, p.blocks.front().length), firstText);
  EXPECT_EQ(std::memcmp(&p.blocks[at], &there, sizeof there), 0);
  EXPECT_EQ(std::memcmp(&p.blocks.back(), &last, sizeof last), 0);
  for (std::size_t k = at; k < at + 100; ++k)
    for (const Word& w : p.wordsOf(p.blocks[k])) EXPECT_TRUE(w.letter == 'G' || w.letter == 'X' || w.letter == 'Y');
  if (kerf::geometry::largePagesOwned()) {  // given back: read as zeros (the first 2 MiB page's second block)
    static const Block zero{};
    EXPECT_EQ(std::memcmp(&p.blocks[1], &zero, sizeof zero), 0);
  }
}
