// Acceptance: Kerf's arcs agree with an independent interpreter — LinuxCNC's standalone rs274,
// whose canonical output (STRAIGHT_FEED, ARC_FEED with end, centre and turn) is printed to 4
// decimals — to 1e-4 mm, on random 2-axis programs of lines, R arcs of both signs and I J arcs
// (full circles too), switching between G90 and G91.
#include "converter_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

namespace {

using kerf::geometry::Vec2;

struct Canon {
  bool arc = false;
  bool rapid = false;
  Vec2 end{0, 0};
  Vec2 centre{0, 0};
  int turn = 0;  // LinuxCNC: -1 clockwise, 1 counter-clockwise
};

std::string f4(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.4f", v);
  return b;
}

/// A random program; positions tracked with the 4-decimal values written, as both readers see them.
std::string randomProgram(std::mt19937& rng) {
  std::uniform_real_distribution<double> unit(0, 1);
  std::ostringstream out;
  out << "G21 G90 G17 G40 F100\n";
  Vec2 pos(0, 0);
  bool incremental = false;
  auto round4 = [](double v) { return std::round(v * 1e4) / 1e4; };
  auto writeEnd = [&](const Vec2& end) {
    if (incremental)
      out << " X" << f4(end.x() - pos.x()) << " Y" << f4(end.y() - pos.y());
    else
      out << " X" << f4(end.x()) << " Y" << f4(end.y());
  };
  for (int i = 0; i < 60; ++i) {
    if (unit(rng) < 0.1) {
      incremental = !incremental;
      out << (incremental ? "G91" : "G90") << "\n";
    }
    const double kind = unit(rng);
    if (kind < 0.3) {  // line (sometimes a rapid)
      const Vec2 end(round4(pos.x() + (unit(rng) - 0.5) * 40), round4(pos.y() + (unit(rng) - 0.5) * 40));
      out << (unit(rng) < 0.2 ? "G0" : "G1");
      writeEnd(end);
      out << "\n";
      pos = end;
    } else if (kind < 0.65) {  // R arc, either sign
      const Vec2 end(round4(pos.x() + (unit(rng) - 0.5) * 30), round4(pos.y() + (unit(rng) - 0.5) * 30));
      const double half = (end - pos).norm() / 2;
      if (half < 0.01) continue;
      double r = round4(half + 0.5 + unit(rng) * 20);
      if (unit(rng) < 0.5) r = -r;
      out << (unit(rng) < 0.5 ? "G2" : "G3");
      writeEnd(end);
      out << " R" << f4(r) << "\n";
      pos = end;
    } else {  // I J arc: centre offset, end on the circle (rounded to 4 decimals)
      const Vec2 ij(round4((unit(rng) - 0.5) * 30), round4((unit(rng) - 0.5) * 30));
      if (ij.norm() < 0.5) continue;
      const Vec2 c = pos + ij;
      const bool full = unit(rng) < 0.1;
      const double a = std::atan2(-ij.y(), -ij.x()) + (unit(rng) - 0.5) * 6;
      const Vec2 end =
          full ? pos : Vec2(round4(c.x() + ij.norm() * std::cos(a)), round4(c.y() + ij.norm() * std::sin(a)));
      out << (unit(rng) < 0.5 ? "G2" : "G3");
      if (!full) writeEnd(end);
      out << " I" << f4(ij.x()) << " J" << f4(ij.y()) << "\n";
      pos = end;
    }
  }
  out << "M2\n";
  return out.str();
}

std::vector<Canon> runRs274(const std::filesystem::path& input) {
  const std::filesystem::path output = input.string() + ".canon";
  const std::string cmd =
      std::string(KERF_RS274) + " -g '" + input.string() + "' '" + output.string() + "' > /dev/null 2>&1";
  EXPECT_EQ(std::system(cmd.c_str()), 0) << cmd;
  std::vector<Canon> moves;
  std::ifstream in(output);
  for (std::string line; std::getline(in, line);) {
    Canon c;
    double v[6];
    if (auto p = line.find("STRAIGHT_FEED("); p != std::string::npos) {
      if (std::sscanf(line.c_str() + p, "STRAIGHT_FEED(%lf, %lf", &v[0], &v[1]) != 2) continue;
      c.end = {v[0], v[1]};
    } else if (auto q = line.find("STRAIGHT_TRAVERSE("); q != std::string::npos) {
      if (std::sscanf(line.c_str() + q, "STRAIGHT_TRAVERSE(%lf, %lf", &v[0], &v[1]) != 2) continue;
      c.rapid = true;
      c.end = {v[0], v[1]};
    } else if (auto a = line.find("ARC_FEED("); a != std::string::npos) {
      if (std::sscanf(line.c_str() + a, "ARC_FEED(%lf, %lf, %lf, %lf, %d", &v[0], &v[1], &v[2], &v[3], &c.turn) != 5)
        continue;
      c.arc = true;
      c.end = {v[0], v[1]};
      c.centre = {v[2], v[3]};
    } else {
      continue;
    }
    moves.push_back(c);
  }
  return moves;
}

TEST(linuxcnc_test, random_programs_agree_to_1e_4_mm) {
  std::mt19937 rng(20261121);
  const auto dir = std::filesystem::temp_directory_path() / ("kerf-rs274-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  std::size_t arcsCompared = 0, radiusArcs = 0, negativeR = 0;
  double worst = 0;
  for (int p = 0; p < 25; ++p) {
    const std::string text = randomProgram(rng);
    const auto file = dir / ("p" + std::to_string(p) + ".ngc");
    std::ofstream(file) << text;
    const std::vector<Canon> theirs = runRs274(file);
    auto ours = kerf::test::run(text);
    ASSERT_FALSE(ours->diags.hasErrors()) << text;
    const auto& moves = ours->path().moves;
    ASSERT_EQ(moves.size(), theirs.size()) << "program " << p << "\n" << text;
    for (std::size_t i = 0; i < moves.size(); ++i) {
      const auto& m = moves[i];
      const Canon& c = theirs[i];
      SCOPED_TRACE("program " + std::to_string(p) + " line " + std::to_string(m.line));
      ASSERT_EQ(m.kind == kerf::converter::MoveKind::Arc, c.arc);
      ASSERT_EQ(m.kind == kerf::converter::MoveKind::Rapid, c.rapid);
      EXPECT_LE((m.lower.end - c.end).norm(), 1e-4);
      worst = std::max(worst, (m.lower.end - c.end).norm());
      if (!c.arc) continue;
      ++arcsCompared;
      if (m.centreForm == kerf::converter::CentreForm::Radius) {
        ++radiusArcs;
        negativeR += ours->path().programmedRadius(i) < 0;
      }
      EXPECT_LE((m.lower.centre - c.centre).norm(), 1e-4);
      worst = std::max(worst, (m.lower.centre - c.centre).norm());
      EXPECT_EQ(m.lower.sweep < 0 ? -1 : 1, c.turn);
    }
  }
  std::filesystem::remove_all(dir);
  EXPECT_GT(arcsCompared, 500u);
  EXPECT_GT(radiusArcs, 200u);
  EXPECT_GT(negativeR, 80u);
  RecordProperty("worst_difference_mm", std::to_string(worst));
  std::printf("compared %zu arcs (%zu by R, %zu with R < 0); worst difference %.6f mm\n", arcsCompared, radiusArcs,
              negativeR, worst);
}

}  // namespace
