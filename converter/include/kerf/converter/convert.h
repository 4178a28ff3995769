// Converting and making programs as the library does it: `kerf convert` (a program the pipeline
// read, written for another controller) and `kerf cam` (a program made from a drawing, written,
// read back and checked). The command line maps its options onto these requests and prints what
// comes back; an embedding (the HTML report) calls the same functions. Nothing here reads a file:
// a point profile or a machine profile comes as text.
#pragma once

#include "kerf/converter/cam/cam.h"
#include "kerf/converter/formats/emit.h"
#include "kerf/converter/pipeline.h"

#include <cstdint>
#include <memory>
#include <optional>
#include <string>

namespace kerf::converter {

/// What `kerf convert` asks.
struct ConvertRequest {
  std::string format;                      ///< a writer's name (emitters())
  std::optional<std::string> plane;        ///< lower, upper, z=HEIGHT; guides (points4)
  std::optional<std::size_t> pass;         ///< of each contour only its Nth pass (1: the rough cut)
  std::optional<SourceText> pointProfile;  ///< a point-file profile's text (docs/bp95d.md)
  std::optional<std::string> target;       ///< the built-in machine an ISO output is written for
  std::optional<SourceText> targetFile;    ///< or a machine profile's text
  EmitRequest emit;                        ///< the writers' settings; convert fills target, profile, planes
  double tolerance = 0.001;                ///< mm: a section between a taper's planes (--plane z=H)
  bool force = false;                      ///< write a program that has errors
};

/// How a conversion or a made program ended.
enum class WriteStatus : std::uint8_t {
  Written,        ///< `output` holds the text
  ProgramErrors,  ///< the program (or the drawing) has errors: nothing written (ConvertRequest::force writes)
  Refused,        ///< an option the program or the writer cannot take, a profile that does not parse
  NotWritten,     ///< the writer, or the check of what it wrote, refused: the diagnostics say why
};

struct Conversion {
  WriteStatus status = WriteStatus::Refused;
  std::optional<EmitOutput> output;
  /// The program's findings (what kerf check reports with the same options), then the conversion's.
  Diagnostics diags{kAllDiagnostics};
  std::unique_ptr<SourceFile> profileSource, targetSource;  ///< the texts the diagnostics may point into
};

/// The program `p` written as `r` asks. A program with errors is not written unless r.force.
Conversion convert(const Pipeline& p, const ConvertRequest& r);

/// What `kerf cam` asks: how to make the program, the writer, and how to read it back.
struct CamRequest {
  CamOptions cam;
  std::string format = "iso";  ///< a writer's name
  EmitRequest emit;            ///< decimals, compact, end, capacity, sampling (cam fills the ISO target and marks)
  /// The options `kerf check` would read the program made with (their reading options are replaced
  /// by the written format's and the drawing's machine).
  PipelineOptions readBack;
  std::string outputName = "<output>";  ///< what the findings of the program made call it
};

struct CamRun {
  WriteStatus status = WriteStatus::Refused;
  std::optional<CamResult> made;
  std::optional<EmitOutput> output;
  /// The drawing's findings, then making's, the writer's and the read-back's warnings and errors.
  Diagnostics diags{kAllDiagnostics};
  std::string readBack;  ///< "; read back: 14 moves, cut length 82.633 mm (made 82.633)", or why not
  std::string refusal;   ///< why it was not written, in a sentence (status ProgramErrors or NotWritten)
  std::optional<Pipeline> readBackPipeline;  ///< the program made, read back: its sources outlive the diagnostics
};

/// The program made from the drawing `p` read (a DXF or a curve), written and read back through the
/// same pipeline as kerf check: not written when it has errors or cuts another length than made.
CamRun makeAndCheck(const Pipeline& p, const CamRequest& r);

}  // namespace kerf::converter
