// Which format a text is in, from its content (read.h).
#include "kerf/converter/formats/read.h"

#include "kerf/converter/formats/3b/read_3b.h"
#include "kerf/converter/formats/curve/read_curve.h"
#include "kerf/converter/formats/dxf/read_dxf.h"

#include <cctype>
#include <string>

namespace kerf::converter {

const char* inputFormatName(InputFormat f) {
  return f == InputFormat::ThreeB ? "3b" : f == InputFormat::Dxf ? "dxf" : f == InputFormat::Curve ? "curve" : "iso";
}

std::optional<InputFormat> parseInputFormat(std::string_view name) {
  std::string n;
  for (char c : name) n += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (n == "iso") return InputFormat::Iso;
  if (n == "3b") return InputFormat::ThreeB;
  if (n == "dxf") return InputFormat::Dxf;
  if (n == "curve") return InputFormat::Curve;
  return std::nullopt;
}

FormatDetection detectFormat(std::string_view text) {
  FormatDetection d;
  if (looksLikeDxf(text)) {
    d.format = InputFormat::Dxf;
    d.why = "it starts as a DXF file does";
    return d;
  }
  if (looksLikeCurve(text)) {
    d.format = InputFormat::Curve;
    d.why = "it starts with a curve's 'x =', 'y =', 't =' or 'points'";
    return d;
  }
  const std::string record = firstThreeBRecord(text);
  if (!record.empty()) {
    d.format = InputFormat::ThreeB;
    d.why = "3B code: the text starts with a record, " + record;
  }
  return d;
}

}  // namespace kerf::converter
