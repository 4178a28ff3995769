// The cutting time: an estimate per pass and in total from a machine's speed model
// (docs/passes.md, "Cutting time" states the model and where its numbers come from).
#pragma once

#include "kerf/converter/interpret/machine.h"
#include "kerf/converter/structure/passes.h"
#include "kerf/converter/toolpath.h"

#include <optional>
#include <string>

namespace kerf::converter {

/// The speeds the estimate takes: a machine profile's, the thickness the toolpath's planes give,
/// and --speed when it is given.
struct SpeedModel {
  CuttingSpeeds speeds;             ///< the profile's
  std::optional<double> speed;      ///< --speed: mm/min for every cut, overriding the rest
  std::optional<double> thickness;  ///< mm, when the planes are known
  std::string thicknessSource;      ///< where the planes come from (PlaneHeights::source)
  std::string profile = "generic";  ///< the profile's name, for the report
};

/// The model of `machine` for `toolpath` (its planes give the thickness), with --speed when given.
SpeedModel speedModel(const MachineProfile& machine, const Toolpath& toolpath, std::optional<double> speed);

/// Sets each pass's minutes and structure.time. A pass under a machining condition the
/// profile gives a speed for is cut at that speed; else a contour's first pass and a cut-off cut
/// full material: roughRate / thickness mm/min (no time when the thickness is unknown); the other
/// passes are skims. With feedIsSpeed a move's own F wins; --speed wins over everything. Rapids
/// at rapidSpeed; one threading per contour. Lengths are the lower plane's.
void estimateTime(const Toolpath& toolpath, const SpeedModel& model, Structure& structure);

}  // namespace kerf::converter
