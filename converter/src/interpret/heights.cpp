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

}  // namespace kerf::converter::interp
