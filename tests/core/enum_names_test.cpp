#include "core/enum_names.h"

#include <gtest/gtest.h>

#include "support/error_capture.h"

namespace iblkit {
namespace {

enum class Colour { Red, Green, Blue };
constexpr EnumName<Colour> kColours[] = {
    {Colour::Red, "red"}, {Colour::Green, "green"}, {Colour::Blue, "blue"}};

TEST(EnumNames, ParsesEveryNameAndNamesEveryValue) {
  for (const EnumName<Colour>& entry : kColours) {
    EXPECT_EQ(parseEnumName(kColours, entry.name, "--colour", "colour"), entry.value);
    EXPECT_EQ(enumNameOf(kColours, entry.value), entry.name);
  }
  EXPECT_EQ(enumNameOf(kColours, Colour(7)), "?");
  EXPECT_EQ(enumNames(kColours), (std::vector<std::string>{"red", "green", "blue"}));
}

TEST(EnumNames, AnUnknownNameListsTheChoicesInTableOrder) {
  EXPECT_EQ(test::errorMessage([] { parseEnumName(kColours, "Red", "--colour", "colour"); }),
            "--colour: unknown colour 'Red' (expected one of red, green, blue)");
  EXPECT_EQ(test::errorMessage([] { parseEnumName(kColours, "", "scene.json", "colour"); }),
            "scene.json: unknown colour '' (expected one of red, green, blue)");
}

}  // namespace
}  // namespace iblkit
