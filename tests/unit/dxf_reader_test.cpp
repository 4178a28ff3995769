// The DXF reader (converter/formats/dxf/read_dxf.h) on small drawings whose geometry is known by hand: bulges and
// their direction, the object coordinate system of a mirrored arc, INSERT transforms, binary DXF
// and its truncation. The real drawings are compared with ezdxf in tests/data/dxf_test.cpp.
#include "kerf/converter/formats/dxf/read_dxf.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

using namespace kerf::converter;
using kerf::geometry::kPi;
using kerf::geometry::Vec2;

namespace {

std::string ascii(const std::string& entities, const std::string& blocks = {}) {
  std::string s = "0\nSECTION\n2\nHEADER\n9\n$INSUNITS\n70\n4\n0\nENDSEC\n";
  if (!blocks.empty()) s += "0\nSECTION\n2\nBLOCKS\n" + blocks + "0\nENDSEC\n";
  return s + "0\nSECTION\n2\nENTITIES\n" + entities + "0\nENDSEC\n0\nEOF\n";
}

Drawing read(const std::string& text, Diagnostics& diags) {
  static std::vector<std::unique_ptr<SourceFile>> keep;  // diagnostics point into the source
  keep.push_back(std::make_unique<SourceFile>("t.dxf", text));
  return readDxf(*keep.back(), DxfOptions{}, diags);
}

TEST(dxf_reader_test, a_positive_bulge_is_a_counter_clockwise_arc_from_its_own_vertex) {
  Diagnostics d(100);
  // (0,0) with bulge 1 to (10,0): counter-clockwise about (5,0), so through (5,-5); closed back
  // with the last vertex's bulge, 0: a half disc of radius 5.
  const Drawing g = read(ascii("0\nLWPOLYLINE\n8\n0\n90\n2\n70\n1\n10\n0\n20\n0\n42\n1\n10\n10\n20\n0\n"), d);
  ASSERT_TRUE(g.ok);
  ASSERT_EQ(g.elements.size(), 2u);
  const auto& arc = g.elements[0].segment;
  ASSERT_TRUE(arc.isArc());
  EXPECT_NEAR(arc.centre.x(), 5, 1e-12);
  EXPECT_NEAR(arc.sweep, kPi, 1e-12);
  EXPECT_NEAR(arc.pointAt(0.5).y(), -5, 1e-9);
  EXPECT_FALSE(g.elements[1].segment.isArc());  // the closing segment takes the last vertex's bulge, 0
  std::vector<kerf::geometry::Segment> path{g.elements[0].segment, g.elements[1].segment};
  EXPECT_NEAR(kerf::geometry::signedArea(path), 12.5 * kPi, 1e-9);
}

TEST(dxf_reader_test, a_negative_bulge_is_clockwise_and_a_bulge_over_one_takes_the_long_way) {
  Diagnostics d(100);
  const Drawing g = read(ascii("0\nLWPOLYLINE\n8\n0\n90\n2\n70\n0\n10\n0\n20\n0\n42\n-2\n10\n10\n20\n0\n"), d);
  ASSERT_EQ(g.elements.size(), 1u);
  const auto& arc = g.elements[0].segment;
  EXPECT_LT(arc.sweep, 0);
  EXPECT_NEAR(std::abs(arc.sweep), 4 * std::atan(2.0), 1e-12);  // more than a half circle
  EXPECT_NEAR((arc.start - Vec2(0, 0)).norm(), 0, 1e-12);
  EXPECT_NEAR((arc.end - Vec2(10, 0)).norm(), 0, 1e-9);
}

TEST(dxf_reader_test, an_arc_with_a_downward_extrusion_is_mirrored_and_clockwise) {
  Diagnostics d(100);
  const Drawing g = read(ascii("0\nARC\n8\n0\n10\n5\n20\n0\n40\n2\n50\n0\n51\n90\n210\n0\n220\n0\n230\n-1\n"), d);
  ASSERT_EQ(g.elements.size(), 1u);
  const auto& arc = g.elements[0].segment;
  EXPECT_NEAR(arc.centre.x(), -5, 1e-12);  // OCS x is world -X
  EXPECT_LT(arc.sweep, 0);
  EXPECT_NEAR((arc.start - Vec2(-7, 0)).norm(), 0, 1e-12);
  EXPECT_NEAR((arc.end - Vec2(-5, 2)).norm(), 0, 1e-9);
}

TEST(dxf_reader_test, inserts_scale_rotate_mirror_and_nest) {
  Diagnostics d(100);
  const std::string blocks =
      "0\nBLOCK\n2\nB\n10\n1\n20\n0\n0\nLINE\n8\n0\n10\n1\n20\n0\n11\n2\n21\n0\n0\nENDBLK\n"
      "0\nBLOCK\n2\nOUTER\n10\n0\n20\n0\n0\nINSERT\n2\nB\n10\n0\n20\n0\n41\n3\n42\n3\n0\nENDBLK\n";
  // OUTER at (10, 0) turned 90 degrees and mirrored in x: B's line (1,0)-(2,0), less its base,
  // scaled by 3 is (0,0)-(3,0); mirrored (0,0)-(-3,0); turned (0,0)-(0,-3); moved (10,0)-(10,-3).
  const Drawing g = read(ascii("0\nINSERT\n8\n0\n2\nOUTER\n10\n10\n20\n0\n41\n-1\n42\n1\n50\n90\n", blocks), d);
  ASSERT_EQ(g.elements.size(), 1u) << d.all().size();
  EXPECT_NEAR((g.elements[0].segment.start - Vec2(10, 0)).norm(), 0, 1e-9);
  EXPECT_NEAR((g.elements[0].segment.end - Vec2(10, -3)).norm(), 0, 1e-9);
  EXPECT_EQ(g.entities.at("INSERT"), 1u);
}

TEST(dxf_reader_test, text_and_dimensions_are_counted_as_skipped) {
  Diagnostics d(100);
  const Drawing g = read(ascii("0\nTEXT\n8\n0\n1\nhello\n0\nLINE\n8\n0\n10\n0\n20\n0\n11\n1\n21\n0\n"), d);
  EXPECT_EQ(g.skipped.at("TEXT"), 1u);
  EXPECT_EQ(g.elements.size(), 1u);
}

std::string binaryLine(bool truncate) {
  std::string b(kBinaryDxfSentinel);
  auto code = [&](int c) {
    b.push_back(static_cast<char>(c & 0xff));
    b.push_back(static_cast<char>(c >> 8));
  };
  auto str = [&](int c, const char* s) {
    code(c);
    b += s;
    b.push_back('\0');
  };
  auto num = [&](int c, double v) {
    code(c);
    char raw[8];
    std::memcpy(raw, &v, 8);
    b.append(raw, 8);
  };
  str(0, "SECTION");
  str(2, "ENTITIES");
  str(0, "LINE");
  str(8, "0");
  num(10, 1.5);
  num(20, 2.5);
  num(11, 4.5);
  num(21, 6.5);
  str(0, "ENDSEC");
  str(0, "EOF");
  if (truncate) b.resize(b.size() - 20);  // ENDSEC and EOF (15 bytes) gone, and 5 of the end point's y
  return b;
}

TEST(dxf_reader_test, binary_dxf_reads_as_its_ascii_twin) {
  Diagnostics d(100);
  const Drawing g = read(binaryLine(false), d);
  ASSERT_TRUE(g.binary);
  ASSERT_EQ(g.elements.size(), 1u);
  EXPECT_EQ(g.elements[0].segment.start, Vec2(1.5, 2.5));
  EXPECT_EQ(g.elements[0].segment.end, Vec2(4.5, 6.5));
  EXPECT_FALSE(d.hasErrors());
}

TEST(dxf_reader_test, a_truncated_binary_dxf_is_an_error_at_its_byte_offset) {
  Diagnostics d(100);
  const Drawing g = read(binaryLine(true), d);
  EXPECT_FALSE(g.ok);
  ASSERT_TRUE(d.hasErrors());
  const Diagnostic& e = d.all().front();
  EXPECT_EQ(e.code, Code::DxfSyntax);
  EXPECT_NE(e.message.find("at byte "), std::string::npos) << e.message;
  EXPECT_NE(e.message.find("group code 21"), std::string::npos) << e.message;
}

}  // namespace

