#include "core/base64.h"

#include <gtest/gtest.h>

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

}  // namespace
}  // namespace iblkit
