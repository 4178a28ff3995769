// kerf::render, kerf::headless and kerf::export: camera, scene, pixels, PNG, the SSIM error, and
// mesh files read back with VTK's readers.
#include "kerf/converter/check/checks.h"
#include "kerf/converter/check/summary.h"
#include "kerf/converter/interpret/analysis.h"
#include "kerf/converter/structure/passes.h"
#include "kerf/export/mesh_export.h"
#include "kerf/headless/context.h"
#include "kerf/headless/png.h"
#include "kerf/render/gl.h"
#include "kerf/render/renderer.h"
#include "kerf/render/scene.h"
#include "ssim.h"

#include <gtest/gtest.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkPLYReader.h>
#include <vtkPolyData.h>
#include <vtkSTLReader.h>
#include <vtkXMLPolyDataReader.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>

namespace {

using namespace kerf;
using converter::Diagnostics;
using converter::SourceFile;

struct Part {
  std::unique_ptr<SourceFile> source;
  converter::Toolpath toolpath;
  std::unique_ptr<Diagnostics> diags;
};

Part analyse(const std::string& text, const converter::InterpreterOptions& options = {}) {
  Part p;
  p.source = std::make_unique<SourceFile>("part.nc", text);
  p.diags = std::make_unique<Diagnostics>(1000);
  p.toolpath = converter::analyse(*p.source, options, *p.diags).toolpath;
  const converter::SurfaceMeasures measures = converter::measureSurface(p.toolpath);
  converter::checkToolpath(p.toolpath, p.source.get(), converter::CheckOptions{}, *p.diags, &measures);
  return p;
}

// A 20 x 10 mm rectangle, counter-clockwise from the origin.
const char* kRectangle = "G90 G21\nG01 X20. Y0\nY10.\nX0\nY0\nM30\n";
// A frustum: a 20 mm square below, a 16 mm square above, 10 mm apart (xyuv-abs).
const char* kFrustum =
    "(AXIS,XY_Z_POS,0)\n(AXIS,UV_Z_POS,10)\nG90 G21\nG00 X-10. Y-10. U-8. V-8.\nG01 X10. U8.\nY10. V8.\nX-10. U-8.\n"
    "Y-10. V-8.\nM30\n";

TEST(render_camera_test, top_view_fits_the_box_with_the_margin) {
  const render::Camera c = render::fitCamera({0, 0, 0}, {20, 10, 2}, render::View::Top, 400, 200, 0.1);
  const Eigen::Vector2d lo = c.project({0, 0, 0}, 400, 200), hi = c.project({20, 10, 0}, 400, 200);
  // Top view: x to the right, y up (so down the image); the box fills the width less 2 x 10 %.
  EXPECT_NEAR(lo.x(), 400 * (1 - 1 / 1.2) / 2, 1e-6);
  EXPECT_NEAR(hi.x(), 400 - 400 * (1 - 1 / 1.2) / 2, 1e-6);
  EXPECT_GT(lo.y(), hi.y());
  EXPECT_NEAR(0.5 * (lo.y() + hi.y()), 100, 1e-6);
}

TEST(render_camera_test, iso_view_is_the_classic_isometric) {
  const render::Camera c = render::fitCamera({-1, -1, -1}, {1, 1, 1}, render::View::Iso, 100, 100);
  const geometry::Vec3 e = c.eyeDirection();
  EXPECT_NEAR(e.x(), 1 / std::sqrt(3.0), 1e-12);
  EXPECT_NEAR(e.y(), -1 / std::sqrt(3.0), 1e-12);
  EXPECT_NEAR(e.z(), 1 / std::sqrt(3.0), 1e-12);
  EXPECT_NEAR(c.up().dot(e), 0.0, 1e-12);
  EXPECT_NEAR(c.right().dot(e), 0.0, 1e-12);
  EXPECT_GT(c.up().z(), 0.0);  // z points up the picture
}

TEST(render_scene_test, two_axis_wall_faces_outwards_with_zero_slope) {
  const Part p = analyse(kRectangle);
  const render::Scene s = render::buildScene(p.toolpath, p.diags->all());
  ASSERT_GT(s.triangles(), 0u);
  EXPECT_FALSE(s.taper);
  EXPECT_NEAR(s.planes.height(), 0.08 * std::hypot(20.0, 10.0), 1e-9);
  for (const auto& v : s.surface) {
    EXPECT_NEAR(v.normal[2], 0.0f, 1e-6f);
    EXPECT_NEAR(v.slopeDegrees, 0.0f, 1e-6f);
    // Outward: the normal points away from the rectangle's centre (10, 5).
    const double out = (static_cast<double>(v.position[0]) - 10.0) * static_cast<double>(v.normal[0]) +
                       (static_cast<double>(v.position[1]) - 5.0) * static_cast<double>(v.normal[1]);
    EXPECT_GT(out, 0.0);
  }
  EXPECT_EQ(s.lower.moveFirst.size(), p.toolpath.moves.size() + 1);
  // Indexed: every index names a vertex, and a wall's two triangles share their vertices: four
  // per wall (each wall its own, so the corners stay sharp), not the six of unshared triangles.
  ASSERT_EQ(s.surfaceIndices.size(), 3 * s.triangles());
  EXPECT_EQ(s.triangleMove.size(), s.triangles());
  for (const std::uint32_t i : s.surfaceIndices) ASSERT_LT(i, s.surface.size());
  EXPECT_EQ(s.triangles(), 8u);
  EXPECT_EQ(s.surface.size(), 16u);
  EXPECT_NEAR(s.boundsMax.x(), 20.0, 1e-6);
  EXPECT_NEAR(s.boundsMax.y(), 10.0, 1e-6);
}

TEST(render_scene_test, moving_frames_merge_runs_of_moves_within_the_tolerance) {
  // A circle of radius 10 as 720 lines, then a square corner: with 0.05 mm the runs of lines merge
  // into chords (22 lines of 0.5° stay within 0.05 mm of theirs), the corner does not.
  std::string text = "G90 G21\nG92 X10. Y0\n";
  for (int k = 1; k <= 720; ++k) {
    const double a = k * geometry::kPi / 360;
    text += "G01 X" + std::to_string(10 * std::cos(a)) + " Y" + std::to_string(10 * std::sin(a)) + "\n";
  }
  text += "G01 X10. Y-5.\nX15. Y-5.\nM30\n";
  const Part p = analyse(text);
  const std::size_t n = p.toolpath.moves.size();
  render::SceneOptions fine, merged;
  merged.mergeTolerance = 0.05;
  merged.generators = fine.generators = 0;
  const render::Scene a = render::buildScene(p.toolpath, {}, fine);
  // A finding on a move inside a run flags the run's patch.
  converter::Diagnostic finding;
  finding.severity = converter::Severity::Error;
  finding.move = 100;
  const render::Scene b = render::buildScene(p.toolpath, std::span(&finding, 1), merged);
  EXPECT_EQ(a.triangles(), 2 * n);
  EXPECT_LT(b.triangles(), 2 * n / 10);
  EXPECT_GT(b.triangles(), 2 * 720 / 40);
  // Every move keeps its place in the lines (a run's chord at its first move, nothing inside).
  ASSERT_EQ(b.lower.moveFirst.size(), n + 1);
  std::size_t empty = 0;
  for (std::size_t m = 0; m < n; ++m) empty += b.lower.moveFirst[m] == b.lower.moveFirst[m + 1];
  EXPECT_GT(empty, n / 2);
  // The chords stay within the tolerance inside the circle; the corner's two lines are there.
  for (std::size_t v = 0; v + 4 < b.lower.vertices.size(); ++v) {
    const auto& q = b.lower.vertices[v].position;
    const double r = std::hypot(static_cast<double>(q[0]), static_cast<double>(q[1]));
    EXPECT_LE(r, 10.0 + 1e-5);
    EXPECT_GE(r, 10.0 - 0.05 - 1e-5);
  }
  EXPECT_EQ(b.lower.moveFirst[n] - b.lower.moveFirst[n - 2], 4u);
  std::size_t flaggedVertices = 0;
  for (const auto& v : b.surface) flaggedVertices += (v.flags & render::kOnFinding) != 0;
  EXPECT_EQ(flaggedVertices, 4u);  // one merged patch: two triangles, four vertices
  // With no tolerance nothing merges.
  EXPECT_EQ(render::displayRuns(p.toolpath, 0.0)[5], 6u);
}

TEST(render_scene_test, frustum_slope_is_the_taper) {
  const Part p = analyse(kFrustum);
  ASSERT_TRUE(p.toolpath.isTaper());
  const render::Scene s = render::buildScene(p.toolpath, p.diags->all());
  // Mid-side generators lean 2 mm over 10 mm; the corner ones 2 sqrt 2.
  EXPECT_NEAR(s.minSlopeDegrees, std::atan(0.2) * 180 / geometry::kPi, 1e-3);
  EXPECT_NEAR(s.maxSlopeDegrees, std::atan(0.2 * std::sqrt(2.0)) * 180 / geometry::kPi, 1e-3);
  EXPECT_DOUBLE_EQ(s.planes.upper, 10.0);
}

TEST(render_scene_test, findings_become_markers_and_flag_their_move) {
  // The path crosses itself: an error with a point.
  const Part p = analyse("G90 G21\nG01 X10. Y10.\nX10. Y0\nX0 Y10.\nX0 Y0\nM30\n");
  ASSERT_TRUE(p.diags->hasErrors());
  const render::Scene s = render::buildScene(p.toolpath, p.diags->all());
  ASSERT_FALSE(s.findings.empty());
  EXPECT_EQ(s.findings[0].severity, converter::Severity::Error);
  EXPECT_NE(s.findings[0].label.find("K0601"), std::string::npos);
  bool flagged = false;
  for (const auto& v : s.surface) flagged = flagged || (v.flags & render::kOnFinding);
  EXPECT_TRUE(flagged);
}

class headless_test : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string error;
    context_ = headless::createContext(headless::Backend::Auto, error);
    ASSERT_NE(context_, nullptr) << error;
  }
  std::unique_ptr<headless::Context> context_;
};

