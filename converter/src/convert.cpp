// Converting and making programs as the library does it (convert.h).
// Sections: 1. kerf convert  2. kerf cam
#include "kerf/converter/convert.h"

#include "kerf/converter/nc/number_format.h"
#include "kerf/converter/structure/passes.h"

#include <algorithm>
#include <cmath>

namespace kerf::converter {
namespace {

// ---- 1. kerf convert -----------------------------------------------------------------------------

/// An option the program cannot take (K0814, at the program): the conversion is refused.
void refuse(Conversion& c, const Pipeline& p, const std::string& message) {
  c.diags.error(Code::OptionDoesNotFit, p.source.get(), SourceSpan::wholeFile(), message);
  c.status = WriteStatus::Refused;
}

/// The profiles the request names, parsed into e (a point-file profile, the machine an ISO output
/// is written for; `target` holds one read from text). False, with the parse's errors, when one
/// does not parse or no built-in machine has the name.
bool resolveProfiles(const ConvertRequest& r, Conversion& c, EmitRequest& e, std::optional<MachineProfile>& target) {
  if (r.pointProfile) {
    c.profileSource = std::make_unique<SourceFile>(r.pointProfile->name, r.pointProfile->text);
    std::optional<PointProfile> parsed = parseProfile(*c.profileSource, c.diags);
    if (!parsed) return false;
    e.points.profile = *parsed;
  }
  if (r.targetFile) {
    c.targetSource = std::make_unique<SourceFile>(r.targetFile->name, r.targetFile->text);
    target = parseMachineProfile(*c.targetSource, c.diags);
    if (!target) return false;
    e.iso.target = &*target;
  } else if (r.target) {
    e.iso.target = findBuiltinMachine(*r.target);
    if (!e.iso.target) {
      c.diags.error(Code::MachineProfileError, nullptr, SourceSpan::wholeFile(),
                    "no built-in machine is named '" + *r.target + "' (kerf machines lists them)");
      return false;
    }
  }
  return true;
}

/// The plane a 2-axis format follows (`plane` stays empty for a writer of both); false, refused,
/// when the request's plane does not fit the writer or the program.
bool planeFor(const ConvertRequest& r, const Emitter& emitter, const Pipeline& p, std::optional<PlaneChoice>& plane,
              Conversion& c) {
  if (emitter.planes == PlaneNeed::Both) {
    if (!r.plane || (*r.plane == "guides" && emitter.name == "points4")) return true;
    refuse(c, p,
           "--plane chooses one plane for a 2-axis file; " + std::string(emitter.name) + " writes both" +
               (emitter.name == "points4" ? " (or both guides: --plane guides)" : ""));
    return false;
  }
  plane = parsePlane(r.plane.value_or("lower"));
  if (!plane) {
    refuse(c, p, "--plane takes lower, upper or z=HEIGHT (|HEIGHT| up to 1e6 mm), not '" + *r.plane + "'");
    return false;
  }
  if (p.toolpath.isTaper() && !r.plane) {
    refuse(c, p,
           "this is a 4-axis taper program: choose the plane the 2-axis file follows with --plane "
           "lower|upper|z=HEIGHT (one file per plane), or write both with --to points4 or --to iso");
    return false;
  }
  return true;
}

}  // namespace

Conversion convert(const Pipeline& p, const ConvertRequest& r) {
  Conversion c;
  for (const Diagnostic& d : p.diags.all()) c.diags.report(d);
  if (p.diags.hasErrors() && !r.force) {
    c.status = WriteStatus::ProgramErrors;
    return c;
  }
  const Emitter* emitter = findEmitter(r.format);
  if (!emitter) {
    refuse(c, p, "no output format is named '" + r.format + "'");
    return c;
  }
  EmitRequest e = r.emit;
  std::optional<MachineProfile> target;
  if (!resolveProfiles(r, c, e, target)) {
    c.status = WriteStatus::Refused;
    return c;
  }
  e.points.request.atGuides = r.plane == std::optional<std::string>("guides");
  // The whole program as its own blocks wrote it: polar output keeps what it does not convert.
  if (p.format == InputFormat::Iso && !r.pass && !p.toolpath.isTaper())
    e.polar.sourceBlocks = parseOptionsFor(p.machine);
  // A drawing shows the passes by layer, and with --drawing the elements cut out of tolerance: what
  // the pipeline found that only the DXF writer draws.
  if (emitter->name == "dxf") {
    e.dxf.movePass = movePasses(p.structure, p.toolpath.moves.size());
    if (p.comparison)
      for (const ElementDeviation& d : p.comparison->elements)
        if (d.deviation > p.comparison->tolerance) e.dxf.deviation.push_back(p.comparison->drawn[d.element]);
  }

  const Toolpath* path = &p.toolpath;
  std::optional<Toolpath> onePass;
  if (r.pass) {
    onePass = toolpathOfPass(p.toolpath, p.structure, *r.pass, p.checkOptions.tolerance);
    if (!onePass) {
      std::size_t most = 0;
      for (const Contour& k : p.structure.contours) most = std::max(most, k.passes.size());
      const std::string n = std::to_string(*r.pass);
      refuse(c, p,
             "--pass " + n + ": no contour of this program has a pass " + n + " (" +
                 (most == 1 ? std::string("each is cut in one pass") : "the most is " + std::to_string(most)) + ")");
      return c;
    }
    path = &*onePass;
  }
  std::optional<PlaneChoice> plane;
  if (!planeFor(r, *emitter, p, plane, c)) return c;
  std::optional<Toolpath> flat;
  if (plane) {
    flat = toolpathAtPlane(*path, *plane, r.tolerance, p.source.get(), c.diags);
    path = flat ? &*flat : nullptr;
  }
  if (path) c.output = emitter->write(*path, p.source.get(), e, c.diags);
  c.status = c.output ? WriteStatus::Written : WriteStatus::NotWritten;
  return c;
}

// ---- 2. kerf cam ---------------------------------------------------------------------------------

namespace {

std::string lengthText(double mm) { return formatFixed(mm, 3); }

/// The program made, read back from its text and checked as kerf check would: false (with the
/// refusal said) when it must not be written. Formats Kerf does not read are not read back.
bool readBack(const Pipeline& p, const CamRequest& r, CamRun& run) {
  const bool threeB = r.format == "3b";
  if (!threeB && r.format != "iso" && r.format != "polar") {
    run.readBack = "; this format is not read back";
    return true;
  }
  PipelineOptions po = r.readBack;
  ReadOptions fresh;  // the written format's reading; the machine the caller named stays
  fresh.machine = po.read.machine;
  fresh.machineFile = po.read.machineFile;
  po.read = std::move(fresh);
  po.read.format = threeB ? InputFormat::ThreeB : InputFormat::Iso;
  if (threeB) {  // 3B has no absolute start: the made program's, in whole micrometres as written
    const geometry::Vec2 s = run.made->toolpath.start;
    po.read.start = geometry::Vec2(std::round(s.x() * 1000.0) / 1000.0, std::round(s.y() * 1000.0) / 1000.0);
  } else {
    po.read.machine = p.machine.name;
  }
  run.readBackPipeline.emplace(runPipeline({r.outputName, run.output->text}, po));
  const Pipeline* back = &*run.readBackPipeline;
  double length = 0.0;
  for (const Move& m : back->toolpath.moves)
    if (m.isCut()) length += m.lower.length();
  const double allowed = 0.002 * static_cast<double>(back->toolpath.moves.size()) + 0.01;
  const double made = run.made->cutLength;
  run.readBack = "; read back: " + std::to_string(back->toolpath.moves.size()) + " moves, cut length " +
                 lengthText(length) + " mm (made " + lengthText(made) + ")";
  const bool lengthOff = std::abs(length - made) > allowed;
  // Refused, nothing is written: the findings name the program made, not a file that is not there.
  if (back->diags.hasErrors() || lengthOff) {
    run.readBackPipeline.emplace(runPipeline({"<not written: " + r.outputName + ">", run.output->text}, po));
    back = &*run.readBackPipeline;
  }
  for (const Diagnostic& d : back->diags.all())
    if (d.severity != Severity::Note) run.diags.report(d);
  if (back->diags.hasErrors())
    run.refusal = "not writing: the program made has errors when read back (shown above)";
  else if (lengthOff)
    run.refusal = "not writing: read back, the program cuts " + lengthText(length) + " mm, not the " +
                  lengthText(made) + " mm made (more than the output's rounding allows)";
  return run.refusal.empty();
}

}  // namespace

CamRun makeAndCheck(const Pipeline& p, const CamRequest& r) {
  CamRun run;
  for (const Diagnostic& d : p.diags.all()) run.diags.report(d);
  const Emitter* emitter = findEmitter(r.format);
  if (!p.drawing || !emitter) {
    run.refusal = !emitter ? "no output format is named '" + r.format + "'"
                           : "cam makes a program from a drawing (DXF) or a curve; this file reads as " +
                                 std::string(inputFormatName(p.format)) +
                                 " (kerf convert writes a program for another machine)";
    return run;  // Refused
  }
  if (p.diags.hasErrors()) {
    run.status = WriteStatus::ProgramErrors;
    run.refusal = "not making a program: the drawing has errors (kerf check shows the same)";
    return run;
  }
  run.status = WriteStatus::NotWritten;
  Diagnostics camDiags(kAllDiagnostics);
  run.made = makeProgram(*p.drawing, p.source.get(), r.cam, camDiags);
  run.diags.append(std::move(camDiags));
  if (!run.made || run.diags.hasErrors()) {
    run.refusal = "no program made: the drawing's contours cannot be cut as asked";
    return run;
  }
  // Through the writer table, in the machine's conventions.
  EmitRequest e = r.emit;
  e.iso.target = &p.machine;
  e.iso.offsetsApplied = true;
  e.iso.flattenSlivers = true;
  run.output = emitter->write(run.made->toolpath, p.source.get(), e, run.diags);
  if (!run.output || !readBack(p, r, run)) return run;
  run.status = WriteStatus::Written;
  return run;
}

}  // namespace kerf::converter
