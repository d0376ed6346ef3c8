// page_size_from_name and page_size_name: the layout's `page` parameter and its read-back.
#include "core/page_size.h"

#include <gtest/gtest.h>

#include "core/errors.h"

namespace papercraft {
namespace {

TEST(PageSize, NamesAndWidthByHeight) {
  EXPECT_EQ(page_size_from_name("A4").width_mm, 210.0);
  EXPECT_EQ(page_size_from_name("a4").height_mm, 297.0);
  EXPECT_EQ(page_size_from_name("Letter").width_mm, 215.9);
  EXPECT_EQ(page_size_from_name("A3").height_mm, 420.0);
  const PageSize custom = page_size_from_name("300x450.5");
  EXPECT_EQ(custom.width_mm, 300.0);
  EXPECT_EQ(custom.height_mm, 450.5);
  EXPECT_THROW(page_size_from_name("B7"), InvalidInputException);
  EXPECT_THROW(page_size_from_name("0x100"), InvalidInputException);
  EXPECT_THROW(page_size_from_name("100x"), InvalidInputException);
}

TEST(PageSize, NameReadsBack) {
  EXPECT_EQ(page_size_name(page_size_from_name("letter")), "Letter");
  EXPECT_EQ(page_size_name(page_size_from_name("300x450.5")), "300x450.5");
  EXPECT_EQ(page_size_from_name(page_size_name({123.5, 200.0})).width_mm, 123.5);
}

}  // namespace
}  // namespace papercraft