std::vector<std::uint8_t> drawTop(const render::Scene& scene, int w, int h, const render::RenderOptions& options) {
  render::Renderer r;
  render::OffscreenTarget t;
  std::string error;
  EXPECT_TRUE(r.init(error)) << error;
  EXPECT_TRUE(t.create(w, h, 1, error)) << error;
  r.setScene(scene);
  t.bind();
  r.render(render::fitCamera(scene.boundsMin, scene.boundsMax, render::View::Top, w, h), options, w, h);
  return t.readRgba();
}

TEST_F(headless_test, top_view_puts_the_contour_where_the_camera_says) {
  const Part p = analyse(kRectangle);
  const render::Scene s = render::buildScene(p.toolpath, p.diags->all());
  constexpr int w = 200, h = 120;
  render::RenderOptions o;
  o.triad = false;
  o.markers = false;
  const std::vector<std::uint8_t> px = drawTop(s, w, h, o);
  const render::Camera c = render::fitCamera(s.boundsMin, s.boundsMax, render::View::Top, w, h);
  auto at = [&](const Eigen::Vector2d& q) {
    const auto x = static_cast<std::size_t>(q.x()), y = static_cast<std::size_t>(q.y());
    return &px[(y * w + x) * 4];
  };
  // The middle of the bottom edge, seen from above: the upper contour's orange (200, 90, 20).
  const std::uint8_t* edge = at(c.project({10, 0, s.planes.upper}, w, h));
  EXPECT_EQ(edge[0], 200);
  EXPECT_EQ(edge[1], 90);
  EXPECT_EQ(edge[2], 20);
  // The rectangle's inside (seen from above, open) and outside are background.
  for (const geometry::Vec3& q : {geometry::Vec3(10, 5, 0), geometry::Vec3(-3, 5, 0)}) {
    const std::uint8_t* bg = at(c.project(q, w, h));
    EXPECT_EQ(bg[0], 250);
    EXPECT_EQ(bg[1], 250);
    EXPECT_EQ(bg[2], 250);
  }
}

