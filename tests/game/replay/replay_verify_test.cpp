// The replay verifier's reach (game/replay/replay_verify.cpp): it compares every traced tick, the
// first and the last included, and every value of every checkpoint, so damage anywhere in a
// recording is found and blamed on the right line and kind: a changed input is a desync at the tick
// the game first differs, a damaged trace token is a damaged trace at its tick (the game matches the
// checkpoint after it), a damaged checkpoint value is a damaged checkpoint (the game matches the
// trace, or the checkpoint's own hash).
#include "replay/replay_verify.h"

#include <gtest/gtest.h>

#include <functional>

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
        EXPECT_EQ(v.desync->kind, Desync::Kind::kGame)
            << "the inputs changed, not a trace or checkpoint line";
        EXPECT_EQ(v.desync->firstTick, index + 1);
        EXPECT_EQ(v.desync->checkpointTick, checkpointAfter(index + 1));
        EXPECT_NE(v.desync->expected, v.desync->actual);
    }
}

// Every trace token, damaged in turn (the game itself untouched), is found at its own tick and told
// apart from a desync: the game matches the checkpoint after it.
TEST_F(ReplayVerify, EveryDamagedTraceTokenIsFoundAtItsTickAndBlamedOnTheTrace) {
    for (std::size_t k = 0; k < replay_.trace.size(); ++k) {
        Replay tampered = replay_;
        tampered.trace[k] ^= 0x0800;
        Verification v = verify(tampered);
        ASSERT_TRUE(v.desync) << "trace token of tick " << k + 1 << " not compared";
        EXPECT_EQ(v.desync->kind, Desync::Kind::kTrace) << "tick " << k + 1;
        EXPECT_EQ(v.desync->firstTick, k + 1);
        EXPECT_EQ(v.desync->checkpointTick, checkpointAfter(k + 1)) << "tick " << k + 1;
        EXPECT_EQ(v.desync->traceExpected, replay_.trace[k] ^ 0x0800);
        EXPECT_EQ(v.desync->traceActual, replay_.trace[k]);
        EXPECT_EQ(v.desync->expected, v.desync->actual) << "the checkpoint matched";
    }
}

// A damaged token with no checkpoint after it (an interrupted recording): a damaged trace when a
// later token matches again, a desync when the game never matched again.
TEST_F(ReplayVerify, WithoutACheckpointAfterItLaterTokensDecide) {
    Replay cut = replay_;
    cut.checkpoints.pop_back();  // ticks 121-130 have no checkpoint after them
    cut.trace[124] ^= 1;
    Verification v = verify(cut);
    ASSERT_TRUE(v.desync);
    EXPECT_EQ(v.desync->kind, Desync::Kind::kTrace);
    EXPECT_EQ(v.desync->firstTick, 125u);
    EXPECT_EQ(v.desync->checkpointTick, 0u);
    EXPECT_NE(describe(*v.desync, "x.replay").find("every later token matches"), std::string::npos);

    Replay last = cut;
    last.trace[124] ^= 1;
    last.trace[kTicks - 1] ^= 1;  // the last tick: no later token to side with the game
    v = verify(last);
    ASSERT_TRUE(v.desync);
    EXPECT_EQ(v.desync->kind, Desync::Kind::kGame);
    EXPECT_EQ(v.desync->firstTick, static_cast<std::uint64_t>(kTicks));
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
        EXPECT_EQ(v.desync->kind, Desync::Kind::kCheckpoint);
        EXPECT_EQ(v.desync->checkpointTick, original.tick);
        EXPECT_EQ(v.desync->checkpointLine, original.line);
        EXPECT_EQ(v.desync->line, original.line);
        EXPECT_EQ(v.desync->expected, original.hash ^ 1);
        EXPECT_EQ(v.desync->actual, original.hash);
        EXPECT_EQ(v.checkpoints, k) << "the checkpoints before it matched";
    }
}

// Every value a checkpoint covers, changed under an unchanged state hash, is a damaged checkpoint
// pointed at by the column of that value: the hash covers them, so the game is not at fault.
TEST_F(ReplayVerify, AValueChangedUnderTheSameHashIsADamagedCheckpointAtItsColumn) {
    Checkpoint& middle = replay_.checkpoints[1];
    middle.line = 40;
    middle.columns = {7, 10, 31, 52, 61, 69};
    middle.objectsLine = 41;
    for (std::size_t i = 0; i < middle.objects.size(); ++i)
        middle.objectColumns.push_back(9 + 8 * static_cast<int>(i));
    ASSERT_GE(middle.objects.size(), 2u);
    struct Case {
        const char* name;
        std::function<void(Checkpoint&)> damage;
        int line, column;
    } cases[] = {
        {"rng", [](Checkpoint& c) { c.rng ^= 1; }, 40, 31},
        {"score", [](Checkpoint& c) { c.score += 10; }, 40, 52},
        {"lives", [](Checkpoint& c) { c.lives += 1; }, 40, 61},
        {"wave", [](Checkpoint& c) { c.wave += 1; }, 40, 69},
        {"first digest", [](Checkpoint& c) { c.objects.front().digest ^= 1; }, 41, 9},
        {"last digest", [](Checkpoint& c) { c.objects.back().digest ^= 1; }, 41,
         9 + 8 * static_cast<int>(middle.objects.size() - 1)},
        {"an id", [](Checkpoint& c) { c.objects.back().id += 1000; }, 41,
         9 + 8 * static_cast<int>(middle.objects.size() - 1)},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.name);
        Replay tampered = replay_;
        c.damage(tampered.checkpoints[1]);
        Verification v = verify(tampered);
        ASSERT_TRUE(v.desync) << "a value the checkpoint holds was not compared";
        EXPECT_EQ(v.desync->kind, Desync::Kind::kCheckpoint);
        EXPECT_EQ(v.desync->expected, v.desync->actual);
        EXPECT_EQ(v.desync->line, c.line);
        EXPECT_EQ(v.desync->column, c.column);
        EXPECT_EQ(v.checkpoints, 1u) << "the first checkpoint matched";
        EXPECT_FALSE(v.desync->differences.empty()) << "the report shows the value, expected and actual";
    }
}

}  // namespace
}  // namespace polar::game
