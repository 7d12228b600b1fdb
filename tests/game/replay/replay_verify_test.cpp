// The replay verifier's reach (game/replay/replay_verify.cpp): it compares every traced tick, the
// first and the last included, and every checkpoint, so damage anywhere in a recording is found and
// blamed on the right line: a changed input at the tick the game first differs, a damaged trace
// token at its tick, a damaged checkpoint line at that checkpoint with the trace agreeing.
#include "replay/replay_verify.h"

#include <gtest/gtest.h>

#include "replay/replay_game.h"
#include "rules/bot.h"

namespace polar::game {
namespace {

constexpr int kTicks = 130;  // checkpoints after ticks 60, 120 and 130 (the end)

class ReplayVerify : public ::testing::Test {
  protected:
    // A recording made in memory as the recorder makes it: the demo pilot's inputs, a trace token
    // per tick, a checkpoint every 60 ticks and at the end (each on a line of its own).
    void SetUp() override {
        Game::Config config;
        config.reader = assets_.reader();
        config.seed = 9;
        Result<Game> game = Game::create(config);
        ASSERT_TRUE(game.ok()) << game.error().message();
        replay_.path = "memory.replay";
        replay_.header = headerFor(*game, replay_.path, {}, {});
        Bot bot(9);
        for (int t = 1; t <= kTicks; ++t) {
            Actions a = bot.decide(*game);
            game->tick(a);
            replay_.actions.push_back(a);
            replay_.trace.push_back(traceOf(game->hash()));
            if (t % 60 == 0 || t == kTicks) {
                replay_.checkpoints.push_back(checkpointOf(*game));
                replay_.checkpoints.back().line = 100 + t;
            }
        }
    }

    Verification verify(const Replay& replay) {
        Result<Verification> v = verifyReplay(replay, assets_);
        EXPECT_TRUE(v.ok()) << (v.ok() ? "" : v.error().message());
        return v.ok() ? *v : Verification{};
    }

    // The state hash after playing `replay`'s inputs, to check a tampered input changes the game.
    std::uint64_t finalHash(const Replay& replay) {
        Result<Game> game = Game::create(configFor(replay, assets_));
        EXPECT_TRUE(game.ok());
        for (Actions a : replay.actions) game->tick(a);
        return game->hash();
    }

    // The checkpoint a desync at `tick` is compared at.
    static std::uint64_t checkpointAfter(std::uint64_t tick) {
        return std::min<std::uint64_t>((tick + 59) / 60 * 60, kTicks);
    }

    AssetFs assets_{POLAR_ASSET_DIR};
    Replay replay_;
};

TEST_F(ReplayVerify, TheUntouchedRecordingPasses) {
    Verification v = verify(replay_);
    EXPECT_FALSE(v.desync);
    EXPECT_EQ(v.ticks, static_cast<std::uint64_t>(kTicks));
    EXPECT_EQ(v.checkpoints, 3u);
}

// The first and the last input, each changed: blamed on that tick, through the trace, never on a
// checkpoint line.
TEST_F(ReplayVerify, AChangedFirstOrLastInputIsFoundAtItsTick) {
    for (std::size_t index : {std::size_t{0}, std::size_t{kTicks - 1}}) {
        SCOPED_TRACE("input of tick " + std::to_string(index + 1));
        Replay tampered = replay_;
        tampered.actions[index] ^= kTurnLeft | kTurnRight | kThrust;
        ASSERT_NE(finalHash(tampered), finalHash(replay_)) << "the change reaches the game";
        Verification v = verify(tampered);
        ASSERT_TRUE(v.desync);
        EXPECT_TRUE(v.desync->traced);
        EXPECT_FALSE(v.desync->traceAgrees) << "the inputs changed, not the checkpoint line";
        EXPECT_EQ(v.desync->firstTick, index + 1);
        EXPECT_EQ(v.desync->checkpointTick, checkpointAfter(index + 1));
        EXPECT_NE(v.desync->expected, v.desync->actual);
    }
}

// Every trace token, damaged in turn (the game itself untouched), is found at its own tick.
TEST_F(ReplayVerify, EveryDamagedTraceTokenIsFoundAtItsTick) {
    for (std::size_t k = 0; k < replay_.trace.size(); ++k) {
        Replay tampered = replay_;
        tampered.trace[k] ^= 0x0800;
        Verification v = verify(tampered);
        ASSERT_TRUE(v.desync) << "trace token of tick " << k + 1 << " not compared";
        EXPECT_TRUE(v.desync->traced) << "tick " << k + 1;
        EXPECT_EQ(v.desync->firstTick, k + 1);
        EXPECT_EQ(v.desync->checkpointTick, checkpointAfter(k + 1)) << "tick " << k + 1;
    }
}

// Every checkpoint line, damaged in turn, is blamed on that line: the trace agrees up to it.
TEST_F(ReplayVerify, EveryDamagedCheckpointLineIsBlamedOnThatLine) {
    for (std::size_t k = 0; k < replay_.checkpoints.size(); ++k) {
        const Checkpoint& original = replay_.checkpoints[k];
        SCOPED_TRACE("checkpoint after tick " + std::to_string(original.tick));
        Replay tampered = replay_;
        tampered.checkpoints[k].hash ^= 1;
        Verification v = verify(tampered);
        ASSERT_TRUE(v.desync);
        EXPECT_TRUE(v.desync->traceAgrees);
        EXPECT_EQ(v.desync->checkpointTick, original.tick);
        EXPECT_EQ(v.desync->line, original.line);
        EXPECT_EQ(v.desync->expected, original.hash ^ 1);
        EXPECT_EQ(v.desync->actual, original.hash);
        EXPECT_EQ(v.checkpoints, k) << "the checkpoints before it matched";
    }
}

}  // namespace
}  // namespace polar::game