TEST_F(headless_test, the_reference_geometry_is_drawn_dashed_beside_the_path_and_can_be_hidden) {
  const Part p = analyse(kRectangle);
  // The rectangle 2 mm inside the path, as the drawing a wire path was made from.
  const std::vector<geometry::Segment> ref{
      geometry::Segment::line({2, 2}, {18, 2}), geometry::Segment::line({18, 2}, {18, 8}),
      geometry::Segment::line({18, 8}, {2, 8}), geometry::Segment::line({2, 8}, {2, 2})};
  const render::Scene s = render::buildScene(p.toolpath, p.diags->all(), {}, ref);
  ASSERT_EQ(s.reference.moveFirst.size(), 2u);
  EXPECT_EQ(s.reference.vertices.size(), 8u);  // four lines, two vertices each
  constexpr int w = 200, h = 120;
  render::RenderOptions o;
  o.triad = false;
  o.markers = false;
  auto magenta = [](const std::vector<std::uint8_t>& px) {
    std::size_t n = 0;
    for (std::size_t i = 0; i + 3 < px.size(); i += 4) n += px[i] > 150 && px[i + 1] < 120 && px[i + 2] > 100;
    return n;
  };
  const std::size_t shown = magenta(drawTop(s, w, h, o));
  o.reference = false;
  const std::size_t hidden = magenta(drawTop(s, w, h, o));
  EXPECT_GT(shown, 100u);  // dashes along 44 mm of lines
  EXPECT_EQ(hidden, 0u);
}