// Angles of any size are reduced in closed form (issue 41: `while (a1 <= a0) a1 += 2 pi` never ended
// for a start angle of 1e20): an ARC from 1e20 degrees (reduced to one turn, exactly) to 10, one
// from 350 to 370 (20 degrees through 0) and an ELLIPSE whose start parameter is 1e300 each read
// at once, as arcs of a sweep in (0, 2 pi].
TEST(dxf_reader_test, huge_angles_are_reduced_without_a_loop) {
  Diagnostics d(100);
  const Drawing g = read(ascii("0\nARC\n8\n0\n10\n0\n20\n0\n40\n5\n50\n1e20\n51\n10\n"
                               "0\nARC\n8\n0\n10\n0\n20\n0\n40\n5\n50\n350\n51\n370\n"
                               "0\nELLIPSE\n8\n0\n10\n0\n20\n0\n11\n5\n21\n0\n40\n0.5\n41\n1e300\n42\n6.28\n"),
                         d);
  ASSERT_TRUE(g.ok);
  ASSERT_GE(g.elements.size(), 3u);
  const auto& first = g.elements[0].segment;
  ASSERT_TRUE(first.isArc());
  EXPECT_GT(first.sweep, 0.0);
  EXPECT_LE(first.sweep, 2 * kPi);
  const double start = std::fmod(std::fmod(1e20, 360.0) * kPi / 180, 2 * kPi);  // where DXF says it starts
  EXPECT_NEAR(first.start.x(), 5 * std::cos(start), 1e-9);
  const auto& second = g.elements[1].segment;
  EXPECT_NEAR(second.sweep, 20 * kPi / 180, 1e-12);  // 350 to 370: 20 degrees through 0
}

// A file whose lines end in a lone CR (old Mac editors) is a DXF file like any other (issue 41: it
// was read as G-code, 200 errors).
TEST(dxf_reader_test, lines_may_end_in_a_lone_carriage_return) {
  std::string text = ascii("0\nLINE\n8\n0\n10\n0\n20\n0\n11\n10\n21\n0\n");
  for (char& c : text)
    if (c == '\n') c = '\r';
  EXPECT_TRUE(looksLikeDxf(text));
  Diagnostics d(100);
  const Drawing g = read(text, d);
  ASSERT_TRUE(g.ok);
  ASSERT_EQ(g.elements.size(), 1u);
  EXPECT_NEAR(g.elements[0].segment.end.x(), 10, 1e-12);
}
