// libFuzzer target: the env/lights.json loader (fuzz/fuzz_loaders.h, docs/robustness.md).
#include <cstddef>
#include <cstdint>

#include "fuzz/fuzz_loaders.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  iblkit::fuzz::runLoader(iblkit::fuzz::Loader::Lights, {data, size});
  return 0;
}
