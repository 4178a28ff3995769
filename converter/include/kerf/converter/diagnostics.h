// Diagnostics: what Kerf says about a program, compiler style.
//
//   part.nc:12:7: error: arc radius 4.000 is shorter than half the chord 5.000 [K0302]
//       G02 X10. Y0 R4.
//                   ^~~
// Every diagnostic has a stable code (docs/diagnostics.md lists them), a severity and a span.
#pragma once

#include "kerf/converter/source.h"
#include "kerf/geometry/vec.h"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace kerf::converter {

enum class Severity : std::uint8_t { Note, Warning, Error };

/// Stable diagnostic codes. The number is the code users see: K0302 is Code::RadiusTooSmall.
enum class Code : std::uint16_t {
  // Lexical and syntax
  UnterminatedComment = 101,
  ExpectedNumber = 102,
  MalformedNumber = 103,
  ExponentNotation = 104,
  NumberOutOfRange = 105,
  UnexpectedCharacter = 106,
  UnknownWord = 107,
  RepeatedWord = 108,
  TooManyMCodes = 111,
  NestedComment = 109,
  MalformedSetting = 110,
  DecimalComma = 112,
  MacroStatement = 113,
  BlockTooLong = 114,
  ThreeBSyntax = 120,
  DxfSyntax = 121,
  DxfEntity = 122,
  DxfSkipped = 123,
  DxfUnits = 124,
  ContourOpen = 125,
  WireCannotReach = 126,
  InsideCornerRadius = 127,
  WirePathSplits = 128,
  WireOffsetRefused = 129,
  CurveSyntax = 130,
  CurveFit = 131,
  // Words and modal state
  UnknownGCode = 201,
  UnknownMCode = 202,
  ModalGroupConflict = 203,
  PlaneNotSupported = 204,
  WordIgnored = 205,
  WordNotInDialect = 206,
  RadiusAndCentre = 207,
  DwellWithoutTime = 208,
  SetPositionWithoutAxis = 209,
  WireOffsetNotApplied = 210,
  WireOffsetUnknown = 211,
  NoMotionMode = 212,
  WorkOffsetIgnored = 213,
  BadFeed = 214,
  // 4-axis taper: dialects, heights, pairing
  DialectAmbiguous = 215,
  DialectChosen = 216,
  HeightsMissing = 217,
  TaperAngleTooLarge = 218,
  TaperOnArc = 219,
  BlockCountMismatch = 220,
  OffsetCollapses = 221,
  CentreOnStraightMove = 222,
  DwellWordsIgnored = 223,
  TaperAngleTwice = 224,
  ParameterMissing = 225,
  UpperSideMissing = 226,
  TwoFileNotPlain = 227,
  NegativeDwell = 228,
  OffsetOnArc = 229,
  // Machine profiles (machine.h)
  MachineDetected = 230,
  MachineCode = 231,
  CodeNotModelled = 232,
  PositionUnknown = 233,
  DirectionWord = 234,
  UpperAxesNamedUZ = 235,
  PolarNotSupported = 236,
  RotaryJump = 237,
  PolarAxisValue = 238,
  // Arcs
  ArcWithoutCentre = 301,
  RadiusTooSmall = 302,
  FullCircleWithRadius = 303,
  ArcEndOffCircle = 304,
  ZeroRadius = 305,
  UpperArcOffCircle = 306,
  CountContradicts = 307,
  CountPastFullCircle = 308,
  // Motion
  ZeroLengthMove = 402,
  // Program flow and subprograms
  CallWithoutProgram = 501,
  SubprogramNotFound = 502,
  CallTooDeep = 503,
  ReturnOutsideSubprogram = 504,
  MissingProgramEnd = 505,
  BadRepeatCount = 506,
  ExecutionLimit = 507,
  DuplicateLabel = 508,
  // Geometry of the cut path
  PathCrossesItself = 601,
  PathTouchesItself = 602,
  PathOverlapsItself = 603,
  PathRetraces = 604,
  PathOpen = 605,
  NothingCut = 606,
  RapidInsideCut = 607,
  LoopClosesInsideMove = 608,
  TaperSeam = 609,
  // Geometry of the ruled surface (4-axis taper)
  TaperTooSteep = 650,
  SurfaceSelfIntersection = 651,
  WireCrossing = 652,
  PatchTwisted = 653,
  SurfaceFold = 654,
  ClosureMismatch = 655,
  UvOutOfRange = 656,
  SectionsCoarsened = 657,
  // Numbers
  IntegerUnitSuspect = 701,
  // Emitters and options
  CapacityTooSmall = 801,
  ProfileError = 802,
  StartBlockNotFound = 803,
  TaperFlattened = 804,
  PolarThroughCentre = 805,
  NotInOutputFormat = 806,
  OutputAdjusted = 807,
  OutputUnsure = 808,
  MachineProfileError = 810,
  TooManyDiagnostics = 899,
};

