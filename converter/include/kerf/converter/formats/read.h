// Readers by format: the format is detected from the content, and every reader yields a Toolpath
// whose moves carry the span of the text they came from (docs/formats.md, docs/3b.md).
//
//   ISO G-code ──parse──▶ Program ──interpret──▶ Toolpath      (pipeline.h: machine profiles)
//   3B code    ──readThreeB──────────────────▶ Toolpath      (3b/read_3b.h: one Move per record)
//   DXF        ──readDxf──▶ Drawing                           (dxf/read_dxf.h; kerf cam makes a program)
//   a curve    ──readCurve──▶ Drawing                         (curve/read_curve.h)
//
// What follows the reader (checks, summary, explain, pictures, emitters) takes the source and the
// Toolpath, so a 3B file gets the same treatment as a G-code file.
#pragma once

#include "kerf/converter/nc/diagnostics.h"
#include "kerf/converter/nc/program.h"
#include "kerf/converter/nc/source.h"
#include "kerf/converter/toolpath.h"

#include <optional>
#include <string>
#include <string_view>

namespace kerf::converter {

/// "iso", "3b".
const char* inputFormatName(InputFormat f);
/// "iso" | "3b" (any case); nothing for another name.
std::optional<InputFormat> parseInputFormat(std::string_view name);

struct FormatDetection {
  InputFormat format = InputFormat::Iso;
  std::string why;  ///< "the first record, B9900 B0 B9900 GX L3, is 3B code" (empty for ISO)
};

/// The format of a text, from its content: 3B when the first thing that is not blank or a `;`
/// comment is a B field and the text holds a count direction (GX or GY); ISO otherwise.
FormatDetection detectFormat(std::string_view text);

}  // namespace kerf::converter