/// Pixels that are not the background (250, 250, 250).
std::size_t drawnPixels(const std::vector<std::uint8_t>& px) {
  std::size_t n = 0;
  for (std::size_t i = 0; i + 3 < px.size(); i += 4) n += px[i] != 250 || px[i + 1] != 250 || px[i + 2] != 250;
  return n;
}

/// Pixels whose colour leans clearly to blue (the ramp's low end) or to red (its high end).
std::pair<std::size_t, std::size_t> blueAndRed(const std::vector<std::uint8_t>& px) {
  std::size_t blue = 0, red = 0;
  for (std::size_t i = 0; i + 3 < px.size(); i += 4) {
    const int r = px[i], b = px[i + 2];
    blue += b > r + 60;
    red += r > b + 60;
  }
  return {blue, red};
}

TEST_F(headless_test, same_scene_same_pixels) {
  const Part p = analyse(kFrustum);
  const render::Scene s = render::buildScene(p.toolpath, p.diags->all());
  render::RenderOptions o;
  o.colourBySlope = true;
  const auto a = drawTop(s, 160, 120, o), b = drawTop(s, 160, 120, o);
  EXPECT_EQ(a, b);
  // Not two empty pictures: the frustum's walls, seen from above, cover a good part of the picture.
  EXPECT_GT(drawnPixels(a), 160u * 120u / 10u);
}

TEST_F(headless_test, drawn_in_pieces_the_picture_is_the_same) {
  // The walls and lines drawn a few primitives at a time (RenderOptions::drawChunk), each piece's
  // first index and count from the last: the same pixels as in one call.
  const Part p = analyse(kFrustum);
  const render::Scene s = render::buildScene(p.toolpath, p.diags->all());
  ASSERT_GT(s.surfaceIndices.size(), 3u * 20);
  render::RenderOptions whole, pieces;
  whole.colourBySlope = pieces.colourBySlope = true;
  pieces.drawChunk = 7;
  const auto a = drawTop(s, 160, 120, whole), b = drawTop(s, 160, 120, pieces);
  EXPECT_GT(drawnPixels(a), 160u * 120u / 10u);
  EXPECT_EQ(a, b);
}

