// The replay file's rules (tests/README.md, "The replay file") at their edges: which header lines
// come once and which may repeat, the ranges of the header's numbers, checkpoints after ticks 1 and
// up and one per tick, object digests in rising ids, comments. (The end line and the trace tokens
// are held by replay_verify_test.cpp.)
#include <gtest/gtest.h>

#include "replay/replay.h"

namespace polar::game {
namespace {

const std::string kFormatRulesHead = "polarcade-replay 1\nscene scenes/cave.json\n";
const std::string kFormatRulesCheck = "0000000000000000 rng=0000000000000000 score=0 lives=3 wave=1";

// The message of `text`'s error, or "(read)" when it reads.
std::string formatRulesError(const std::string& text) {
    Result<Replay> replay = parseReplay("x.replay", text);
    return replay.ok() ? "(read)" : replay.error().message();
}

// Expects `text` refused with a message that starts with `start`.
void expectRefused(const std::string& text, const std::string& start) {
    std::string message = formatRulesError(text);
    EXPECT_EQ(message.rfind(start, 0), 0u) << "got: " << message << "\nfor:\n" << text;
}

TEST(ReplayFormatRules, HeaderLinesThatComeOnceAreRefusedTheSecondTime) {
    struct Case {
        const char* first;
        const char* second;
        const char* message;
    };
    for (const Case& c : std::initializer_list<Case>{
             {"game 0.1.0", "game 0.1.0", "x.replay:4:1: a second \"game\" line (the first is on line 3)"},
             {"seed 4", "seed 4", "x.replay:4:1: a second \"seed\" line (the first is on line 3)"},
             {"tick-rate 60", "tick-rate 60",
              "x.replay:4:1: a second \"tick-rate\" line (the first is on line 3)"},
             {"tuning thrust=260", "tuning turn-rate=4.2",
              "x.replay:4:1: a second \"tuning\" line (the first is on line 3)"},
             {"scene scenes/cave.json", "scene-file cave.json",
              "x.replay:4:1: a second scene (the first is on line 2)"}}) {
        // The scene line is line 2; the case's lines are 3 and 4 (for the scene case, 3 is a second).
        std::string text = kFormatRulesHead + c.first + "\n" + c.second + "\nbegin\n";
        if (std::string(c.first).rfind("scene", 0) == 0)
            expectRefused(kFormatRulesHead + c.second + "\nbegin\n",
                          "x.replay:3:1: a second scene (the first is on line 2)");
        else
            expectRefused(text, c.message);
    }
    // Mods, assets and screenshots are lists: each line adds one, in file order.
    Result<Replay> lists = parseReplay("x.replay", kFormatRulesHead +
                                                       "mod b\nmod a\n"
                                                       "asset 0000000000000001 sprites/ship.bounds.json\n"
                                                       "asset 0000000000000002 sprites/ship.bounds.json\n"
                                                       "screenshot 5:one.png\nscreenshot 1:two.png\nbegin\n");
    ASSERT_TRUE(lists.ok()) << lists.error().message();
    EXPECT_EQ(lists->header.mods, (std::vector<std::string>{"b", "a"}));
    ASSERT_EQ(lists->header.assets.size(), 2u);
    EXPECT_EQ(lists->header.assets[0].hash, 1u);
    EXPECT_EQ(lists->header.assets[1].line, 6);
    ASSERT_EQ(lists->header.screenshots.size(), 2u);
    EXPECT_EQ(lists->header.screenshots[0].tick, 5u);
    EXPECT_EQ(lists->header.screenshots[1].png, "two.png");
}

TEST(ReplayFormatRules, HeaderNumbersAtTheEndsOfTheirRanges) {
    for (const char* good : {"tick-rate 1", "tick-rate 1000", "screenshot 1:a.png", "tuning thrust=0",
                             "tuning thrust=1000000", "tuning start-lives=0 extra-life-every=1",
                             "tuning max-bullets=1000000", "seed 18446744073709551615"})
        EXPECT_EQ(formatRulesError(kFormatRulesHead + good + "\nbegin\n"), "(read)") << good;
    struct Case {
        const char* line;
        const char* message;
    };
    for (const Case& c : std::initializer_list<Case>{
             {"tick-rate 0.999",
              "x.replay:3:11: bad tick rate \"0.999\"; expected ticks per second from 1 to 1000"},
             {"tick-rate 1000.001", "x.replay:3:11: bad tick rate \"1000.001\""},
             {"screenshot 0:a.png",
              "x.replay:3:12: bad screenshot \"0:a.png\"; expected TICK:FILE.png with TICK ≥ 1"},
             {"screenshot 5:", "x.replay:3:12: bad screenshot \"5:\""},
             {"tuning thrust=-0.001",
              "x.replay:3:15: bad tuning value \"-0.001\" for thrust; expected a number from 0"},
             {"tuning thrust=1000000.5", "x.replay:3:15: bad tuning value \"1000000.5\" for thrust"},
             {"tuning max-bullets=-1",
              "x.replay:3:20: bad tuning value \"-1\" for max-bullets; expected a whole number from 0"},
             {"tuning max-bullets=1000001", "x.replay:3:20: bad tuning value \"1000001\" for max-bullets"},
             {"seed 18446744073709551616", "x.replay:3:6: bad seed"},
             {"seed -1", "x.replay:3:6: bad seed"}})
        expectRefused(kFormatRulesHead + c.line + "\nbegin\n", c.message);
}

TEST(ReplayFormatRules, CheckpointsFollowTicksOneAndUpOncePerTick) {
    const std::string head = kFormatRulesHead + "begin\n";
    EXPECT_EQ(formatRulesError(head + "in F\ncheck 1 " + kFormatRulesCheck + "\n"), "(read)");
    expectRefused(head + "check 0 " + kFormatRulesCheck + "\n",
                  "x.replay:4:7: a checkpoint before the first tick");
    expectRefused(
        head + "in F\ncheck 1 " + kFormatRulesCheck + "\nobjects 1:0001\ncheck 1 " + kFormatRulesCheck + "\n",
        "x.replay:7:7: a second checkpoint after tick 1; expected one per tick");
    expectRefused(head + "in F*2\ncheck 1 " + kFormatRulesCheck + "\n",
                  "x.replay:5:7: a checkpoint after tick 1 where the inputs so far cover 2 ticks");
    expectRefused(head + "in F\ncheck 1 " + kFormatRulesCheck + " score=5\n",
                  "x.replay:5:70: \"score\" twice");
    expectRefused(head + "in F\ncheck 1 " + kFormatRulesCheck + " rng=0000000000000000\n",
                  "x.replay:5:70: \"rng\" twice");
}

TEST(ReplayFormatRules, ObjectDigestsComeInRisingIdsEachOnce) {
    const std::string head = kFormatRulesHead + "begin\nin F\ncheck 1 " + kFormatRulesCheck + "\n";
    Result<Replay> good = parseReplay("x.replay", head + "objects 1:0001 2:0002 9:ffff\n");
    ASSERT_TRUE(good.ok()) << good.error().message();
    ASSERT_EQ(good->checkpoints.size(), 1u);
    ASSERT_EQ(good->checkpoints[0].objects.size(), 3u);
    EXPECT_EQ(good->checkpoints[0].objects[2].id, 9u);
    EXPECT_EQ(good->checkpoints[0].objects[2].digest, 0xffffu);
    expectRefused(head + "objects 1:0001 1:0002\n",
                  "x.replay:6:16: object 1 is out of order; expected objects in creation order (rising ids)");
    expectRefused(head + "objects 2:0001 1:0002\n", "x.replay:6:16: object 1 is out of order");
    expectRefused(head + "objects 1:0001\nobjects 2:0002\n",
                  "x.replay:7:1: an objects line that does not follow a check line");
}

TEST(ReplayFormatRules, CommentsAndBlankLinesChangeNothing) {
    const std::string plain =
        kFormatRulesHead + "seed 3\nbegin\nin F*2 .\ncheck 3 " + kFormatRulesCheck + "\n";
    const std::string commented =
        "polarcade-replay 1\n# one\n\nscene scenes/cave.json\n  # two\nseed 3\n"
        "begin\n# in the body\nin F*2 .\n\ncheck 3 " +
        kFormatRulesCheck + "\n# last\n";
    Result<Replay> a = parseReplay("x.replay", plain);
    Result<Replay> b = parseReplay("x.replay", commented);
    ASSERT_TRUE(a.ok()) << a.error().message();
    ASSERT_TRUE(b.ok()) << b.error().message();
    EXPECT_EQ(b->actions, a->actions);
    EXPECT_EQ(b->actions, (std::vector<Actions>{kFire, kFire, 0}));
    EXPECT_EQ(b->header.seed, 3u);
    ASSERT_EQ(b->checkpoints.size(), 1u);
    EXPECT_EQ(b->checkpoints[0].line, 11);
    EXPECT_EQ(b->header.comments, (std::vector<std::string>{"# one", "  # two"})) << "the header's, in order";
    expectRefused(kFormatRulesHead + "begin x\n", "x.replay:3:7: unexpected \"x\"; expected \"begin\" alone");
}

}  // namespace
}  // namespace polar::game
