// Diagnostics do not echo huge tokens whole.
#include <gtest/gtest.h>

#include <string>

#include "tierlift/ir/diagnostic.h"

using tierlift::ir::shorten_long_words;

TEST(ShortenLongWords, ShortMessagesAreUntouched) {
  const std::string m = "register index 'c99999' is out of range (c0..c255)";
  EXPECT_EQ(shorten_long_words(m), m);
  const std::string word200(200, 'x'); // exactly the limit: kept
  EXPECT_EQ(shorten_long_words("a " + word200 + " b"), "a " + word200 + " b");
}

TEST(ShortenLongWords, ALongWordKeepsItsHeadAndLength) {
  const std::string digits(50'000'000, '9');
  const std::string m = "unknown register 'c" + digits + "' here";
  // The word is 'c999…9' with both quotes: 50,000,003 bytes; the first 96 are kept.
  const std::string want = "unknown register 'c" + std::string(94, '9') + "… (50000003 bytes) here";
  EXPECT_EQ(shorten_long_words(m), want);
}

TEST(ShortenLongWords, CutsAtACharacterBoundary) {
  // 95 ASCII bytes then 'é' (2 bytes) straddling byte 96: the cut backs up before it.
  const std::string word = std::string(95, 'a') + "\xC3\xA9" + std::string(200, 'b');
  EXPECT_EQ(shorten_long_words(word), std::string(95, 'a') + "… (297 bytes)");
}

TEST(ShortenLongWords, TheSinkShortensWhatItStores) {
  tierlift::ir::DiagnosticSink sink;
  sink.error({}, "syntax", "bad '" + std::string(1000, 'z') + "'");
  ASSERT_EQ(sink.all().size(), 1u);
  EXPECT_LT(sink.all()[0].message.size(), 140u);
}