TEST_F(headless_test, colour_by_slope_follows_the_ramp) {
  // The frustum's wire leans 11.3 degrees mid-side (2 mm over 10) and 15.8 at the corners (2.83
  // mm): coloured by slope, its walls run from the ramp's blue (mid-sides) to its red (corners);
  // shaded plainly, they are one colour, neither blue nor red.
  const Part p = analyse(kFrustum);
  const render::Scene s = render::buildScene(p.toolpath, p.diags->all());
  render::RenderOptions plain, slope;
  for (render::RenderOptions* o : {&plain, &slope}) {
    o->contours = o->generators = o->rapids = o->markers = o->triad = false;
  }
  slope.colourBySlope = true;
  const auto [slopeBlue, slopeRed] = blueAndRed(drawTop(s, 160, 120, slope));
  const auto [plainBlue, plainRed] = blueAndRed(drawTop(s, 160, 120, plain));
  EXPECT_GT(slopeBlue, 50u);
  EXPECT_GT(slopeRed, 50u);
  EXPECT_EQ(plainRed, 0u);
  EXPECT_LT(plainBlue + plainRed, slopeBlue + slopeRed);
}

TEST(headless_png_test, encodes_and_decodes_the_same_pixels) {
  std::vector<std::uint8_t> rgba(7 * 5 * 4);
  for (std::size_t i = 0; i < rgba.size(); ++i) rgba[i] = static_cast<std::uint8_t>(i * 37 % 256);
  const std::string png = headless::encodePng(rgba, 7, 5);
  ASSERT_FALSE(png.empty());
  EXPECT_EQ(png.substr(1, 3), "PNG");
  const auto back = headless::decodePng(png);
  ASSERT_TRUE(back.has_value());
  EXPECT_EQ(back->width, 7);
  EXPECT_EQ(back->height, 5);
  EXPECT_EQ(back->rgba, rgba);
  EXPECT_TRUE(headless::encodePng(rgba, 8, 5).empty());  // wrong size
  EXPECT_FALSE(headless::decodePng("not a png").has_value());
}

std::vector<std::uint8_t> checker(int w, int h) {
  std::vector<std::uint8_t> px(static_cast<std::size_t>(w) * h * 4, 255);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      if (((x / 8) + (y / 8)) % 2)
        for (int c = 0; c < 3; ++c) px[(static_cast<std::size_t>(y) * w + x) * 4 + c] = 40;
  return px;
}

TEST(snapshot_ssim_test, identical_images_have_no_error) {
  const auto a = checker(96, 64);
  const test::SsimResult r = test::compareImages({96, 64, &a}, {96, 64, &a});
  EXPECT_NEAR(r.error, 0.0, 1e-6);
  EXPECT_NEAR(r.meanSsim, 1.0, 1e-6);
}

TEST(snapshot_ssim_test, a_small_local_change_is_above_the_default_threshold) {
  const auto a = checker(320, 240);
  auto b = a;
  // A 10 x 10 red square (a finding marker) in a 320 x 240 picture: 0.13 % of its pixels.
  for (int y = 100; y < 110; ++y)
    for (int x = 200; x < 210; ++x) {
      auto* p = &b[(static_cast<std::size_t>(y) * 320 + x) * 4];
      p[0] = 220, p[1] = 30, p[2] = 30;
    }
  const test::SsimResult r = test::compareImages({320, 240, &a}, {320, 240, &b});
  EXPECT_GT(r.error, 0.05);
  EXPECT_GT(r.meanSsim, 0.99);  // a whole-picture mean would have missed it
  EXPECT_EQ(r.worstTileX, 192);
  EXPECT_EQ(r.worstTileY, 96);
}

TEST(snapshot_ssim_test, faint_noise_is_below_the_default_threshold) {
  const auto a = checker(160, 120);
  auto b = a;
  for (std::size_t i = 0; i < b.size(); i += 4)
    b[i] = static_cast<std::uint8_t>(std::clamp(b[i] + static_cast<int>(i % 5) - 2, 0, 255));
  const test::SsimResult r = test::compareImages({160, 120, &a}, {160, 120, &b});
  EXPECT_GT(r.error, 0.0);
  EXPECT_LT(r.error, 0.05);
}

TEST(snapshot_ssim_test, different_sizes_are_a_full_error) {
  const auto a = checker(16, 16), b = checker(16, 24);
  EXPECT_EQ(test::compareImages({16, 16, &a}, {16, 24, &b}).error, 1.0);
}

class export_test : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() /
           ("kerf_export_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::filesystem::path dir_;
};

