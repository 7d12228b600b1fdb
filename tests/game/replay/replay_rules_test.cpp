// A replay records the rules version and the game speed its game was played under, and is replayed
// under them: the replays saved before there were versions (no "rules" line) play by rules 1.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "replay/replay.h"
#include "rules/bot.h"
#include "scratch_folder.h"

namespace polar::game {
namespace {

namespace fs = std::filesystem;

class ReplayRules : public ::testing::Test {
  protected:
    // A replay of `ticks` ticks of the demo pilot in a game made with `rules` and `speed`.
    Replay recordInMemory(int rules, int speed, int ticks) {
        Game::Config config;
        config.reader = assets_.reader();
        config.seed = 5;
        config.rules = rules;
        config.speed = speed;
        std::vector<AssetStamp> stamps;
        Result<Game> game = createStampedGame(config, &assets_, "x.replay", stamps);
        EXPECT_TRUE(game.ok());
        Replay replay;
        replay.path = "x.replay";
        replay.header = headerFor(*game, replay.path, {}, stamps);
        Bot bot(5);
        for (int t = 0; t < ticks; ++t) {
            const Actions a = bot.decide(*game);
            game->tick(a);
            replay.actions.push_back(a);
            replay.trace.push_back(traceOf(game->hash()));
            if (game->tickCount() % kCheckpointInterval == 0)
                replay.checkpoints.push_back(checkpointOf(*game));
        }
        if (game->tickCount() % kCheckpointInterval != 0) replay.checkpoints.push_back(checkpointOf(*game));
        return replay;
    }

    AssetFs assets_{POLAR_ASSET_DIR};
};

TEST_F(ReplayRules, ANewGameRecordsItsRulesAndSpeedAndReplaysUnderThem) {
    for (int speed : {100, 75}) {
        const Replay replay = recordInMemory(kRulesVersion, speed, 600);
        const std::string text = formatReplay(replay);
        EXPECT_NE(text.find("\nrules " + std::to_string(kRulesVersion) + "\n"), std::string::npos) << text;
        EXPECT_EQ(text.find("\nspeed "), speed == 100 ? std::string::npos : text.find("\nspeed 75\n"))
            << text;
        Result<Replay> back = parseReplay("x.replay", text);
        ASSERT_TRUE(back.ok()) << back.error().message();
        EXPECT_EQ(back->header.rules, kRulesVersion);
        EXPECT_EQ(back->header.speed, speed);
        EXPECT_EQ(formatReplay(*back), text);
        Result<Verification> v = verifyReplay(*back, assets_);
        ASSERT_TRUE(v.ok()) << v.error().message();
        EXPECT_FALSE(v->desync) << "speed " << speed << ": " << describe(*v->desync, "x.replay");
        EXPECT_EQ(v->ticks, 600u);
    }
}

// The same inputs under the other rules or at another speed are another game: the replay's own
// line is what keeps it in step.
TEST_F(ReplayRules, TheRulesLineIsWhatKeepsAReplayInStep) {
    const Replay replay = recordInMemory(kRulesVersion, 100, 900);
    Replay asOld = replay;
    asOld.header.rules = 1;
    Result<Verification> v = verifyReplay(asOld, assets_);
    ASSERT_TRUE(v.ok());
    EXPECT_TRUE(v->desync) << "played by rules 1, a rules-2 game desyncs";
    Replay slower = replay;
    slower.header.speed = 90;
    v = verifyReplay(slower, assets_);
    ASSERT_TRUE(v.ok());
    EXPECT_TRUE(v->desync);
}

// Every golden replay but the foes' was saved before the rules had versions: each reads as rules 1
// at full speed. The foes' scenes (minefield, saucers) were recorded under rules 3 and say so.
TEST_F(ReplayRules, ReplaysWithoutARulesLinePlayByRulesOne) {
    int seen = 0;
    for (const auto& entry : fs::directory_iterator(POLAR_REPLAY_DIR)) {
        if (entry.path().extension() != ".replay") continue;
        Result<Replay> replay = readReplay(entry.path().string());
        ASSERT_TRUE(replay.ok()) << replay.error().message();
        const std::string stem = entry.path().stem().string();
        EXPECT_EQ(replay->header.rules, stem == "minefield" || stem == "saucers" ? 3 : 1) << entry.path();
        EXPECT_EQ(replay->header.speed, 100) << entry.path();
        ++seen;
    }
    EXPECT_GE(seen, 5);
}

TEST_F(ReplayRules, BadRulesAndSpeedLinesArePointedAt) {
    const std::string head = "polarcade-replay 1\nscene scenes/cave.json\n";
    struct Case {
        std::string line, message;
    } cases[] = {
        {"rules 1\n", "x.replay:3:7: bad rules version \"1\""},
        {"rules two\n", "x.replay:3:7: bad rules version \"two\""},
        {"rules " + std::to_string(kRulesVersion + 1) + "\n",
         "x.replay:3:7: rules " + std::to_string(kRulesVersion + 1) + " are newer than polarcade"},
        {"rules 2\nrules 2\n", "x.replay:4:1: a second \"rules\" line (the first is on line 3)"},
        {"speed 49\n", "x.replay:3:7: bad game speed \"49\""},
        {"speed 100\n", "x.replay:3:7: bad game speed \"100\""},
        {"speed 75 80\n", "x.replay:3:10: unexpected \"80\""},
    };
    for (const Case& c : cases) {
        Result<Replay> r = parseReplay("x.replay", head + c.line + "begin\n");
        ASSERT_FALSE(r.ok()) << c.line;
        EXPECT_EQ(r.error().message().rfind(c.message, 0), 0u) << r.error().message();
    }
}

}  // namespace
}  // namespace polar::game
