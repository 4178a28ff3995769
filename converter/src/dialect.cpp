#include "kerf/converter/dialect.h"

#include <cmath>

namespace kerf::converter {

const char* dialectName(Dialect d) {
  switch (d) {
    case Dialect::Plain: return "plain";
    case Dialect::XyuvAbs: return "xyuv-abs";
    case Dialect::XyuvRel: return "xyuv-rel";
    case Dialect::SodickColon: return "sodick-colon";
    case Dialect::TaperAngle: return "taper-angle";
    case Dialect::TwoFile: return "two-file";
  }
  return "plain";
}

std::optional<Dialect> parseDialect(std::string_view name) {
  for (Dialect d : {Dialect::Plain, Dialect::XyuvAbs, Dialect::XyuvRel, Dialect::SodickColon, Dialect::TaperAngle})
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

std::string onLine(const std::string& what, std::uint32_t line) { return what + " on line " + std::to_string(line); }

}  // namespace

DialectDetection detectDialect(const Program& program) {
  Evidence colon, taperAngle, colonMode, uv, abs, rel;
  for (const Block& b : program.blocks) {
    if (b.colon) colon.set(onLine("':'", b.line), b.span());
    bool setPosition = false, hasUv = false, upperMotion = false, upperCentre = false, kl = false, g92ij = false;
    const auto words = program.wordsOf(b);
    for (std::size_t k = 0; k < words.size(); ++k) {
      const Word& w = words[k];
      const bool upperSide = k >= b.upperFrom;
      if (w.letter == 'G') {
        const long tenths = std::lround(w.value * 10);
        if (tenths == 510 || tenths == 520) taperAngle.set(onLine(tenths == 510 ? "G51" : "G52", b.line), w.span());
        if (tenths >= 1400 && tenths <= 1420 && tenths % 10 == 0)
          colonMode.set(onLine("G" + std::to_string(tenths / 10), b.line), w.span());
        if (tenths == 920) setPosition = true;
        if (upperSide && tenths <= 30 && tenths % 10 == 0) upperMotion = true;
      } else if (w.letter == 'M') {
        const long m = std::lround(w.value);
        if (m == 100 || m == 101) abs.set(onLine("M" + std::to_string(m), b.line), w.span());
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
      uv.set(onLine("U/V", b.line), b.span());
      if (upperMotion) abs.set(onLine("a second motion word for U V", b.line), b.span());
      if (upperCentre) abs.set(onLine("a second I J / R for the upper arc", b.line), b.span());
      if (kl && !upperCentre) rel.set(onLine("K L with U V", b.line), b.span());
    }
    if (g92ij) rel.set(onLine("G92 with I J (NCVC plane heights)", b.line), b.span());
  }
  for (const HeightWord& h : program.heights)
    if (h.kind == HeightWord::Kind::LinuxCncUvPlane) abs.set(onLine("(AXIS,UV_Z_POS)", h.line), h.span);

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
    if (abs.found() && !rel.found()) {
      choose(Dialect::XyuvAbs, abs);
    } else if (rel.found() && !abs.found()) {
      choose(Dialect::XyuvRel, rel);
    } else {
      choose(Dialect::XyuvAbs, uv);
      d.reason = abs.found() ? uv.what + ", with " + abs.what + " (xyuv-abs) and " + rel.what + " (xyuv-rel)"
                             : uv.what + " with nothing that tells whether U V are absolute or relative";
      d.candidates = {Dialect::XyuvAbs, Dialect::XyuvRel};
    }
  }
  return d;
}

}  // namespace kerf::converter