TEST_F(export_test, vtp_carries_move_line_slope_and_findings) {
  // The frustum: every cell names its move and that move's line, and its slope lies between the
  // mid-side (atan 0.2) and the corner (atan 0.2 sqrt 2) generators.
  const Part p = analyse(kFrustum);
  const exporter::SurfaceData data = exporter::surfaceData(p.toolpath, p.diags->all(), {}, false);
  const std::string path = (dir_ / "part.vtp").string();
  std::string error;
  ASSERT_TRUE(exporter::writeMesh(data, exporter::MeshFormat::Vtp, path, error)) << error;
  vtkNew<vtkXMLPolyDataReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  vtkPolyData* poly = reader->GetOutput();
  ASSERT_EQ(poly->GetNumberOfPolys(), static_cast<vtkIdType>(data.surface.mesh.triangles.size()));
  EXPECT_EQ(poly->GetNumberOfPoints(), static_cast<vtkIdType>(data.surface.mesh.vertices.size()));
  for (const char* name : {"move", "line", "slope", "findings"})
    ASSERT_NE(poly->GetCellData()->GetArray(name), nullptr) << name;
  vtkDataArray* line = poly->GetCellData()->GetArray("line");
  vtkDataArray* move = poly->GetCellData()->GetArray("move");
  vtkDataArray* slope = poly->GetCellData()->GetArray("slope");
  for (vtkIdType c = 0; c < poly->GetNumberOfPolys(); ++c) {
    const auto m = static_cast<std::size_t>(move->GetTuple1(c));
    ASSERT_LT(m, p.toolpath.moves.size());
    EXPECT_EQ(line->GetTuple1(c), p.toolpath.moves[m].line);
    EXPECT_GE(slope->GetTuple1(c), std::atan(0.2) * 180 / geometry::kPi - 1e-3);
    EXPECT_LE(slope->GetTuple1(c), std::atan(0.2 * std::sqrt(2.0)) * 180 / geometry::kPi + 1e-3);
  }
}

// A program cut in two passes (a rough cut G41 and a reversed skim G42 over a 20 mm square): every
// cell of the VTP carries its move's pass, 1 or 2, as the structure numbers them.
TEST_F(export_test, vtp_carries_each_cells_pass) {
  const std::string square =
      "G90 G92 X0 Y0\nG41 G01 X10. Y0\nY10.\nX-10.\nY-10.\nX10.\nY0\nG40 G01 X0 Y0\n"
      "G42 G01 X10. Y0\nY-10.\nX-10.\nY10.\nX10.\nY0\nG40 G01 X0 Y0\nM02\n";
  const Part p = analyse(square);
  const converter::Structure st = converter::findStructure(p.toolpath, 1e-3);
  ASSERT_EQ(st.contours.size(), 1u);
  ASSERT_EQ(st.contours[0].passes.size(), 2u);
  render::SceneOptions options;
  options.movePass = converter::movePasses(st, p.toolpath.moves.size());
  const exporter::SurfaceData data = exporter::surfaceData(p.toolpath, p.diags->all(), options, false);
  const std::string path = (dir_ / "passes.vtp").string();
  std::string error;
  ASSERT_TRUE(exporter::writeMesh(data, exporter::MeshFormat::Vtp, path, error)) << error;
  vtkNew<vtkXMLPolyDataReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  vtkDataArray* pass = reader->GetOutput()->GetCellData()->GetArray("pass");
  vtkDataArray* move = reader->GetOutput()->GetCellData()->GetArray("move");
  ASSERT_NE(pass, nullptr);
  std::size_t seen[3] = {0, 0, 0};
  for (vtkIdType c = 0; c < reader->GetOutput()->GetNumberOfPolys(); ++c) {
    const auto m = static_cast<std::size_t>(move->GetTuple1(c));
    const auto k = static_cast<std::size_t>(pass->GetTuple1(c));
    const std::size_t expected = m < st.contours[0].passes[1].first ? 1 : 2;
    ASSERT_EQ(k, expected) << "cell " << c << ", move " << m;
    ++seen[k];
  }
  EXPECT_GT(seen[1], 0u);
  EXPECT_GT(seen[2], 0u);
}

