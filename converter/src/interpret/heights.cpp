// The heights of the lower, upper and program planes, once the whole program is read.
#include "interpreter_impl.h"

namespace kerf::converter::interp {

/// Heights written outside the words: Sodick TP/TN, LinuxCNC AXIS comments (mm).
Height Interpreter::heightOf(const HeightWord& w) const {
  double v = w.value;
  if (!w.hasPoint && options_.integerUnit == IntegerUnit::Micrometre) v *= 0.001;
  static constexpr const char* kNames[] = {"TP", "TN", "(AXIS,XY_Z_POS)", "(AXIS,UV_Z_POS)"};
  return {v, std::string(kNames[static_cast<int>(w.kind)]) + " on line " + std::to_string(w.line)};
}

/// The planes: command line first, then the program, then the machine profile's default
/// thickness (docs/taper.md lists the order and the assumptions).
void Interpreter::resolveHeights() {
  std::optional<Height> xyZ, uvZ, tp, tn;
  for (const HeightWord& w : program_.heights) {
    switch (w.kind) {
      case HeightWord::Kind::SodickProgramPlane: tp = heightOf(w); break;
      case HeightWord::Kind::SodickLowerPlane: tn = heightOf(w); break;
      case HeightWord::Kind::LinuxCncXyPlane: xyZ = heightOf(w); break;
      case HeightWord::Kind::LinuxCncUvPlane: uvZ = heightOf(w); break;
    }
  }
  Height lower{0.0, "the lower plane at z = 0"};
  if (options_.lowerZ)
    lower = {*options_.lowerZ, "--lower-z"};
  else if (xyZ)
    lower = *xyZ;
  // Sodick: TP is the programmed contour's plane, TN the lower plane, both from the same datum.
  std::optional<double> sodickProgram;
  if (tp) sodickProgram = tp->value - (tn ? tn->value : 0.0);
  std::optional<Height> upper;
  if (options_.upperZ)
    upper = Height{*options_.upperZ, "--upper-z"};
  else if (options_.thickness)
    upper = Height{lower.value + *options_.thickness, "--thickness"};
  else if (uvZ)
    upper = uvZ;
  else if (fileThickness_)
    upper = Height{lower.value + fileThickness_->value, fileThickness_->source};
  else if (sodickProgram && *sodickProgram > 0)
    upper = Height{lower.value + *sodickProgram, tp->source + " (the program plane taken as the upper plane)"};
  else if (machine_.thickness)
    upper = Height{lower.value + *machine_.thickness, "the " + machine_.name + " profile's thickness"};
  PlaneHeights& h = toolpath_.heights;
  h.planes.lower = lower.value;
  h.programZ = options_.programZ ? *options_.programZ
               : fileProgramZ_   ? lower.value + fileProgramZ_->value
               : sodickProgram   ? lower.value + *sodickProgram
                                 : lower.value;
  resolveGuides(lower.value);
  const SourceSpan where = program_.blocks.empty() ? SourceSpan::wholeFile() : program_.blocks.front().span();
  if (upper && upper->value > lower.value) {
    h.planes.upper = upper->value;
    h.known = true;
    h.source = "lower z " + formatFixed(lower.value, 3) + " (" + lower.source + "), upper z " +
               formatFixed(upper->value, 3) + " (" + upper->source + ")";
  } else if (upper) {
    diags_.error(Code::HeightsMissing, src_, where,
                 "the upper plane (z " + formatFixed(upper->value, 3) + ", " + upper->source +
                     ") is not above the lower plane (z " + formatFixed(lower.value, 3) + ", " + lower.source + ")");
  } else if (dialect_ != Dialect::Plain && !warnedUz_) {  // with U Z unresolved the upper side is unread
    // On a hot-wire foam cutter the two planes are the carriages: the part's "thickness" is the
    // machine's width, written in a header comment if anywhere, never in a word.
    const bool xyuv = dialect_ == Dialect::XyuvAbs || dialect_ == Dialect::XyuvLinuxCnc || dialect_ == Dialect::XyuvRel;
    diags_.error(Code::HeightsMissing, src_, where,
                 std::string("this ") + dialectName(dialect_) +
                     " program gives no heights for its planes, and a taper needs them",
                 std::string("give --thickness H or --upper-z Z (in the program: M101 P, G92 I, TP/TN or "
                             "(AXIS,UV_Z_POS,z))") +
                     (xyuv ? "; on a hot-wire foam cutter X Y and U V are the two carriages, so the thickness is "
                             "the distance between them (the machine's width)"
                           : ""));
  }
}

/// The guides: --guides, else cnc3's M100 P Q in the program, else the profile's `guides`; each
/// measured from the part's lower face (z = lowerZ). A spacing not above 0, or guides that do not
/// hold the part between them, are an error that names where they came from.
void Interpreter::resolveGuides(double lowerZ) {
  PlaneHeights& h = toolpath_.heights;
  std::optional<std::array<double, 2>> g;
  std::string source;
  if (options_.guides) {
    g = options_.guides;
    source = "--guides";
  } else if (fileGuideSpacing_ && fileGuideBelow_) {
    g = std::array<double, 2>{-fileGuideBelow_->value, fileGuideSpacing_->value - fileGuideBelow_->value};
    source = fileGuideSpacing_->source + " (spacing), " + fileGuideBelow_->source + " (below the work)";
  } else if (machine_.guides) {
    g = machine_.guides;
    source = "the " + machine_.name + " profile's guides";
  }
  if (!g) return;
  if (!((*g)[1] > (*g)[0]) || std::abs((*g)[0]) > 1e5 || std::abs((*g)[1]) > 1e5) {
    diags_.error(Code::HeightsMissing, src_,
                 program_.blocks.empty() ? SourceSpan::wholeFile() : program_.blocks.front().span(),
                 "the guides (" + source + ") are at z " + formatFixed((*g)[0], 3) + " and " + formatFixed((*g)[1], 3) +
                     " mm: the upper must be above the lower, both within 100 m");
    return;
  }
  h.guides = geometry::Planes{lowerZ + (*g)[0], lowerZ + (*g)[1]};
  h.guidesSource = source;
}

}  // namespace kerf::converter::interp
