// The cutting-time estimate (docs/passes.md, "Cutting time").
#include "kerf/converter/structure/cutting_time.h"

#include "kerf/converter/nc/number_format.h"

#include <string>

namespace kerf::converter {
namespace {

/// mm/min as the report writes a speed: three decimals, trailing zeros dropped ("5", "6.667").
std::string speedText(double v) {
  std::string t = formatFixed(v, 3);
  while (t.back() == '0') t.pop_back();
  if (t.back() == '.') t.pop_back();
  return t;
}

/// Minutes of one pass: its moves at their own F where the model takes F, else at `speed`
/// (mm/min; nothing when it is unknown, 0).
std::optional<double> passMinutes(const Toolpath& toolpath, const Pass& pass, const SpeedModel& model, double speed) {
  double minutes = 0.0;
  for (std::size_t m = pass.first; m < pass.end; ++m) {
    const double length = toolpath.moves[m].lower.length();
    if (const double feed = model.speeds.feedIsSpeed ? toolpath.feedOf(m) : 0.0; feed > 0)
      minutes += length / feed;
    else if (speed > 0)
      minutes += length / speed;
    else
      return std::nullopt;
  }
  return minutes;
}

/// The model in one line: "rough 100 mm²/min over 20.000 mm (--thickness) = 5 mm/min, skims 10 mm/min,
/// rapids 1000 mm/min, threading 30 s: the generic profile's speeds".
std::string modelText(const SpeedModel& model, double roughSpeed) {
  if (model.speed) return "every cut at " + speedText(*model.speed) + " mm/min (--speed)";
  std::string rough = "rough " + speedText(model.speeds.roughRate) + " mm²/min";
  if (model.thickness)
    rough += " over " + formatFixed(*model.thickness, 3) + " mm = " + speedText(roughSpeed) + " mm/min";
  return (model.speeds.feedIsSpeed ? std::string("F where the program gives it, else ") : std::string()) + rough +
         ", skims " + speedText(model.speeds.skimSpeed) + " mm/min, rapids " + speedText(model.speeds.rapidSpeed) +
         " mm/min, threading " + speedText(model.speeds.threadSeconds) + " s" +
         (model.speeds.conditionSpeeds.empty() ? std::string() : ", and its conditions' speeds") + ": the " +
         model.profile + " profile's speeds";
}

}  // namespace

SpeedModel speedModel(const MachineProfile& machine, const Toolpath& toolpath, std::optional<double> speed) {
  SpeedModel m;
  m.speeds = machine.speeds;
  m.speed = speed;
  m.profile = machine.name;
  if (toolpath.heights.known) {
    m.thickness = toolpath.heights.planes.height();
    m.thicknessSource = toolpath.heights.source;
  }
  return m;
}

void estimateTime(const Toolpath& toolpath, const SpeedModel& model, Structure& structure) {
  TimeEstimate& t = structure.time;
  t = {};
  const double roughSpeed = model.speed       ? *model.speed
                            : model.thickness ? model.speeds.roughRate / *model.thickness
                                              : 0.0;
  const double skimSpeed = model.speed ? *model.speed : model.speeds.skimSpeed;
  bool roughUnknown = false;
  for (Contour& c : structure.contours) {
    for (std::size_t k = 0; k < c.passes.size(); ++k) {
      Pass& p = c.passes[k];
      const bool fullMaterial = k == 0 || p.cutOff;  // a skim cuts only what the pass before left
      double speed = fullMaterial ? roughSpeed : skimSpeed;
      if (const auto known = model.speeds.conditionSpeeds.find(p.condition);
          !model.speed && known != model.speeds.conditionSpeeds.end())
        speed = known->second;
      p.minutes = passMinutes(toolpath, p, model, speed);
      if (p.minutes) {
        t.cutting += *p.minutes;
        ++t.passesTimed;
      } else {
        roughUnknown = true;
      }
    }
  }
  for (const Move& m : toolpath.moves)
    if (!m.isCut()) t.rapids += m.lower.length() / model.speeds.rapidSpeed;
  t.threading = static_cast<double>(structure.contours.size()) * model.speeds.threadSeconds / 60.0;
  if (roughUnknown) t.missing = "the workpiece thickness is unknown (give --thickness, or --speed)";
  t.model = modelText(model, roughSpeed);
}

}  // namespace kerf::converter
