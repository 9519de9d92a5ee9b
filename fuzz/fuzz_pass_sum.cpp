// libFuzzer target: the reference pass sum loader (reference/pass_sum.h, docs/robustness.md).
#include <cstddef>
#include <cstdint>

#include "fuzz/fuzz_loaders.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  iblkit::fuzz::runLoader(iblkit::fuzz::Loader::PassSum, {data, size});
  return 0;
}
