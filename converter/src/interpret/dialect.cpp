#include "kerf/converter/interpret/dialect.h"

#include "../nc/gcode.h"

#include "kerf/converter/nc/number_format.h"

#include <cmath>
#include <cstdio>

namespace kerf::converter {

const char* dialectName(Dialect d) {
  switch (d) {
    case Dialect::Plain: return "plain";
    case Dialect::XyuvAbs: return "xyuv-abs";
    case Dialect::XyuvRel: return "xyuv-rel";
    case Dialect::XyuvLinuxCnc: return "xyuv-linuxcnc";
    case Dialect::SodickColon: return "sodick-colon";
    case Dialect::TaperAngle: return "taper-angle";
    case Dialect::TwoFile: return "two-file";
  }
  return "plain";
}

std::optional<Dialect> parseDialect(std::string_view name) {
  for (Dialect d : {Dialect::Plain, Dialect::XyuvAbs, Dialect::XyuvRel, Dialect::XyuvLinuxCnc, Dialect::SodickColon,
                    Dialect::TaperAngle})
    if (name == dialectName(d)) return d;
  return std::nullopt;
}

namespace {

struct Evidence {
  std::string what;
  SourceSpan span;
  [[nodiscard]] bool found() const { return !what.empty(); }
  void set(std::string w, SourceSpan s) {
    if (found()) return;
    what = std::move(w);
    span = s;
  }
};

std::string mm(double v) { return formatFixed(v, 3); }

/// Absolute U V track X Y: |U - X| is small against |U|. Relative U V are small deviations:
/// |U| is small against |U - X|. Compared over every U/V word of the motion blocks, with X Y
/// (and U V) modal in G90 and per block in G91.
struct NumberEvidence {
  double deviation = 0.0;  ///< sum of |U - X| and |V - Y|
  double magnitude = 0.0;  ///< sum of |U| and |V|
  std::size_t samples = 0;
  SourceSpan first;
  std::uint32_t firstLine = 0;
};

/// U V against X Y at the positions the words reach: under G91 the words are increments, so the
/// positions are summed (from 0, or where a G92 sets them; G28/G30 take the axes they name, all when
/// none, to 0: the home).
NumberEvidence compareNumbers(const Program& program) {
  NumberEvidence e;
  bool incremental = false;
  std::array<double, 4> at{};  // X Y U V
  constexpr std::array<char, 4> kAxes{'X', 'Y', 'U', 'V'};
  WordReader reader(program);
  for (const Block& b : program.blocks) {
    bool setPosition = false, home = false;
    std::array<const Word*, 4> given{};
    for (const Word& w : reader.words(b)) {
      if (const GCodeInfo* g = w.letter == 'G' && w.isNumber() ? findGCode(w.value) : nullptr) {
        if (g->code == GCode::Absolute) incremental = false;
        if (g->code == GCode::Incremental) incremental = true;
        if (g->code == GCode::SetPosition) setPosition = true;
        home |= g->code == GCode::ReferenceReturn || g->code == GCode::SecondReference;
      }
      for (std::size_t k = 0; k < kAxes.size(); ++k)
        if (w.letter == kAxes[k] && !given[k]) given[k] = &w;
    }
    if (home) {
      const bool all = std::none_of(given.begin(), given.end(), [](const Word* w) { return w != nullptr; });
      for (std::size_t k = 0; k < kAxes.size(); ++k)
        if (all || given[k]) at[k] = 0.0;
      continue;
    }
    for (std::size_t k = 0; k < kAxes.size(); ++k)
      if (given[k] && given[k]->isNumber())
        at[k] = incremental && !setPosition ? at[k] + given[k]->value : given[k]->value;
    if (setPosition || (!given[2] && !given[3])) continue;
    auto add = [&](std::size_t upper, std::size_t lower) {
      if (!given[upper]) return;
      const double dev = std::abs(at[upper] - at[lower]), mag = std::abs(at[upper]);
      if (dev < 1e-9 && mag < 1e-9) return;  // zero against zero tells nothing
      e.deviation += dev;
      e.magnitude += mag;
      if (e.samples++ == 0) {
        e.first = b.span();
        e.firstLine = program.lineOf(b);
      }
    };
    add(2, 0);
    add(3, 1);
  }
  return e;
}

/// Everything in the program that points at a dialect (docs/taper.md, "Dialects").
struct DialectEvidence {
  Evidence colon, taperAngle, colonMode, uv, abs, rel, linuxcnc, homesUv;
};

DialectEvidence gatherEvidence(const Program& program) {
  DialectEvidence e;
  for (const std::uint32_t index : program.notPlain) {  // a plain block holds no evidence
    const Block& b = program.blocks[index];
    const std::uint32_t line = program.lineOf(b);
    if (b.colon) e.colon.set(onLine("':'", line), b.span());
    bool setPosition = false, homing = false, hasUv = false, upperCentre = false, kl = false, g92ij = false;
    const auto words = program.wordsOf(b);
    for (std::size_t k = 0; k < words.size(); ++k) {
      const Word& w = words[k];
      const bool upperSide = k >= b.upperFrom;
      if (w.letter == 'G' && w.isNumber()) {
        const long tenths = roundHalfAway(w.value * 10);
        if (tenths == 510 || tenths == 520) e.taperAngle.set(onLine(tenths == 510 ? "G51" : "G52", line), w.span());
        if (tenths >= 1400 && tenths <= 1420 && tenths % 10 == 0)
          e.colonMode.set(onLine("G" + std::to_string(tenths / 10), line), w.span());
        if (tenths == 920) setPosition = true;
        if (tenths == 280 || tenths == 300) homing = true;
      } else if (w.letter == 'M' && w.isNumber()) {
        const long m = roundHalfAway(w.value);
        if (m == 100 || m == 101) e.abs.set(onLine("M" + std::to_string(m), line), w.span());
      } else if (w.letter == 'U' || w.letter == 'V') {
        hasUv = true;
      } else if (upperSide && (w.letter == 'I' || w.letter == 'J' || w.letter == 'R')) {
        upperCentre = true;
      } else if (w.letter == 'K' || w.letter == 'L') {
        kl = true;
      }
      if (setPosition && (w.letter == 'I' || w.letter == 'J')) g92ij = true;
    }
    if (hasUv && !setPosition) {
      e.uv.set(onLine("U/V", line), b.span());
      if (b.twoMotions) e.abs.set(onLine("a second motion word for U V", line), b.span());
      if (upperCentre) e.abs.set(onLine("a second I J / R for the upper arc", line), b.span());
      if (kl && !upperCentre) e.rel.set(onLine("K L with U V", line), b.span());
    }
    if (g92ij) e.rel.set(onLine("G92 with I J (NCVC plane heights)", line), b.span());
    if (homing && hasUv) e.homesUv.set(onLine("U V homed as axes of their own (G28/G30)", line), b.span());
  }
  for (const HeightWord& h : program.heights)
    if (h.kind == HeightWord::Kind::LinuxCncUvPlane || h.kind == HeightWord::Kind::LinuxCncXyPlane)
      e.linuxcnc.set(
          onLine(h.kind == HeightWord::Kind::LinuxCncUvPlane ? "(AXIS,UV_Z_POS)" : "(AXIS,XY_Z_POS)", h.line), h.span);
  // Carriages homed as axes are absolute positions (a hot-wire foam cutter): evidence for xyuv-abs
  // where nothing else says which (LinuxCNC's foam configs home them too, and say so in comments).
  if (e.homesUv.found() && !e.abs.found() && !e.linuxcnc.found()) e.abs = e.homesUv;
  return e;
}

}  // namespace

DialectDetection detectDialect(const Program& program, const MachineProfile& machine) {
  const DialectEvidence ev = gatherEvidence(program);
  const Evidence &colon = ev.colon, &taperAngle = ev.taperAngle, &colonMode = ev.colonMode, &uv = ev.uv, &abs = ev.abs,
                 &rel = ev.rel, &linuxcnc = ev.linuxcnc;
  DialectDetection d;
  auto choose = [&](Dialect dialect, const Evidence& e) {
    d.dialect = dialect;
    d.reason = e.what;
    d.span = e.span;
  };
  if (colon.found()) {
    choose(Dialect::SodickColon, colon);
  } else if (taperAngle.found()) {
    choose(Dialect::TaperAngle, taperAngle);
  } else if (colonMode.found()) {
    choose(Dialect::SodickColon, colonMode);
  } else if (uv.found()) {
    const int kinds = (abs.found() ? 1 : 0) + (rel.found() ? 1 : 0) + (linuxcnc.found() ? 1 : 0);
    if (kinds == 1) {
      if (abs.found()) choose(Dialect::XyuvAbs, abs);
      if (rel.found()) choose(Dialect::XyuvRel, rel);
      if (linuxcnc.found()) choose(Dialect::XyuvLinuxCnc, linuxcnc);
      return d;
    }
    if (kinds == 0 && machine.uvDialect) {
      choose(*machine.uvDialect, uv);
      d.reason = uv.what + ", which the " + machine.name + " profile reads as " + dialectName(*machine.uvDialect);
      return d;
    }
    if (kinds == 0) {
      const NumberEvidence n = compareNumbers(program);
      const double count = static_cast<double>(std::max<std::size_t>(n.samples, 1));
      const std::string numbers = "mean |U - X|, |V - Y| " + mm(n.deviation / count) + " against mean |U|, |V| " +
                                  mm(n.magnitude / count) + " over " + std::to_string(n.samples) + " words";
      if (n.samples > 0 && n.deviation <= 0.5 * n.magnitude) {
        choose(Dialect::XyuvAbs, uv);
        d.reason = uv.what + " and the numbers: U V follow X Y, so they are the upper contour itself (" + numbers + ")";
        return d;
      }
      if (n.samples > 0 && n.magnitude <= 0.5 * n.deviation) {
        choose(Dialect::XyuvRel, uv);
        d.reason = uv.what +
                   " and the numbers: U V stay small against X Y, so they are the upper contour's deviation (" +
                   numbers + ")";
        return d;
      }
      choose(Dialect::XyuvAbs, uv);
      d.reason = uv.what + " with nothing that tells whether U V are absolute or relative" +
                 (n.samples > 0 ? " (" + numbers + ")" : std::string{});
      d.candidates = {Dialect::XyuvAbs, Dialect::XyuvRel};
      return d;
    }
    choose(Dialect::XyuvAbs, uv);
    std::string list;
    if (abs.found()) list += abs.what + " (xyuv-abs)";
    if (rel.found()) list += std::string(list.empty() ? "" : ", ") + rel.what + " (xyuv-rel)";
    if (linuxcnc.found()) list += std::string(list.empty() ? "" : ", ") + linuxcnc.what + " (xyuv-linuxcnc)";
    d.reason = uv.what + ", with " + list;
    if (abs.found()) d.candidates.push_back(Dialect::XyuvAbs);
    if (rel.found()) d.candidates.push_back(Dialect::XyuvRel);
    if (linuxcnc.found()) d.candidates.push_back(Dialect::XyuvLinuxCnc);
  }
  return d;
}

std::string onLine(const std::string& what, std::uint32_t line) { return what + " on line " + std::to_string(line); }

}  // namespace kerf::converter
