// Fuzz entry point for the curve reader (expressions through muparser, point lists) and the
// biarc fit, with what Kerf writes from it read back (libFuzzer ABI; issue 41).
#include "fuzz_readers.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const kerf::converter::Pipeline p = kerf::fuzz::readAs(data, size, kerf::converter::InputFormat::Curve, "fuzz.curve");
  kerf::fuzz::writeAndReadBack(p);
  return 0;
}
