#include "score/heat_map.h"

#include <gtest/gtest.h>

#include <vector>

#include "core/color_map.h"
#include "core/image_io.h"
#include "support/error_capture.h"
#include "support/test_paths.h"

namespace iblkit {
namespace {

TEST(HeatMap, MapsValuesAndDrawsALegendBar) {
  const std::vector<float> values = {0.0f, 0.5f, 1.0f, 2.0f};
  const Image image = heatMapImage(values, 4, 1);
  ASSERT_EQ(image.width(), 4);
  ASSERT_EQ(image.height(), 1 + 2 * 4);  // the band is at least 4 rows
  EXPECT_EQ(glm::vec3(image.at(0, 0)), magma(0.0f));
  EXPECT_EQ(glm::vec3(image.at(1, 0)), magma(0.5f));
  EXPECT_EQ(glm::vec3(image.at(3, 0)), magma(1.0f));      // clamped
  EXPECT_EQ(glm::vec3(image.at(2, 2)), glm::vec3(0.0f));  // the gap
  EXPECT_EQ(glm::vec3(image.at(0, 8)), magma(0.0f));      // legend: 0 at the left
  EXPECT_EQ(glm::vec3(image.at(3, 8)), magma(1.0f));      // and 1 at the right
  EXPECT_EQ(test::errorMessage([] { heatMapImage(std::vector<float>(3), 2, 2); }),
            "heatMapImage: values do not match the size");
}

TEST(HeatMap, WritesAPng) {
  const std::filesystem::path file = test::scratchDir() / "heat.png";
  writeHeatMap(file, std::vector<float>(64 * 32, 0.25f), 64, 32);
  const Image read = readPng(file);
  EXPECT_EQ(read.width(), 64);
  EXPECT_EQ(read.height(), 32 + 2 * 4);
  EXPECT_NEAR(read.at(5, 5).r, magma(0.25f).r, 0.01f);
}

}  // namespace
}  // namespace iblkit
