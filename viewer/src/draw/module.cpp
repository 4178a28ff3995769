// The drawing module's one exported symbol: the table of the commands that draw, for the loader in
// cli/draw_module.cpp. Everything else in the module is hidden (-fvisibility=hidden and
// --exclude-libs), so its copies of the converter and geometry never meet the program's.
#include "draw.h"
#include "draw_module.h"

namespace {

const kerf::cli::DrawCommands kCommands{
    kerf::cli::kDrawAbi,        kerf::cli::kDrawVersion,    &kerf::cli::drawRender,        &kerf::cli::drawView,
    &kerf::cli::drawExportMesh, &kerf::cli::drawExportPage, &kerf::cli::drawReportPictures};

}  // namespace

extern "C" __attribute__((visibility("default"))) const kerf::cli::DrawCommands* kerf_draw_commands() {
  return &kCommands;
}
