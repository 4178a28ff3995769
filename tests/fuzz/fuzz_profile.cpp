// Fuzz entry point for the side files a command reads: a machine profile, an --offsets table and a
// point-file profile (libFuzzer ABI; issue 41). Their readers report, never crash, on any bytes.
#include "kerf/converter/formats/points/points.h"
#include "kerf/converter/interpret/machine.h"
#include "kerf/converter/interpret/offset_table.h"

#include <cstddef>
#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace kerf::converter;
  const SourceFile file("fuzz.profile", std::string(reinterpret_cast<const char*>(data), size));
  Diagnostics diags(20);
  (void)parseMachineProfile(file, diags);
  (void)readOffsetTable(file, diags);
  (void)parseProfile(file, diags);
  return 0;
}
