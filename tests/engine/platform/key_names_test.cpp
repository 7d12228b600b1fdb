#include <gtest/gtest.h>

#include "polar/platform/events.h"

namespace polar::platform {
namespace {

TEST(KeyNames, EveryKeyHasANameThatMapsBack) {
    for (int k = 1; k < int(Key::Count); ++k) {
        const Key key = Key(k);
        const std::optional<Key> back = keyFromName(keyName(key));
        ASSERT_TRUE(back.has_value()) << keyName(key);
        EXPECT_EQ(*back, key) << keyName(key);
    }
}

TEST(KeyNames, NamesAreTheDocumentedOnesAndCaseDoesNotMatter) {
    EXPECT_STREQ(keyName(Key::A), "a");
    EXPECT_STREQ(keyName(Key::Num0), "0");
    EXPECT_STREQ(keyName(Key::PageDown), "page-down");
    EXPECT_STREQ(keyName(Key::LeftCtrl), "left-ctrl");
    EXPECT_STREQ(keyName(Key::Slash), "slash");
    EXPECT_STREQ(keyName(Key::Unknown), "unknown");
    EXPECT_EQ(keyFromName("Delete"), Key::Delete);
    EXPECT_EQ(keyFromName("F12"), Key::F12);
    EXPECT_EQ(keyFromName("unknown"), std::nullopt);  // not a key one can press
    EXPECT_EQ(keyFromName("ctrl"), std::nullopt);
    EXPECT_EQ(keyFromName(""), std::nullopt);
}

}  // namespace
}  // namespace polar::platform
