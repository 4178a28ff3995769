// A block's construction as lines, dots and labels (construction_scene.h).
#include "kerf/render/construction_scene.h"

#include <cmath>

namespace kerf::render {

using converter::ConstructionMark;
using geometry::Vec2;
using geometry::Vec3;
using Role = ConstructionMark::Role;

std::uint32_t constructionColour(Role role) {
  switch (role) {
    case Role::Path: return rgba(230, 170, 0);
    case Role::Upper: return rgba(200, 120, 0);
    case Role::Chord: return rgba(220, 90, 30);
    case Role::Bisector: return rgba(110, 110, 110);
    case Role::Centre: return rgba(20, 150, 60);
    case Role::Rejected: return rgba(210, 40, 40);
    case Role::Vector: return rgba(170, 40, 170);
    case Role::Radius: return rgba(20, 130, 170);
    case Role::Angle: return rgba(60, 90, 200);
    case Role::Sample: return rgba(40, 40, 40);
    case Role::Deviation: return rgba(210, 40, 40);
    case Role::Programmed: return rgba(110, 110, 110);
    case Role::Offset: return rgba(170, 40, 170);
  }
  return rgba(40, 40, 40);
}

namespace {

void addLine(LineSet& set, const geometry::Segment& s, double z, double tolerance, std::uint32_t colour) {
  std::vector<Vec2> points(1, s.start);
  geometry::sample(s, geometry::Sampling::tolerance(tolerance), &points);
  for (std::size_t i = 0; i + 1 < points.size(); ++i)
    set.add({points[i].x(), points[i].y(), z}, {points[i + 1].x(), points[i + 1].y(), z}, colour);
}

/// An arrow's head: two strokes back from the tip, a fifth of its length (at most 8 % of `scale`).
void addHead(LineSet& set, const Vec2& from, const Vec2& to, double z, double scale, std::uint32_t colour) {
  const double length = (to - from).norm();
  if (!(length > 0)) return;
  const Vec2 back = (from - to) / length * std::min(0.2 * length, 0.08 * scale);
  for (double turn : {0.45, -0.45}) {
    const Vec2 stroke(std::cos(turn) * back.x() - std::sin(turn) * back.y(),
                      std::sin(turn) * back.x() + std::cos(turn) * back.y());
    set.add({to.x(), to.y(), z}, {to.x() + stroke.x(), to.y() + stroke.y(), z}, colour);
  }
}

bool dashedRole(Role role) { return role == Role::Bisector || role == Role::Programmed; }

}  // namespace

ConstructionScene constructionScene(const converter::Construction& c, const geometry::Planes& planes, double tolerance,
                                    std::size_t captionLines) {
  ConstructionScene out;
  out.lines.moveFirst.push_back(0);
  out.dashed.moveFirst.push_back(0);
  double scale = 0.0;  // the size of the construction, for the arrow heads and the arcs' chords
  for (const ConstructionMark& m : c.marks) scale = std::max(scale, m.segment.length());
  if (scale > 0) tolerance = std::min(tolerance, 5e-4 * scale);
  for (const ConstructionMark& m : c.marks) {
    const std::uint32_t colour = constructionColour(m.role);
    const double z = m.upper ? planes.upper : planes.lower;
    Vec3 anchor;
    switch (m.kind) {
      case ConstructionMark::Kind::Point:
        anchor = {m.segment.start.x(), m.segment.start.y(), z};
        out.points.push_back(Marker{anchor, colour, m.role == Role::Path ? 7.0f : 10.0f, {}});
        break;
      case ConstructionMark::Kind::Wire:
        out.lines.add({m.segment.start.x(), m.segment.start.y(), planes.lower},
                      {m.segment.end.x(), m.segment.end.y(), planes.upper}, colour);
        anchor = {m.segment.end.x(), m.segment.end.y(), planes.upper};
        break;
      case ConstructionMark::Kind::Arrow:
        addLine(out.lines, m.segment, z, tolerance, colour);
        addHead(out.lines, m.segment.start, m.segment.end, z, scale, colour);
        anchor = {m.segment.pointAt(0.5).x(), m.segment.pointAt(0.5).y(), z};
        break;
      case ConstructionMark::Kind::Segment: {
        addLine(dashedRole(m.role) ? out.dashed : out.lines, m.segment, z, tolerance, colour);
        const Vec2 at = m.segment.pointAt(m.role == Role::Bisector ? 0.85 : 0.5);
        anchor = {at.x(), at.y(), z};
        break;
      }
    }
    if (!m.label.empty()) out.labels.push_back(Marker{anchor, colour, 0.0f, m.label});
  }
  out.lines.moveFirst.push_back(static_cast<std::uint32_t>(out.lines.vertices.size()));
  out.dashed.moveFirst.push_back(static_cast<std::uint32_t>(out.dashed.vertices.size()));
  if (captionLines > 0) {
    out.caption.push_back("line " + std::to_string(c.line) + ": " + c.block);
    if (!c.pass.empty()) out.caption.push_back(c.pass);
    for (const converter::WordMeaning& w : c.words) out.caption.push_back("  " + w.word + "  " + w.sets);
    for (const std::string& mode : c.modes) out.caption.push_back("  " + mode);
    if (out.caption.size() > captionLines) {
      out.caption.resize(captionLines - 1);
      out.caption.push_back("  ...");
    }
  }
  return out;
}

void extendBounds(const ConstructionScene& c, Vec3& lo, Vec3& hi) {
  auto grow = [&](const Vec3& p) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  };
  for (const LineSet* set : {&c.lines, &c.dashed})
    for (const LineVertex& v : set->vertices) grow(Vec3(v.position[0], v.position[1], v.position[2]));
  for (const Marker& m : c.points) grow(m.position);
}

}  // namespace kerf::render
