// env/sh9.json: the exact text written, the round trip, and the writer's and reader's errors.
#include "bakefile/sh9_json.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "support/error_capture.h"
#include "support/test_paths.h"

namespace iblkit {
namespace {

std::string readText(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(Sh9Json, JsonNamesTheNormalisationAndHoldsTheCoefficients) {
  SphericalHarmonics9 sh;
  for (int k = 0; k < kShCoefficients; ++k)
    sh.coefficients[static_cast<std::size_t>(k)] = glm::vec3(static_cast<float>(k), 0.5f, -0.25f);
  const std::filesystem::path file = test::scratchDir() / "sh9.json";
  writeSh9Json(file, sh, 6.5f);
  EXPECT_FALSE(std::filesystem::exists(file.string() + ".tmp"));
  EXPECT_EQ(
      readText(file),
      "{\n"
      "  \"basis\": \"real orthonormal SH, Sloan 2008 A1\",\n"
      "  \"order\": \"k = l(l+1)+m: Y00, Y1-1, Y10, Y11, Y2-2, Y2-1, Y20, Y21, Y22\",\n"
      "  \"coefficients\": \"L_k = integral L(w) Y_k(w) dw\",\n"
      "  \"irradiance\": \"E(n) = sum A_l L_k Y_k(n)\",\n"
      "  \"A_l\": [3.14159274, 2.09439516, 0.785398185],\n"
      "  \"window\": \"sinc^4, w_l = (sin(x)/x)^4 with x = pi l / cutoff, applied to L_k; cutoff 0: none\",\n"
      "  \"windowCutoff\": 6.5,\n"
      "  \"L\": [\n"
      "    [0, 0.5, -0.25],\n    [1, 0.5, -0.25],\n    [2, 0.5, -0.25],\n    [3, 0.5, -0.25],\n"
      "    [4, 0.5, -0.25],\n    [5, 0.5, -0.25],\n    [6, 0.5, -0.25],\n    [7, 0.5, -0.25],\n"
      "    [8, 0.5, -0.25]\n"
      "  ]\n}\n");
}

TEST(Sh9Json, JsonWriterRefusesNonFiniteCoefficientsAndUnwritablePaths) {
  SphericalHarmonics9 sh;
  sh.coefficients[3].g = NAN;
  EXPECT_EQ(test::errorMessage([&] { writeSh9Json("sh9.json", sh, 0.0f); }),
            "sh9.json: cannot write non-finite SH coefficients");
  const std::filesystem::path missing = test::scratchDir() / "no" / "sh9.json";
  EXPECT_EQ(test::errorMessage([&] { writeSh9Json(missing, SphericalHarmonics9{}, 0.0f); }),
            missing.string() + ": cannot create a temporary file beside it: No such file or directory");
}

TEST(Sh9Json, ReadsBackTheCoefficientsAndTheCutoff) {
  SphericalHarmonics9 sh;
  for (int k = 0; k < kShCoefficients; ++k)
    sh.coefficients[std::size_t(k)] = glm::vec3(0.1f * float(k), -1.0f / 3.0f, 1e-7f * float(k + 1));
  const std::filesystem::path file = test::scratchDir() / "sh9_round_trip.json";
  writeSh9Json(file, sh, 3.25f);
  float cutoff = 0.0f;
  const SphericalHarmonics9 read = readSh9Json(file, &cutoff);
  EXPECT_EQ(cutoff, 3.25f);
  for (int k = 0; k < kShCoefficients; ++k) EXPECT_EQ(read.coefficients[std::size_t(k)], sh.coefficients[std::size_t(k)]);
}

TEST(Sh9Json, MissingOrMalformedFilesAreErrorsNamingTheFile) {
  const std::filesystem::path missing = test::scratchDir() / "no_sh9.json";
  EXPECT_EQ(test::errorMessage([&] { readSh9Json(missing); }), missing.string() + ": cannot open: No such file or directory");
  const std::filesystem::path shortList = test::scratchDir() / "short_sh9.json";
  std::ofstream(shortList) << R"({"L": [[1, 2, 3]], "windowCutoff": 0})";
  EXPECT_EQ(test::errorMessage([&] { readSh9Json(shortList); }),
            shortList.string() + ": \"L\" must hold 9 RGB coefficients");
}

}  // namespace
}  // namespace iblkit