// The window hides a pass by building the scene without its moves: they draw no surface and no
// line, and keep their indices (the other moves' lines stay where they were).
TEST(scene_test, hidden_moves_draw_nothing_and_keep_their_indices) {
  const std::string square = "G90 G92 X0 Y0\nG01 X10. Y0\nY10.\nX-10.\nY-10.\nX10.\nY0\nX0 Y0\nM02\n";
  const Part p = analyse(square);
  const std::size_t n = p.toolpath.moves.size();
  ASSERT_EQ(n, 7u);
  const render::Scene all = render::buildScene(p.toolpath, {});
  render::SceneOptions options;
  options.hiddenMoves.assign(n, false);
  options.hiddenMoves[2] = options.hiddenMoves[3] = true;
  const render::Scene some = render::buildScene(p.toolpath, {}, options);
  ASSERT_EQ(some.lower.moveFirst.size(), n + 1);                // one a move, and the end
  EXPECT_EQ(some.lower.moveFirst[3], some.lower.moveFirst[2]);  // move 2 drew no line
  EXPECT_LT(some.lower.vertices.size(), all.lower.vertices.size());
  EXPECT_LT(some.triangles(), all.triangles());
  for (const std::uint32_t m : some.triangleMove) EXPECT_TRUE(m != 2 && m != 3) << m;
  EXPECT_GT(some.triangles(), 0u);
}

TEST_F(export_test, findings_flags_mark_the_moves_with_findings) {
  const Part p = analyse("G90 G21\nG01 X10. Y10.\nX10. Y0\nX0 Y10.\nX0 Y0\nM30\n");
  const exporter::SurfaceData data = exporter::surfaceData(p.toolpath, p.diags->all(), {}, false);
  std::size_t flagged = 0;
  for (std::size_t c = 0; c < data.cellFindings.size(); ++c) {
    if (data.cellFindings[c] & exporter::kFindingError) ++flagged;
  }
  EXPECT_GT(flagged, 0u);
  EXPECT_LT(flagged, data.cellFindings.size());  // the crossing is on some moves, not all
}

TEST_F(export_test, stl_and_ply_read_back_with_the_same_triangles) {
  const Part p = analyse(kFrustum);
  const exporter::SurfaceData data = exporter::surfaceData(p.toolpath, p.diags->all(), {}, true);
  EXPECT_EQ(data.surface.mesh.capsMade, 2u);
  std::string error;
  const std::string stl = (dir_ / "part.stl").string(), ply = (dir_ / "part.ply").string();
  ASSERT_TRUE(exporter::writeMesh(data, exporter::MeshFormat::Stl, stl, error)) << error;
  ASSERT_TRUE(exporter::writeMesh(data, exporter::MeshFormat::Ply, ply, error)) << error;
  vtkNew<vtkSTLReader> stlReader;
  stlReader->SetFileName(stl.c_str());
  stlReader->Update();
  EXPECT_EQ(stlReader->GetOutput()->GetNumberOfPolys(), static_cast<vtkIdType>(data.surface.mesh.triangles.size()));
  vtkNew<vtkPLYReader> plyReader;
  plyReader->SetFileName(ply.c_str());
  plyReader->Update();
  EXPECT_EQ(plyReader->GetOutput()->GetNumberOfPolys(), static_cast<vtkIdType>(data.surface.mesh.triangles.size()));
  EXPECT_EQ(plyReader->GetOutput()->GetNumberOfPoints(), static_cast<vtkIdType>(data.surface.mesh.vertices.size()));
}

TEST(export_format_test, chosen_by_extension) {
  EXPECT_EQ(exporter::formatOfPath("a/b.VTP"), exporter::MeshFormat::Vtp);
  EXPECT_EQ(exporter::formatOfPath("b.stl"), exporter::MeshFormat::Stl);
  EXPECT_EQ(exporter::formatOfPath("b.ply"), exporter::MeshFormat::Ply);
  EXPECT_FALSE(exporter::formatOfPath("b.obj").has_value());
  EXPECT_FALSE(exporter::formatOfPath("noext").has_value());
}

}  // namespace
