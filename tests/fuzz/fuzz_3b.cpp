// Fuzz entry point for the 3B reader and its route through the pipeline, with what Kerf writes
// from it read back (libFuzzer ABI; issue 41).
#include "fuzz_readers.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const kerf::converter::Pipeline p = kerf::fuzz::readAs(data, size, kerf::converter::InputFormat::ThreeB, "fuzz.3b");
  kerf::fuzz::writeAndReadBack(p);
  return 0;
}