/// "K0302" for Code::RadiusTooSmall.
std::string codeName(Code code);
const char* severityName(Severity s);

struct Diagnostic {
  Severity severity = Severity::Error;
  Code code = Code::UnexpectedCharacter;
  const SourceFile* source = nullptr;  ///< null: not tied to a file (options, emitters)
  SourceSpan span;
  std::string message;
  std::string help;  ///< optional "did you mean ..." or how to fix it
  // Geometric findings also name the move (index into Toolpath::moves) and a 3D point (z = 0 on
  // the program plane), so the report, the picture and the window show the same place.
  std::optional<std::size_t> move;
  std::optional<geometry::Vec3> point;
};

/// What the user asked of the codes, as compilers take it (-Wno-K0604, -Werror=K0650, -Werror).
/// Every command applies it to the pipeline's findings, so they all say the same.
struct DiagnosticPolicy {
  std::vector<Code> silenced;      ///< -Wno-CODE: a warning or note not reported
  std::vector<Code> promoted;      ///< -Werror=CODE: reported as an error
  bool warningsAreErrors = false;  ///< -Werror: every warning is an error
  [[nodiscard]] bool empty() const { return silenced.empty() && promoted.empty() && !warningsAreErrors; }
  /// The severity d is reported with, or nothing when it is silenced. Errors are never silenced.
  [[nodiscard]] std::optional<Severity> levelOf(const Diagnostic& d) const;
};

/// Collects diagnostics up to a cap; counts every one.
class Diagnostics {
 public:
  explicit Diagnostics(std::size_t cap = 50) : cap_(cap) {}

  void report(Diagnostic d);
  void error(Code code, const SourceFile* src, SourceSpan span, std::string message, std::string help = {});
  void warning(Code code, const SourceFile* src, SourceSpan span, std::string message, std::string help = {});
  void note(Code code, const SourceFile* src, SourceSpan span, std::string message, std::string help = {});
  /// Appends what later reported (its counts and its dropped ones too), as if reported here.
  void append(Diagnostics&& later);

  [[nodiscard]] const std::vector<Diagnostic>& all() const { return items_; }
  [[nodiscard]] std::size_t errorCount() const { return errors_; }
  [[nodiscard]] std::size_t warningCount() const { return warnings_; }
  [[nodiscard]] std::size_t dropped() const { return dropped_; }
  [[nodiscard]] std::size_t cap() const { return cap_; }
  [[nodiscard]] bool hasErrors() const { return errors_ > 0; }
  /// Stable order for output: by file position, then as reported.
  void sortByPosition();
  /// The same diagnostics under a policy: silenced ones gone, promoted ones errors. Those dropped
  /// past the cap were never seen, so they keep their severities in the counts.
  [[nodiscard]] Diagnostics under(const DiagnosticPolicy& policy) const;

 private:
  std::size_t cap_;
  std::vector<Diagnostic> items_;
  std::size_t errors_ = 0;
  std::size_t warnings_ = 0;
  std::size_t dropped_ = 0;
};

/// One diagnostic as text: the location line, the source line and a caret under the span.
std::string formatDiagnostic(const Diagnostic& d);

/// "file:line:col" (or the file name alone for a span-less diagnostic).
std::string formatLocation(const Diagnostic& d);

}  // namespace kerf::converter
