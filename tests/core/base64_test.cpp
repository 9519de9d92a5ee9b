#include "core/base64.h"

#include <gtest/gtest.h>

#include "core/error.h"

namespace iblkit {
namespace {

TEST(Base64, MatchesTheRfc4648TestVectors) {  // RFC 4648 section 10
  EXPECT_EQ(base64({}), "");
  EXPECT_EQ(base64({'f'}), "Zg==");
  EXPECT_EQ(base64({'f', 'o'}), "Zm8=");
  EXPECT_EQ(base64({'f', 'o', 'o'}), "Zm9v");
  EXPECT_EQ(base64({'f', 'o', 'o', 'b'}), "Zm9vYg==");
  EXPECT_EQ(base64({'f', 'o', 'o', 'b', 'a'}), "Zm9vYmE=");
  EXPECT_EQ(base64({'f', 'o', 'o', 'b', 'a', 'r'}), "Zm9vYmFy");
  EXPECT_EQ(base64({0xfb, 0xff}), "+/8=");  // the last two letters of the alphabet
}

TEST(Base64, DecodeInvertsBase64AndRefusesOtherText) {
  for (const std::vector<std::uint8_t>& bytes :
       {std::vector<std::uint8_t>{}, {'f'}, {'f', 'o'}, {'f', 'o', 'o'}, {0, 255, 128, 7, 63}})
    EXPECT_EQ(base64Decode(base64(bytes)), bytes);
  EXPECT_THROW(base64Decode("Zm9"), Error);    // not a multiple of 4
  EXPECT_THROW(base64Decode("Zm*v"), Error);   // not in the alphabet
  EXPECT_THROW(base64Decode("Zg==Zm9v"), Error);  // padding before the end
}

}  // namespace
}  // namespace iblkit
