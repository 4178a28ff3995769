// The emitter table, and the point-file emitters (points.cpp) in its shape.
#include "kerf/converter/emit.h"

namespace kerf::converter {

namespace {

/// pairs: points4 (an X Y U V pair a line, in the profile's number format).
EmitOutput fromPoints(PointOutput&& p, const EmitRequest& request, bool pairs = false) {
  EmitOutput out;
  out.text = std::move(p.text);
  out.what = pairs ? std::to_string(p.points) + " point pairs (points4: X Y U V, numbers as the " +
                         request.profile.name + " profile writes them)"
                   : std::to_string(p.points) + " points (" + request.profile.name + " profile)";
  const std::size_t capacity = request.maxPoints ? *request.maxPoints : request.profile.maxPoints.value_or(0);
  out.detail = std::string("; ") + (p.sampling.mode == geometry::SamplingMode::Step ? "step k = " : "tolerance ") +
               formatFixed(p.sampling.value, 6) + " mm" +
               (p.fitted ? " chosen to fit " + std::to_string(capacity) + " points" : "") + ", max deviation " +
               formatFixed(p.stats.maxDeviation, 6) + " mm";
  return out;
}

PointRequest pointRequest(const EmitRequest& r) {
  PointRequest p;
  p.sampling = r.sampling;
  p.maxPoints = r.maxPoints;
  p.startLine = r.startLine;
  return p;
}

}  // namespace

std::optional<EmitOutput> writeBp95d(const Toolpath& toolpath, const SourceFile* source, const EmitRequest& request,
                                     Diagnostics& diags) {
  std::optional<PointOutput> p = emitPoints(toolpath, source, request.profile, pointRequest(request), diags);
  if (!p) return std::nullopt;
  return fromPoints(std::move(*p), request);
}

std::optional<EmitOutput> writePoints4(const Toolpath& toolpath, const SourceFile* source, const EmitRequest& request,
                                       Diagnostics& diags) {
  std::optional<PointOutput> p =
      emitPoints4(toolpath, source, request.profile, pointRequest(request), request.relativeUv, diags);
  if (!p) return std::nullopt;
  return fromPoints(std::move(*p), request, true);
}

const std::vector<Emitter>& emitters() {
  static const std::vector<Emitter> table = {
      {"bp95d", "point sequence for point-driven 2-axis controllers (BP-95d): X Y per line, profile-driven",
       PlaneNeed::One, writeBp95d},
      {"points4", "point sequence for point-driven 4-axis controllers: X Y U V per line, both planes at the same t",
       PlaneNeed::Both, writePoints4},
      {"3b", "Chinese fast-wire 3B code: B x B y B J G Z, whole micrometres, one file per plane", PlaneNeed::One,
       writeThreeB},
      {"4b", "4B code: 3B with the radius and convex/concave marks for controls that offset the wire [unsure layout]",
       PlaneNeed::One, writeFourB},
      {"iso", "normalised ISO G-code: absolute, one move per block, I J incremental; --for a machine's conventions",
       PlaneNeed::Both, writeIso},
      {"polar", "polar X/C for mill-turn lathes: X diameter (or radius), C degrees unwrapped, spirals within tolerance",
       PlaneNeed::One, writePolar},
  };
  return table;
}

const Emitter* findEmitter(std::string_view name) {
  for (const Emitter& e : emitters())
    if (e.name == name) return &e;
  return nullptr;
}

}  // namespace kerf::converter
