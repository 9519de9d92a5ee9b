// The committed fuzz corpora (fuzz/corpus/<target>/) replayed through the fuzz targets' own
// driver (fuzz/fuzz_loaders.h) in the normal build, without libFuzzer: every past finding
// (finding_*) must be refused with an exception or loaded, never crash; every hand-made seed
// (seed_*, fuzz/make_seeds.py) must load, so the fuzzer starts from inputs that pass the checks.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "fuzz/fuzz_loaders.h"

namespace iblkit {
namespace {

namespace fs = std::filesystem;

std::vector<fs::path> corpusFiles(std::string_view target) {
  std::vector<fs::path> files;
  for (const fs::directory_entry& entry : fs::directory_iterator(fs::path(IBLKIT_FUZZ_CORPUS) / target))
    if (entry.is_regular_file()) files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  return files;
}

std::vector<std::uint8_t> bytesOf(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST(FuzzCorpus, EveryTargetHasSeedsThatLoad) {
  for (const EnumName<fuzz::Loader>& target : fuzz::kLoaderNames) {
    int seeds = 0;
    for (const fs::path& file : corpusFiles(target.name)) {
      if (file.filename().string().rfind("seed_", 0) != 0) continue;
      ++seeds;
      std::string refusal;
      EXPECT_TRUE(fuzz::runLoader(target.value, bytesOf(file), &refusal)) << file << ": " << refusal;
    }
    EXPECT_GT(seeds, 0) << target.name;
  }
}

TEST(FuzzCorpus, EveryFindingIsHandled) {
  for (const EnumName<fuzz::Loader>& target : fuzz::kLoaderNames)
    for (const fs::path& file : corpusFiles(target.name))
      if (file.filename().string().rfind("finding_", 0) == 0) fuzz::runLoader(target.value, bytesOf(file));
}

}  // namespace
}  // namespace iblkit
