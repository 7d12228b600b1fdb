// The web page's flags (engine/cli/plain_flags.h): read from its address without CLI11, refused in
// one line with the command line's words.
#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

#include "plain_flags.h"

namespace polar::cli {
namespace {

struct PageFlags {
    std::string scene = "cave";
    std::uint64_t seed = 0;
    int lives = 3;
    bool mute = false, seedGiven = false, livesGiven = false;
    PlainFlags flags;

    PageFlags() {
        flags.text("--scene", scene);
        flags.number("--seed", seed, {}, &seedGiven);
        flags.number("--lives", lives, {1, 99}, &livesGiven);
        flags.flag("--mute", mute);
    }
    std::string parse(const std::vector<std::string>& args) { return flags.parse(args).value_or("(read)"); }
};

TEST(PlainFlags, ReadsEachKindAndSaysWhichNumbersWereGiven) {
    PageFlags page;
    EXPECT_EQ(page.parse({"--lives", "1", "--mute", "--scene", "storm"}), "(read)");
    EXPECT_EQ(page.lives, 1);
    EXPECT_TRUE(page.livesGiven);
    EXPECT_FALSE(page.seedGiven) << "a number not named keeps its value and says so";
    EXPECT_EQ(page.seed, 0u);
    EXPECT_TRUE(page.mute);
    EXPECT_EQ(page.scene, "storm");
    PageFlags none;
    EXPECT_EQ(none.parse({}), "(read)");
    EXPECT_FALSE(none.mute);
}

TEST(PlainFlags, RefusesInOneLineWithTheRangeInWords) {
    EXPECT_EQ(PageFlags().parse({"--lives", "0"}), "--lives: expected a whole number from 1 to 99, got 0");
    EXPECT_EQ(PageFlags().parse({"--seed", "-5"}),
              "--seed: expected a whole number from 0 to 18446744073709551615, got -5");
    EXPECT_EQ(PageFlags().parse({"--seed"}), "--seed: expected a value");
    EXPECT_EQ(PageFlags().parse({"--seed", "--mute"}), "--seed: expected a value");
    EXPECT_EQ(PageFlags().parse({"--lifes", "3"}),
              "unknown flag --lifes; expected one of --scene, --seed, --lives, --mute");
}

}  // namespace
}  // namespace polar::cli
