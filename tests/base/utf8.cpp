#include "base/utf8.h"

#include <gtest/gtest.h>

#include <string>

using namespace boxlod;

TEST(Utf8, AcceptsWellFormedText) {
    EXPECT_TRUE(is_utf8(""));
    EXPECT_TRUE(is_utf8("Terraind\xc3\xa6k"));              // æ, 2 bytes
    EXPECT_TRUE(is_utf8("\xe2\x82\xac \xf0\x9f\x8f\xa0"));  // the euro sign, a house (4 bytes)
    EXPECT_TRUE(is_utf8("\xf4\x8f\xbf\xbf"));               // U+10FFFF, the last code point
}

TEST(Utf8, RefusesWhatRfc3629Excludes) {
    EXPECT_FALSE(is_utf8("Terraind\xe6k"));     // Latin-1
    EXPECT_FALSE(is_utf8("\x80"));              // a continuation byte alone
    EXPECT_FALSE(is_utf8("\xc3"));              // a sequence cut short
    EXPECT_FALSE(is_utf8("\xc0\xaf"));          // overlong '/'
    EXPECT_FALSE(is_utf8("\xe0\x80\xaf"));      // overlong, 3 bytes
    EXPECT_FALSE(is_utf8("\xed\xa0\x80"));      // a surrogate
    EXPECT_FALSE(is_utf8("\xf4\x90\x80\x80"));  // past U+10FFFF
    EXPECT_FALSE(is_utf8("\xf5\x80\x80\x80"));
}

TEST(Utf8, ReadsWhatIsNotUtf8AsLatin1) {
    EXPECT_EQ(utf8_or_latin1("Terraind\xe6k"), "Terraind\xc3\xa6k");
    EXPECT_EQ(utf8_or_latin1("caf\xc3\xa9"), "caf\xc3\xa9");  // already UTF-8: kept
    EXPECT_EQ(utf8_or_latin1("\xff"), "\xc3\xbf");
    EXPECT_TRUE(is_utf8(utf8_or_latin1("\xed\xa0\x80 \xc0")));
}
