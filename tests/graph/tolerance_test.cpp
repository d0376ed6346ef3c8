#include "graph/tolerance.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace papercraft {
namespace {

TEST(Tolerance, RelativeAndAbsolute) {
  const ToleranceSpec relative = parse_tolerance("2%");
  EXPECT_TRUE(relative.relative);
  EXPECT_DOUBLE_EQ(relative.value, 0.02);
  EXPECT_DOUBLE_EQ(relative.absolute(10.0), 0.2);
  const ToleranceSpec absolute = parse_tolerance("0.004 ");
  EXPECT_FALSE(absolute.relative);
  EXPECT_DOUBLE_EQ(absolute.absolute(10.0), 0.004);
  for (const char* bad : {"", "%", "two", "2%%", "-1%", "0", "nan", "inf", "2 mm"}) {
    EXPECT_THROW(parse_tolerance(bad), std::invalid_argument) << bad;
  }
}

TEST(Tolerance, PaperLengthsWithUnits) {
  EXPECT_DOUBLE_EQ(parse_length_mm("200"), 200.0);
  EXPECT_DOUBLE_EQ(parse_length_mm("200mm"), 200.0);
  EXPECT_DOUBLE_EQ(parse_length_mm("20 cm"), 200.0);
  EXPECT_DOUBLE_EQ(parse_length_mm("0.2m"), 200.0);
  EXPECT_DOUBLE_EQ(parse_length_mm("8in"), 203.2);
  EXPECT_DOUBLE_EQ(parse_length_mm("8IN"), 203.2);
  for (const char* bad : {"", "mm", "200 furlongs", "200mmm", "-5cm", "0", "nan", "inf"}) {
    EXPECT_THROW(parse_length_mm(bad), std::invalid_argument) << bad;
  }
}

}  // namespace
}  // namespace papercraft
