// Machine profiles: what one controller means by its words (docs/machines.md).
//
// A profile sets the arc-centre convention, the unit of integer coordinates, what U V mean, how
// `;` splits blocks, the machine's taper and U/V limits, and the codes that machine knows beyond
// the standard ISO set, each with what it does. Built-in profiles live in converter/machines/ as
// text, compiled in; a user's own is the same text format (`--machine FILE`). When no profile is
// named, detectMachine() picks one from the program's evidence and says why.
#pragma once

#include "kerf/converter/interpret/offset_table.h"
#include "kerf/converter/nc/diagnostics.h"
#include "kerf/converter/nc/program.h"
#include "kerf/converter/nc/source.h"
#include "kerf/converter/toolpath.h"

#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace kerf::converter {

const char* integerUnitName(IntegerUnit u);  ///< "mm", "um"
const char* arcCentreName(ArcCentreMode m);  ///< "incremental", "reversed", "absolute"
/// What I J are under a convention: "centre minus start", "start minus centre", "the centre itself".
const char* arcCentreMeaning(ArcCentreMode m);
/// The centre I J give: "centre = start + (I, J)", "centre = start - (I, J)", "centre = (I, J)".
const char* arcCentreRule(ArcCentreMode m);
std::optional<ArcCentreMode> parseArcCentre(std::string_view name);

/// What a code the profile knows does on that machine.
enum class CodeEffect : std::uint8_t {
  Harmless,     ///< no effect on the programmed path: a note, once per code
  NotModelled,  ///< changes the path in a way Kerf does not model: a warning, once per code
  Position,     ///< moves the wire to a place known only at the machine (edge sensing, homing)
  NoMotion,     ///< the block's axis words are parameters, not a destination (`G83 Y101`)
  Thickness,    ///< P is the workpiece thickness: the upper plane is that far above the lower
  Guides,       ///< P Q give the wire guides' geometry: accepted, not needed for the part
  ProgramEnd,   ///< ends the program, as M02 does
  Rethread,     ///< cuts or threads the wire: a rapid next to it goes to a new start hole (as after M00)
  Condition,    ///< selects a machining condition (Sodick C001): each pass reports the one in force
  // The taper corner model in force from the code on (docs/taper.md, "Corners"): how a corner
  // rounded at the program plane (`,R`, NCVC's R) is made on the other planes.
  CornerEqual,        ///< the same radius on every plane (an oblique cylinder); K beside R: the upper plane's own
  CornerConicalMin,   ///< the taper's offset of the fillet (a cone), its offset the smaller of the neighbours'
  CornerConicalMean,  ///< the same, the mean of the neighbours' offsets
  CornerConicalMax,   ///< the same, the larger
  // What a taper does with the corners and arcs the program writes without corner words, from the
  // code on (Charmilles' G28/G29 as FeatureCAM describes them).
  CornerRounded,      ///< sharp corners rounded away from the program plane (a cone, its apex the corner); arcs conical
  CornerCylindrical,  ///< sharp corners kept sharp; an arc tangent to both neighbours keeps its radius on every plane
};
const char* codeEffectName(CodeEffect e);

struct KnownCode {
  std::string key;  ///< "G60", "M28", "T84", "G12.1"; a letter alone ("C") for any value; "QAIC" for a macro call
  CodeEffect effect = CodeEffect::Harmless;
  std::string note;  ///< one line: what it does on this machine
  // The key as numbers, to look codes up without building strings: letter, number (-1: any value
  // of the letter) and the digit after the point. A macro call has number -2.
  char letter = 0;
  int number = -1;
  int fraction = 0;
};

/// How fast a machine cuts, for the cutting-time estimate (docs/passes.md, "Cutting time"). The
/// defaults are assumptions (see there), the generic profile's; a profile sets its machine's own.
struct CuttingSpeeds {
  double roughRate = 100.0;     ///< rough_rate: mm² of cut face a minute where the wire cuts full material
  double skimSpeed = 10.0;      ///< skim_speed: mm/min along a skim
  double rapidSpeed = 1000.0;   ///< rapid_speed: mm/min of a rapid
  double threadSeconds = 30.0;  ///< thread_time: s to thread the wire in a start hole
  bool feedIsSpeed = false;     ///< feed = speed: the program's F is the wire's speed, mm/min (LinuxCNC, hot wire)
  /// `condition_speed C001 = 4`: mm/min of a pass cut under that machining condition (it wins over
  /// rough_rate and skim_speed), by the condition as the program writes it, upper case.
  std::map<std::string, double> conditionSpeeds;
};

