// Fuzz entry point for the DXF reader (ASCII and binary), its chaining and the drawing's route
// through the pipeline, with what Kerf writes from it read back (libFuzzer ABI; issue 41).
#include "fuzz_readers.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const kerf::converter::Pipeline p = kerf::fuzz::readAs(data, size, kerf::converter::InputFormat::Dxf, "fuzz.dxf");
  kerf::fuzz::writeAndReadBack(p);
  return 0;
}
