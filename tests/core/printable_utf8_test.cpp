#include "core/printable_utf8.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <random>

namespace papercraft {
namespace {

TEST(PrintableUtf8, WellFormedTextIsUnchanged) {
  for (const std::string text :
       {"", "plain ascii", "caf\xC3\xA9", "\xE2\x82\xAC 5", "\xF0\x9F\x93\x84 paper",
        "\xEF\xBF\xBF", "\xF4\x8F\xBF\xBF", "back\\xslash"}) {
    EXPECT_TRUE(is_valid_utf8(text)) << text;
    EXPECT_EQ(printable_utf8(text), text);
  }
}

TEST(PrintableUtf8, EachBadByteBecomesHex) {
  EXPECT_EQ(printable_utf8("caf\xE9.off"), "caf\\xE9.off");               // Latin-1
  EXPECT_EQ(printable_utf8("\xC3"), "\\xC3");                             // truncated
  EXPECT_EQ(printable_utf8("\xC0\xAF"), "\\xC0\\xAF");                    // overlong '/'
  EXPECT_EQ(printable_utf8("\xE0\x80\xAF"), "\\xE0\\x80\\xAF");           // overlong
  EXPECT_EQ(printable_utf8("\xED\xA0\x80"), "\\xED\\xA0\\x80");           // surrogate
  EXPECT_EQ(printable_utf8("\xF4\x90\x80\x80"), "\\xF4\\x90\\x80\\x80");  // > U+10FFFF
  EXPECT_EQ(printable_utf8("\xFF\xC3\xA9"), "\\xFF\xC3\xA9");             // good after bad kept
  EXPECT_EQ(printable_utf8(std::string("a\0b", 3)), "a\\x00b");           // control
  EXPECT_EQ(printable_utf8("\x1B[2Jgone"), "\\x1B[2Jgone");  // a terminal escape, disarmed
  EXPECT_EQ(printable_utf8("tab\tand\nnewline\x7F"), "tab\tand\nnewline\\x7F");
  EXPECT_FALSE(is_valid_utf8("caf\xE9"));
}

// The reason for the function: whatever the bytes, the result can be dumped as JSON, and
// applying it again changes nothing.
TEST(PrintableUtf8, RandomBytesAlwaysDumpAsJson) {
  std::mt19937 random(15);
  std::uniform_int_distribution<int> byte(0, 255);
  int invalid = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    std::string text(1 + trial % 40, '\0');
    for (char& c : text) c = static_cast<char>(byte(random));
    invalid += is_valid_utf8(text) ? 0 : 1;
    const std::string escaped = printable_utf8(text);
    EXPECT_TRUE(is_valid_utf8(escaped));
    EXPECT_NO_THROW((void)nlohmann::json(escaped).dump()) << escaped;
    EXPECT_EQ(printable_utf8(escaped), escaped);
  }
  EXPECT_GT(invalid, 1000) << "the test must feed invalid text to mean anything";
  EXPECT_THROW((void)nlohmann::json(std::string("caf\xE9")).dump(), nlohmann::json::type_error);
}

}  // namespace
}  // namespace papercraft