struct MachineProfile {
  std::string name = "generic";
  std::string summary;               ///< one line for `kerf machines`
  std::vector<std::string> sources;  ///< where its facts come from
  /// nothing: decided by the arcs (incremental unless every I J arc closes only another way).
  std::optional<ArcCentreMode> arcCentre;
  /// nothing: decided by the numbers (micrometres when no length has a decimal point and the
  /// largest integer is above integerThreshold).
  std::optional<IntegerUnit> integerUnit;
  double integerThreshold = 1000.0;
  /// What U V mean when the words alone do not say (XyuvAbs, XyuvRel or XyuvLinuxCnc); nothing:
  /// decided by the numbers.
  std::optional<Dialect> uvDialect;
  bool semicolonEndsBlock = false;       ///< `;` ends a block (Sodick) instead of starting a comment
  bool upperAxesUZ = false;              ///< the second plane's axes are named U Z
  bool bareSetPositionIsOrigin = false;  ///< a bare `G92`: the current position becomes the origin (Robofil)
  bool legacyTaperCodes = false;         ///< cnc3's earlier M106 P L Q H / M107 P T, recognised by M106 with P and Q
  /// `guides = LOWER_Z, UPPER_Z`: the wire guides' heights, mm, the part's lower face at 0.
  std::optional<std::array<double, 2>> guides;
  bool bareCornerRadius =
      false;  ///< an R beside a G01, or beside a G02/G03's I J, rounds the block's corner (NCVC wire mode)
  double maxTaperDegrees = 30.0;    ///< the machine's largest wire slope
  std::optional<double> uvRange;    ///< largest |upper - lower| per axis, mm
  std::optional<double> thickness;  ///< default workpiece thickness, mm
  /// `home = X, Y`: where G28/G30 take the wire, mm in the program's frame [decided: the origin, as
  /// GRBL and LinuxCNC home to machine zero unless set]; `home = unknown`: only the machine knows.
  std::optional<std::array<double, 2>> home = std::array<double, 2>{0.0, 0.0};
  /// The speed model of the cutting-time estimate (docs/passes.md, "Cutting time").
  CuttingSpeeds speeds;
  // Writing for this machine (`kerf convert --to iso --for NAME`, docs/machines.md).
  bool writeMicrometres = false;          ///< write_unit = um: integers in µm, no decimal point
  bool crlf = false;                      ///< line_end = crlf
  Dialect writeTaper = Dialect::XyuvAbs;  ///< write_taper: xyuv-abs (cnc3 two motions) or sodick-colon
  int writeDecimals = 3;                  ///< write_decimals: digits after the point in mm output
  bool writeComment = true;               ///< write_comment: a first comment line saying what wrote it
  bool writeShortG = false;               ///< write_g = G1: `G1` rather than `G01`
  // Blocks around the motion (write_start, write_offset, write_cancel, write_end: blocks separated
  // by `|`; {x} {y} the start point, {g} G41 or G42, {offset} the first offset-on blocks, {cancel}
  // the cancel blocks when an offset is on). Empty: the built-in layout (docs/machines.md).
  std::vector<std::string> writeStart, writeOffset, writeCancel, writeEnd;
  // Between contours (write_wire_cut before the rapid to the next start hole, write_wire_thread
  // after it): the wire is cut and threaded again. [assumption: M00, the program stop of ISO 6983,
  // for the operator to do it; a machine with automatic threading names its own codes]
  std::vector<std::string> writeWireCut{"M00"}, writeWireThread{"M00"};
  // Polar coordinate interpolation (G12.1/G112, docs/polar.md).
  bool polarXRadius = true;     ///< polar_x = radius | diameter: X inside G12.1
  bool polarCDiameter = false;  ///< polar_c = linear | diameter: Star machines write C as a diameter
  /// polar_frame = tool | table: the frame of G12.1 turns with the table's C when G12.1 is commanded
  /// (Fanuc 15i-MA: the tool's position is angle 0), or is the table's frame at C 0 (seed 002's post).
  bool polarFrameTable = false;
  std::vector<KnownCode> codes;
  /// `offset H001 = 0.180` lines: the machine's offset registers, for G41/G42 D.. or H.. that the
  /// program's own table and --offsets do not give.
  OffsetTable offsets;
  std::string text;  ///< the profile as written (`kerf machines show`)

  /// The entry for a code: "G60", "T84", "QAIC"; a letter-only entry matches any value of it.
  [[nodiscard]] const KnownCode* find(std::string_view key) const;
  /// The entry for letter + number (G 12 1 is G12.1), else the letter's own entry, else null.
  [[nodiscard]] const KnownCode* find(char letter, int number, int fraction) const;
};

/// Parses a profile file (docs/machines.md). Nothing, with errors (K0810) at file:line:col, when
/// a line is wrong. `name` defaults to the file's name without its folder and extension.
std::optional<MachineProfile> parseMachineProfile(const SourceFile& file, Diagnostics& diags);

/// The built-in profiles in `kerf machines` order: generic, robofil, sodick, linuxcnc, cnc3,
/// ncvc, fanuc.
const std::vector<MachineProfile>& builtinMachines();
/// A built-in profile by name, or null.
const MachineProfile* findBuiltinMachine(std::string_view name);
/// The built-in profiles, other than `except`, that know a code (for "did you mean" help).
std::vector<const MachineProfile*> machinesKnowing(std::string_view key, const MachineProfile* except);

struct MachineEvidence {
  std::string what;  ///< "G60 on line 3"
  SourceSpan span;
  int weight = 0;
};

/// Which built-in machine a program was written for, from its words (docs/machines.md lists the
/// evidence each profile looks for). The generic profile when nothing points elsewhere.
struct MachineDetection {
  const MachineProfile* profile = nullptr;
  std::vector<MachineEvidence> evidence;  ///< for the profile chosen, strongest first
};
MachineDetection detectMachine(const Program& program);

/// How a profile splits the text into blocks; `upperAxesUZ` (--upper-axes) wins over the profile's.
ParseOptions parseOptionsFor(const MachineProfile& machine, std::optional<bool> upperAxesUZ = std::nullopt);

/// A program parsed for its machine. `machine` is `given`, or the detected profile when none was
/// given; `diags` holds the parse's findings, for the caller to merge where it reports them.
struct MachineReading {
  Program program;
  const MachineProfile* machine = nullptr;
  MachineDetection detection;  ///< empty when a machine was given
  ParseOptions parse;
  Diagnostics diags{kAllDiagnostics};
};

/// Parses with `given`'s rules (the generic profile's when null); with none given, detects the
/// profile from the program and parses again when that profile splits blocks differently
/// (Sodick's ';' ends a block). The one place a program meets its machine profile.
MachineReading readForMachine(const SourceFile& source, const MachineProfile* given,
                              std::optional<bool> upperAxesUZ = std::nullopt);

}  // namespace kerf::converter
