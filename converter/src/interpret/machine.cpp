// Machine profiles: the text format, the built-in profiles (converter/machines/, compiled in) and
// detection from a program's evidence, and reading a program with its profile.
//
// Sections: 1. names  2. the profile file  3. built-ins  4. detection  5. reading a program for its machine
#include "kerf/converter/interpret/machine.h"

#include "kerf/converter/interpret/dialect.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <map>

namespace kerf::converter {

namespace machines {
struct EmbeddedFile {
  const char* name;
  const char* text;
};
extern const EmbeddedFile kFiles[];
extern const std::size_t kFileCount;
}  // namespace machines

// ---- 1. names -----------------------------------------------------------------------------------

const char* integerUnitName(IntegerUnit u) { return u == IntegerUnit::Micrometre ? "um" : "mm"; }

namespace {

/// Each I J convention: its name (profiles, options, reports), what I J are, the centre they give.
struct ArcCentreWords {
  ArcCentreMode mode;
  const char* name;
  const char* meaning;
  const char* rule;
};
constexpr ArcCentreWords kArcCentres[] = {
    {ArcCentreMode::Incremental, "incremental", "centre minus start", "centre = start + (I, J)"},
    {ArcCentreMode::Reversed, "reversed", "start minus centre", "centre = start - (I, J)"},
    {ArcCentreMode::Absolute, "absolute", "the centre itself", "centre = (I, J)"},
};

const ArcCentreWords& wordsOf(ArcCentreMode m) {
  for (const ArcCentreWords& w : kArcCentres)
    if (w.mode == m) return w;
  return kArcCentres[0];
}

}  // namespace

const char* arcCentreName(ArcCentreMode m) { return wordsOf(m).name; }
const char* arcCentreMeaning(ArcCentreMode m) { return wordsOf(m).meaning; }
const char* arcCentreRule(ArcCentreMode m) { return wordsOf(m).rule; }

std::optional<ArcCentreMode> parseArcCentre(std::string_view name) {
  for (const ArcCentreWords& w : kArcCentres)
    if (name == w.name) return w.mode;
  return std::nullopt;
}

const char* codeEffectName(CodeEffect e) {
  switch (e) {
    case CodeEffect::Harmless: return "harmless";
    case CodeEffect::NotModelled: return "not-modelled";
    case CodeEffect::Position: return "position";
    case CodeEffect::NoMotion: return "no-motion";
    case CodeEffect::Thickness: return "thickness";
    case CodeEffect::Guides: return "guides";
    case CodeEffect::ProgramEnd: return "program-end";
    case CodeEffect::Rethread: return "rethread";
    case CodeEffect::Condition: return "condition";
    case CodeEffect::CornerEqual: return "corner-equal";
    case CodeEffect::CornerConicalMin: return "corner-conical-min";
    case CodeEffect::CornerConicalMean: return "corner-conical-mean";
    case CodeEffect::CornerConicalMax: return "corner-conical-max";
    case CodeEffect::CornerRounded: return "corner-rounded";
    case CodeEffect::CornerCylindrical: return "corner-cylindrical";
  }
  return "harmless";
}

const KnownCode* MachineProfile::find(std::string_view key) const {
  for (const KnownCode& c : codes)
    if (c.key == key) return &c;
  return nullptr;
}

const KnownCode* MachineProfile::find(char letter, int number, int fraction) const {
  const KnownCode* any = nullptr;
  for (const KnownCode& c : codes) {
    if (c.letter != letter) continue;
    if (c.number == number && c.fraction == fraction) return &c;
    if (c.number == -1) any = &c;
  }
  return any;
}

// ---- 2. the profile file ------------------------------------------------------------------------

namespace {

std::string trim(std::string_view s) {
  std::size_t b = 0, e = s.size();
  while (b < e && (s[b] == ' ' || s[b] == '\t' || s[b] == '\r')) ++b;
  while (e > b && (s[e - 1] == ' ' || s[e - 1] == '\t' || s[e - 1] == '\r')) --e;
  return std::string(s.substr(b, e - b));
}

std::string upperCase(std::string s) {
  for (char& c : s)
    if (c >= 'a' && c <= 'z') c = static_cast<char>(c - 'a' + 'A');
  return s;
}

/// "G02" -> "G2", "g12.1" -> "G12.1", "qaic" -> "QAIC", "c" -> "C". Empty when it is no code.
std::string normaliseKey(std::string_view raw) {
  const std::string key = upperCase(trim(raw));
  if (key.empty() || key[0] < 'A' || key[0] > 'Z') return {};
  if (key.size() == 1) return key;
  if (key[0] == 'Q' &&
      std::all_of(key.begin() + 1, key.end(), [](char c) { return (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9'); }))
    return key;  // a Sodick macro call name
  const std::string number = key.substr(1);
  if (number.find_first_not_of("0123456789.") != std::string::npos || number.front() == '.' ||
      std::count(number.begin(), number.end(), '.') > 1)
    return {};
  const double v = std::strtod(number.c_str(), nullptr);
  if (!(v < 1e6)) return {};  // no code has seven digits (and the key's number is an int: readCode)
  const long tenths = roundHalfAway(v * 10);
  if (std::abs(v * 10 - static_cast<double>(tenths)) > 1e-9) return {};
  std::string out(1, key[0]);
  out += std::to_string(tenths / 10);
  if (tenths % 10) out += "." + std::to_string(tenths % 10);
  return out;
}

std::optional<double> number(const std::string& value) {
  char* end = nullptr;
  const double v = std::strtod(value.c_str(), &end);
  if (value.empty() || end != value.c_str() + value.size() || !std::isfinite(v)) return std::nullopt;
  return v;
}

std::string baseName(const std::string& path) {
  std::string name = path.substr(path.find_last_of('/') == std::string::npos ? 0 : path.find_last_of('/') + 1);
  if (const auto dot = name.find('.'); dot != std::string::npos && dot > 0) name.resize(dot);
  return name;
}

}  // namespace

namespace {

/// One `key = value` line of a profile, with what reports a problem at it.
struct ProfileLine {
  const SourceFile& file;
  Diagnostics& diags;
  bool& ok;
  std::uint32_t begin = 0;  // the line's offset in the file
  std::size_t lead = 0, eq = 0, valueAt = 0;
  std::string key, value;

  void fail(std::size_t at, std::size_t length, std::string message, std::string help = {}) const {
    diags.error(Code::MachineProfileError, &file,
                {static_cast<std::uint32_t>(begin + at), static_cast<std::uint32_t>(std::max<std::size_t>(1, length))},
                std::move(message), std::move(help));
    ok = false;
  }
  void badValue(const std::string& allowed) const {
    fail(valueAt, value.size(), "'" + value + "' is not a value of " + key, "allowed: " + allowed);
  }
  /// A key with two values: `off` sets the flag false, `on` sets it true.
  void either(bool& flag, const char* off, const char* on) const {
    if (value == off || value == on)
      flag = value == on;
    else
      badValue(std::string(off) + " or " + on);
  }
};

/// `code G60 = effect: note`.
void readCode(const ProfileLine& l, MachineProfile& p) {
  KnownCode c;
  c.key = normaliseKey(l.key.substr(5));
  if (c.key.empty()) {
    l.fail(l.lead, l.eq - l.lead, "'" + trim(l.key.substr(5)) + "' is not a code", "write G60, M28, T84, C or QAIC");
    return;
  }
  c.letter = c.key[0];
  if (c.key.size() > 1 && c.key[0] == 'Q' && (c.key[1] < '0' || c.key[1] > '9')) {
    c.number = -2;  // a macro call's name
  } else if (c.key.size() > 1) {
    const double v = std::strtod(c.key.c_str() + 1, nullptr);
    if (!(v >= 0 && v < 1e6)) {  // `Q2222...AIC` passes as a macro name but reads as a number here
      l.fail(l.lead, l.eq - l.lead, "'" + trim(l.key.substr(5)) + "' is not a code", "write G60, M28, T84, C or QAIC");
      return;
    }
    c.number = static_cast<int>(v);
    c.fraction = static_cast<int>(std::lround((v - c.number) * 10));
  }
  const std::size_t colon = l.value.find(':');
  const std::string effect = trim(l.value.substr(0, colon));
  c.note = colon == std::string::npos ? std::string{} : trim(l.value.substr(colon + 1));
  bool known = false;
  for (CodeEffect e :
       {CodeEffect::Harmless, CodeEffect::NotModelled, CodeEffect::Position, CodeEffect::NoMotion,
        CodeEffect::Thickness, CodeEffect::Guides, CodeEffect::ProgramEnd, CodeEffect::Rethread, CodeEffect::Condition,
        CodeEffect::CornerEqual, CodeEffect::CornerConicalMin, CodeEffect::CornerConicalMean,
        CodeEffect::CornerConicalMax, CodeEffect::CornerRounded, CodeEffect::CornerCylindrical})
    if (effect == codeEffectName(e)) {
      c.effect = e;
      known = true;
    }
  if (!known) {
    l.badValue(
        "harmless, not-modelled, position, no-motion, thickness, guides, program-end, rethread, condition, "
        "corner-equal, corner-conical-min, corner-conical-mean, corner-conical-max, corner-rounded or "
        "corner-cylindrical, then ': note'");
    return;
  }
  if (c.note.empty()) {
    l.fail(l.valueAt, l.value.size(), "code " + c.key + " needs a note: what it does on this machine",
           "write 'harmless: meaning not modelled' when it is not known");
    return;
  }
  if (p.find(c.key)) {
    l.fail(l.lead, l.eq - l.lead, "code " + c.key + " is listed twice");
    return;
  }
  p.codes.push_back(std::move(c));
}

/// `offset H001 = 0.180`: a register of the machine's offset table, mm.
void readOffset(const ProfileLine& l, MachineProfile& p) {
  const std::string name = offsetRegisterName(std::string_view(l.key).substr(7));
  if (name.empty()) {
    l.fail(l.lead, l.eq - l.lead, "'" + trim(l.key.substr(7)) + "' is not a D or H register",
           "write offset H001 = 0.180");
    return;
  }
  double value = 0.0;
  if (!parseNumberField(l.value, value) || value < 0.0 || value > kLargestTableOffset) {
    l.fail(l.valueAt, l.value.size(), name + ": '" + l.value + "' is not an offset from 0 to 10 mm");
    return;
  }
  if (!p.offsets.emplace(name, value).second) l.fail(l.lead, l.eq - l.lead, name + " is given twice");
}

/// `condition_speed C001 = 4`: mm/min of a pass cut under that machining condition.
void readConditionSpeed(const ProfileLine& l, MachineProfile& p) {
  std::string name = trim(l.key.substr(16));
  for (char& c : name) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  const bool wellFormed = name.size() >= 2 && std::isalpha(static_cast<unsigned char>(name[0])) &&
                          name.find_first_not_of("0123456789", 1) == std::string::npos;
  if (!wellFormed) {
    l.fail(l.lead, l.eq - l.lead, "'" + trim(l.key.substr(16)) + "' is not a condition",
           "write condition_speed C001 = 4");
    return;
  }
  double value = 0.0;
  if (!parseNumberField(l.value, value) || value <= 0.0 || value > 1e6) {
    l.fail(l.valueAt, l.value.size(), name + ": '" + l.value + "' is not a speed above 0 mm/min");
    return;
  }
  if (!p.speeds.conditionSpeeds.emplace(name, value).second) l.fail(l.lead, l.eq - l.lead, name + " is given twice");
}

/// The keys of what the machine means by its words; false for a key that is none of them.
bool readReadingKey(const ProfileLine& l, MachineProfile& p) {
  const std::string& key = l.key;
  const std::string& value = l.value;
  if (key == "name") {
    if (value.empty() || value.find_first_of(" \t/") != std::string::npos)
      l.badValue("one word");
    else
      p.name = value;
  } else if (key == "summary") {
    p.summary = value;
  } else if (key == "source") {
    p.sources.push_back(value);
  } else if (key == "arc_centre") {
    if (value == "auto")
      p.arcCentre.reset();
    else if (auto m = parseArcCentre(value))
      p.arcCentre = m;
    else
      l.badValue("incremental, reversed, absolute or auto");
  } else if (key == "integer_unit") {
    if (value == "auto")
      p.integerUnit.reset();
    else if (value == "mm")
      p.integerUnit = IntegerUnit::Millimetre;
    else if (value == "um")
      p.integerUnit = IntegerUnit::Micrometre;
    else
      l.badValue("mm, um or auto");
  } else if (key == "integer_threshold") {
    if (auto v = number(value); v && *v >= 0)
      p.integerThreshold = *v;
    else
      l.badValue("a number of 0 or more");
  } else if (key == "uv_words") {
    const auto d = parseDialect(value);
    if (value == "auto")
      p.uvDialect.reset();
    else if (d && (*d == Dialect::XyuvAbs || *d == Dialect::XyuvRel || *d == Dialect::XyuvLinuxCnc))
      p.uvDialect = d;
    else
      l.badValue("xyuv-abs, xyuv-rel, xyuv-linuxcnc or auto");
  } else if (key == "polar_x") {
    l.either(p.polarXRadius, "diameter", "radius");
  } else if (key == "polar_c") {
    l.either(p.polarCDiameter, "linear", "diameter");
  } else if (key == "polar_frame") {
    l.either(p.polarFrameTable, "tool", "table");
  } else if (key == "semicolon") {
    l.either(p.semicolonEndsBlock, "comment", "end-of-block");
  } else if (key == "upper_axes") {
    l.either(p.upperAxesUZ, "uv", "uz");
  } else if (key == "bare_g92") {
    l.either(p.bareSetPositionIsOrigin, "error", "origin");
  } else if (key == "legacy_taper_codes") {
    l.either(p.legacyTaperCodes, "no", "detect");
  } else if (key == "corner_r") {
    l.either(p.bareCornerRadius, "comma", "bare");
  } else {
    return false;
  }
  return true;
}

/// The keys of the machine itself: its limits, speeds, home and guides, and the thickness it holds;
/// false for a key that is none of them.
bool readMachineKey(const ProfileLine& l, MachineProfile& p) {
  const std::string& key = l.key;
  const std::string& value = l.value;
  if (key == "max_taper") {
    if (auto v = number(value); v && *v >= 0 && *v <= 89)
      p.maxTaperDegrees = *v;
    else
      l.badValue("degrees from 0 to 89");
  } else if (key == "rough_rate" || key == "skim_speed" || key == "rapid_speed") {
    double& slot = key == "rough_rate"   ? p.speeds.roughRate
                   : key == "skim_speed" ? p.speeds.skimSpeed
                                         : p.speeds.rapidSpeed;
    if (auto v = number(value); v && *v > 0 && *v <= 1e6)
      slot = *v;
    else
      l.badValue(key == "rough_rate" ? "mm²/min above 0" : "mm/min above 0");
  } else if (key == "thread_time") {
    if (auto v = number(value); v && *v >= 0 && *v <= 86400)
      p.speeds.threadSeconds = *v;
    else
      l.badValue("seconds from 0 to 86400");
  } else if (key == "feed") {
    l.either(p.speeds.feedIsSpeed, "machine", "speed");
  } else if (key == "home") {
    const std::size_t comma = value.find(',');
    const auto x = comma == std::string::npos ? std::nullopt : number(trim(value.substr(0, comma)));
    const auto y = comma == std::string::npos ? std::nullopt : number(trim(value.substr(comma + 1)));
    if (value == "unknown")
      p.home.reset();
    else if (x && y && std::abs(*x) <= 1e6 && std::abs(*y) <= 1e6)
      p.home = std::array<double, 2>{*x, *y};
    else
      l.badValue("unknown, or X, Y in mm within 1e6");
  } else if (key == "guides") {
    const std::size_t comma = value.find(',');
    const std::optional<double> lo = number(trim(value.substr(0, comma)));
    std::optional<double> hi;
    if (comma != std::string::npos) hi = number(trim(value.substr(comma + 1)));
    if (value == "none")
      p.guides.reset();
    else if (lo && hi && *lo < *hi && std::abs(*lo) <= 1e5 && std::abs(*hi) <= 1e5)
      p.guides = std::array<double, 2>{*lo, *hi};
    else
      l.badValue("none, or LOWER_Z, UPPER_Z in mm within 1e5, the lower below the upper (the part's lower face at 0)");
  } else if (key == "uv_range" || key == "thickness") {
    std::optional<double>& slot = key == "uv_range" ? p.uvRange : p.thickness;
    if (value == "none")
      slot.reset();
    else if (auto v = number(value); v && *v > 0)
      slot = v;
    else
      l.badValue("none or a length in mm above 0");
  } else {
    return false;
  }
  return true;
}

/// The first `{...}` in a write_* block that the writer would not fill for that key (it would be
/// written verbatim); empty when there is none. {x} {y} everywhere; {g} in write_offset and
/// write_cancel; {offset} as a whole block of write_start and {cancel} of write_end.
std::string unknownPlaceholder(const std::string& key, const std::string& block) {
  if ((key == "write_start" && block == "{offset}") || (key == "write_end" && block == "{cancel}")) return {};
  const bool g = key == "write_offset" || key == "write_cancel";
  for (std::size_t open = block.find('{'); open != std::string::npos; open = block.find('{', open + 1)) {
    const std::size_t close = block.find('}', open);
    const std::string token = block.substr(open, close == std::string::npos ? std::string::npos : close - open + 1);
    if (token != "{x}" && token != "{y}" && !(g && token == "{g}")) return token;
  }
  return {};
}

/// The keys of how `kerf convert --to iso --for` writes for the machine; false for another key.
bool readWritingKey(const ProfileLine& l, MachineProfile& p) {
  const std::string& key = l.key;
  const std::string& value = l.value;
  if (key == "write_unit") {
    l.either(p.writeMicrometres, "mm", "um");
  } else if (key == "line_end") {
    l.either(p.crlf, "lf", "crlf");
  } else if (key == "write_decimals") {
    if (auto v = number(value); v && *v >= 0 && *v <= 6 && *v == std::floor(*v))
      p.writeDecimals = static_cast<int>(*v);
    else
      l.badValue("a whole number from 0 to 6");
  } else if (key == "write_comment") {
    l.either(p.writeComment, "no", "yes");
  } else if (key == "write_g") {
    l.either(p.writeShortG, "G01", "G1");
  } else if (key == "write_start" || key == "write_offset" || key == "write_cancel" || key == "write_end" ||
             key == "write_wire_cut" || key == "write_wire_thread") {
    std::vector<std::string>& blocks = key == "write_start"      ? p.writeStart
                                       : key == "write_offset"   ? p.writeOffset
                                       : key == "write_cancel"   ? p.writeCancel
                                       : key == "write_wire_cut" ? p.writeWireCut
                                       : key == "write_end"      ? p.writeEnd
                                                                 : p.writeWireThread;
    blocks.clear();
    std::size_t from = 0;
    while (from <= value.size()) {
      const std::size_t bar = value.find('|', from);
      const std::string b = trim(value.substr(from, bar == std::string::npos ? std::string::npos : bar - from));
      if (const std::string bad = unknownPlaceholder(key, b); !bad.empty()) {
        l.fail(l.valueAt, l.value.size(),
               key + ": '" + bad + "' is not a placeholder this key fills (it would be written as it stands)",
               "{x} {y} the start; {g} in write_offset and write_cancel; {offset} alone in write_start, {cancel} "
               "alone in write_end (docs/machines.md)");
        return true;
      }
      if (!b.empty()) blocks.push_back(b);
      if (bar == std::string::npos) break;
      from = bar + 1;
    }
  } else if (key == "write_taper") {
    bool colon = false;
    l.either(colon, "xyuv-abs", "sodick-colon");
    p.writeTaper = colon ? Dialect::SodickColon : Dialect::XyuvAbs;
  } else {
    return false;
  }
  return true;
}

}  // namespace

std::optional<MachineProfile> parseMachineProfile(const SourceFile& file, Diagnostics& diags) {
  MachineProfile p;
  p.name = baseName(file.name());
  p.text = std::string(file.text());
  bool ok = true;
  for (std::uint32_t line = 1; line <= file.lineCount(); ++line) {
    const auto range = file.lineRange(line);
    const std::string_view text = file.text().substr(range.first, range.second - range.first);
    if (const std::string t = trim(text); t.empty() || t[0] == '#') continue;
    ProfileLine l{file, diags, ok, range.first, 0, 0, 0, {}, {}};
    l.lead = text.find_first_not_of(" \t");
    l.eq = text.find('=');
    if (l.eq == std::string_view::npos) {
      l.fail(l.lead, text.size() - l.lead, "expected 'key = value'");
      continue;
    }
    l.key = trim(text.substr(0, l.eq));
    l.value = trim(text.substr(l.eq + 1));
    l.valueAt = std::min(text.size(), text.find_first_not_of(" \t", l.eq + 1));
    if (l.key.rfind("code ", 0) == 0 || l.key.rfind("code\t", 0) == 0)
      readCode(l, p);
    else if (l.key.rfind("offset ", 0) == 0 || l.key.rfind("offset\t", 0) == 0)
      readOffset(l, p);
    else if (l.key.rfind("condition_speed ", 0) == 0 || l.key.rfind("condition_speed\t", 0) == 0)
      readConditionSpeed(l, p);
    else if (!readReadingKey(l, p) && !readMachineKey(l, p) && !readWritingKey(l, p))
      l.fail(l.lead, l.eq - l.lead, "unknown key '" + l.key + "'",
             "keys: name, summary, source, arc_centre, integer_unit, integer_threshold, uv_words, semicolon, "
             "upper_axes, bare_g92, legacy_taper_codes, corner_r, guides, max_taper, uv_range, thickness, home, "
             "rough_rate, "
             "skim_speed, "
             "rapid_speed, thread_time, feed, write_unit, line_end, "
             "write_taper, write_decimals, write_comment, write_g, write_start, write_offset, write_cancel, "
             "write_end, polar_x, polar_c, polar_frame, code <CODE>, offset <REGISTER>, condition_speed <CONDITION>");
  }
  if (!ok) return std::nullopt;
  return p;
}

// ---- 3. built-ins ---------------------------------------------------------------------------------

const std::vector<MachineProfile>& builtinMachines() {
  static const std::vector<MachineProfile> all = [] {
    static constexpr std::array<const char*, 7> kOrder = {"generic", "robofil", "sodick", "linuxcnc",
                                                          "cnc3",    "ncvc",    "fanuc"};
    std::vector<MachineProfile> out;
    for (const char* name : kOrder) {
      for (std::size_t k = 0; k < machines::kFileCount; ++k) {
        if (std::string(machines::kFiles[k].name) != std::string(name) + ".profile") continue;
        const SourceFile file(machines::kFiles[k].name, machines::kFiles[k].text);
        Diagnostics diags;
        // The built-in files are tested (machine_test.cpp): a profile that does not parse is
        // left out rather than half read.
        if (std::optional<MachineProfile> p = parseMachineProfile(file, diags)) out.push_back(std::move(*p));
      }
    }
    return out;
  }();
  return all;
}

const MachineProfile* findBuiltinMachine(std::string_view name) {
  for (const MachineProfile& m : builtinMachines())
    if (m.name == name) return &m;
  return nullptr;
}

std::vector<const MachineProfile*> machinesKnowing(std::string_view key, const MachineProfile* except) {
  std::vector<const MachineProfile*> out;
  for (const MachineProfile& m : builtinMachines()) {
    if (&m == except || (except && m.name == except->name)) continue;
    if (key == "bare G92" ? m.bareSetPositionIsOrigin : m.find(key) != nullptr) out.push_back(&m);
  }
  return out;
}

// ---- 4. detection ---------------------------------------------------------------------------------

namespace {

/// Evidence for one profile: each kind of evidence counted once, at its first place.
struct Tally {
  std::vector<MachineEvidence> items;
  std::vector<std::string> seen;
  /// Counts `kind` once, at its first place; `what` is only built then.
  template <typename What>
  void add(const std::string& kind, What&& what, SourceSpan span, int weight) {
    if (std::find(seen.begin(), seen.end(), kind) != seen.end()) return;
    seen.push_back(kind);
    items.push_back({what(), span, weight});
  }
  [[nodiscard]] int score() const {
    int s = 0;
    for (const MachineEvidence& e : items) s += e.weight;
    return s;
  }
};

}  // namespace

namespace {

using Tallies = std::map<std::string, Tally>;

/// Evidence outside the blocks: Robofil's (MEM:...) header, Sodick's condition and offset tables
/// and TP/TN heights, LinuxCNC's AXIS height comments.
void fileEvidence(const Program& program, Tallies& t) {
  // Robofil names the program in its first line: % (MEM:F17A15.ISO)
  const std::string_view first = program.source->lineText(1);
  if (const auto at = first.find("(MEM:"); at != std::string_view::npos)
    t["robofil"].add(
        "mem", [] { return std::string("the (MEM:...) header on line 1"); }, {static_cast<std::uint32_t>(at), 5}, 3);
  for (const Setting& s : program.settings) {
    if (s.name[0] == 'C')
      t["sodick"].add(
          "conditions", [&] { return onLine("the condition table (" + s.name + " = ...)", s.line); }, s.span, 3);
    if (s.name[0] == 'H')
      t["sodick"].add(
          "offsets", [&] { return onLine("the offset table (" + s.name + " = ...)", s.line); }, s.span, 1);
  }
  for (const HeightWord& h : program.heights) {
    if (h.kind == HeightWord::Kind::SodickProgramPlane || h.kind == HeightWord::Kind::SodickLowerPlane)
      t["sodick"].add(
          "tp", [&] { return onLine("TP/TN plane heights", h.line); }, h.span, 2);
    else
      t["linuxcnc"].add(
          "axis", [&] { return onLine("an (AXIS,..._Z_POS,z) comment", h.line); }, h.span, 3);
  }
}

/// The G, M and T codes of block b that only some machines use. Sets g92 and taper when the block
/// has G92 or G51/G52 (evidence with other words of the block).
void codeEvidence(const Program& program, const Block& b, bool p, Tallies& t, bool& g92, bool& taper) {
  const std::string_view text = program.source->text();
  for (const Word& w : program.wordsOf(b)) {
    if (!w.isNumber() || (w.letter != 'G' && w.letter != 'M' && w.letter != 'T')) continue;
    // The common codes (G00-G03, G90-G92, M02 ...) are no evidence: out before any arithmetic.
    if (w.value < 28 || (w.value >= 90 && w.value <= 95 && w.letter == 'G')) {
      if (!(w.letter == 'G' && (std::abs(w.value - 12.1) < 1e-9 || std::abs(w.value - 13.1) < 1e-9)))
        if (!(w.letter == 'G' && w.value == 92)) continue;
    }
    const long n = roundHalfAway(w.value);
    const bool whole = std::abs(w.value - static_cast<double>(n)) < 1e-9;
    if (w.letter == 'G') {
      const long tenths = roundHalfAway(w.value * 10);
      if (whole && (n == 60 || n == 38 || n == 39))
        t["robofil"].add(
            "G" + std::to_string(n), [&] { return onLine("G" + std::to_string(n), program.lineOf(b)); }, w.span(), 2);
      if (whole && n >= 140 && n <= 142)
        t["sodick"].add(
            "colon", [&] { return onLine("G" + std::to_string(n), program.lineOf(b)); }, w.span(), 2);
      if ((whole && (n == 112 || n == 113)) || tenths == 121 || tenths == 131)
        t["fanuc"].add(
            "polar",
            [&] {
              return onLine("polar interpolation (" + std::string(text.substr(w.offset, w.length)) + ")",
                            program.lineOf(b));
            },
            w.span(), 3);
      if (whole && (n == 98 || n == 99))
        t["fanuc"].add(
            "g98", [&] { return onLine("G" + std::to_string(n), program.lineOf(b)); }, w.span(), 1);
      if (whole && (n == 61 || n == 64))
        t["linuxcnc"].add(
            "path", [&] { return onLine("G" + std::to_string(n) + " path control", program.lineOf(b)); }, w.span(), 1);
      g92 |= whole && n == 92;
      taper |= whole && (n == 51 || n == 52);
    } else if (w.letter == 'M' && whole) {
      if (n == 28)
        t["robofil"].add(
            "M28", [&] { return onLine("M28", program.lineOf(b)); }, w.span(), 2);
      if ((n == 100 || n == 101) && p)
        t["cnc3"].add(
            "geometry", [&] { return onLine("M" + std::to_string(n) + " P (taper geometry)", program.lineOf(b)); },
            w.span(), 3);
      if (n >= 105 && n <= 107 && p)
        t["cnc3"].add(
            "generator",
            [&] { return onLine("M" + std::to_string(n) + " P (generator and wire settings)", program.lineOf(b)); },
            w.span(), 2);
      if (n == 40 || n == 41 || (n >= 82 && n <= 85))
        t["cnc3"].add(
            "M" + std::to_string(n), [&] { return onLine("M" + std::to_string(n), program.lineOf(b)); }, w.span(), 1);
      if (n == 199)
        t["sodick"].add(
            "M199", [&] { return onLine("M199", program.lineOf(b)); }, w.span(), 1);
    } else if (w.letter == 'T' && whole && (n == 84 || n == 85 || n == 94)) {
      t["sodick"].add(
          "T" + std::to_string(n), [&] { return onLine("T" + std::to_string(n), program.lineOf(b)); }, w.span(), 1);
    }
  }
}

/// Block b's evidence: macro calls and macro B, two motion words, lower case, unusual values, its
/// codes, and the words that go together (G92 with I J, K L beside U V, G51/G52 with T).
void blockEvidence(const Program& program, const Block& b, Tallies& t) {
  if (b.kind == BlockKind::MacroCall) {
    const std::string_view call = program.textOf(b).substr(0, program.textOf(b).find('('));
    t["sodick"].add(
        "call", [&] { return onLine("the macro call " + std::string(call) + "(...)", program.lineOf(b)); }, b.span(),
        3);
    return;
  }
  if (b.kind == BlockKind::MacroB) {
    t["fanuc"].add(
        "macro", [&] { return onLine("macro B", program.lineOf(b)); }, b.span(), 2);
    return;
  }
  if (b.twoMotions)
    t["cnc3"].add(
        "two", [&] { return onLine("two motion words in one block", program.lineOf(b)); }, b.span(), 3);
  if (b.lowerCase)
    t["linuxcnc"].add(
        "lower", [&] { return onLine("lower-case words", program.lineOf(b)); }, b.span(), 1);
  std::uint32_t letters = 0;  // a bit per letter the block has
  for (const Word& w : program.wordsOf(b)) letters |= 1u << (w.letter - 'A');
  auto has = [&](char c) { return (letters & (1u << (c - 'A'))) != 0; };
  const bool p = has('P'), uv = has('U') || has('V'), kl = has('K') || has('L'), ij = has('I') || has('J');
  const bool tWord = has('T');
  bool g92 = false, taper = false;
  for (const Word& w : program.wordsOf(b))
    if (w.corner) {
      t["fanuc"].add(
          "corner", [&] { return onLine("a corner word (,R or ,C)", program.lineOf(b)); }, w.span(), 2);
      break;
    }
  if (b.unusualValues)
    for (const Word& w : program.wordsOf(b)) {
      if (w.kind == WordValue::Macro)
        t["fanuc"].add(
            "macro", [&] { return onLine("a macro B value", program.lineOf(b)); }, w.span(), 2);
      if (w.kind == WordValue::Register)
        t["sodick"].add(
            "register", [&] { return onLine("a register value", program.lineOf(b)); }, w.span(), 2);
    }
  codeEvidence(program, b, p, t, g92, taper);
  if (g92 && ij)
    t["ncvc"].add(
        "g92ij", [&] { return onLine("G92 with I J (plane heights)", program.lineOf(b)); }, b.span(), 3);
  if (uv && kl)
    t["ncvc"].add(
        "kl", [&] { return onLine("K L beside U V", program.lineOf(b)); }, b.span(), 2);
  if (taper && tWord)
    t["ncvc"].add(
        "t", [&] { return onLine("G51/G52 with a T angle", program.lineOf(b)); }, b.span(), 2);
}

}  // namespace

MachineDetection detectMachine(const Program& program) {
  Tallies t;
  fileEvidence(program, t);
  for (const std::uint32_t k : program.notPlain)
    blockEvidence(program, program.blocks[k], t);  // a plain block holds none
  MachineDetection d;
  d.profile = findBuiltinMachine("generic");
  int best = 1;  // a single weak hint is not enough
  for (const MachineProfile& m : builtinMachines()) {
    const auto it = t.find(m.name);
    if (it == t.end() || it->second.score() <= best) continue;
    best = it->second.score();
    d.profile = &m;
    d.evidence = it->second.items;
  }
  std::stable_sort(d.evidence.begin(), d.evidence.end(),
                   [](const MachineEvidence& a, const MachineEvidence& b) { return a.weight > b.weight; });
  return d;
}

// ---- 5. reading a program for its machine ---------------------------------------------------------

ParseOptions parseOptionsFor(const MachineProfile& machine, std::optional<bool> upperAxesUZ) {
  ParseOptions p;
  p.semicolonEndsBlock = machine.semicolonEndsBlock;
  p.upperAxesUZ = upperAxesUZ.value_or(machine.upperAxesUZ);
  return p;
}

MachineReading readForMachine(const SourceFile& source, const MachineProfile* given, std::optional<bool> upperAxesUZ) {
  MachineReading r;
  r.machine = given ? given : findBuiltinMachine("generic");
  r.parse = parseOptionsFor(*r.machine, upperAxesUZ);
  r.program = parseProgram(source, r.diags, r.parse);
  if (given) return r;
  r.detection = detectMachine(r.program);
  r.machine = r.detection.profile;
  if (const ParseOptions again = parseOptionsFor(*r.machine, upperAxesUZ); again != r.parse) {
    r.diags = Diagnostics(r.diags.cap());
    r.parse = again;
    r.program = parseProgram(source, r.diags, r.parse);
  }
  return r;
}

}  // namespace kerf::converter
