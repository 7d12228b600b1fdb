// Seeking a replay by keyframes lands on straight play: after any sequence of seeks, forward and
// back, the game's hash, the particles and the drawn frame at tick T are straight play's at T, and
// playing on from there verifies every later checkpoint (a desync after a seek is reported as
// today). `polarcade --replay FILE --seek TICK --headless --screenshot` gives straight play's PNG.
#include "app/theatre/replay_seek.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <string>

#include "files/assets.h"
#include "golden_replays.h"
#include "polar/render/canvas.h"
#include "replay/replay.h"
#include "run_command.h"
#include "scratch_folder.h"

namespace polar::game {
namespace {

namespace fs = std::filesystem;

using polar::testing::goldenReplays;

std::vector<std::uint32_t> frameOf(const Game& game, SpriteCache& sprites, const Particles& particles) {
    render::Canvas canvas(kScreenWidth, kScreenHeight);
    drawGame(canvas, game, sprites, Interpolation{}, particles, 1.0, DrawOptions{});
    std::vector<std::uint32_t> pixels;
    for (int y = 0; y < canvas.height(); ++y)
        pixels.insert(pixels.end(), canvas.row(y), canvas.row(y) + canvas.width());
    return pixels;
}

TEST(ReplaySeek, AnySequenceOfSeeksLandsOnStraightPlay) {
    AssetFs assets{POLAR_ASSET_DIR};
    SpriteCache sprites(assets);
    Rng pick(2027);
    for (const std::string& file : goldenReplays()) {
        Result<Replay> replay = readReplay(file);
        ASSERT_TRUE(replay.ok()) << replay.error().message();
        const double dt = 1.0 / replay->header.tuning.tickRate;
        const std::uint64_t total = replay->actions.size();
        // Straight play: the hash and particle count at every tick, frames at a few.
        std::vector<std::uint64_t> hashes;
        std::vector<std::size_t> particleCounts;
        std::map<std::uint64_t, std::vector<std::uint32_t>> frames;
        std::vector<std::uint64_t> drawn;
        for (int k = 0; k < 4; ++k) drawn.push_back(pick.below(static_cast<std::uint32_t>(total)) + 1);
        {
            Result<ReplayPlayer> player = ReplayPlayer::start(*replay, assets);
            ASSERT_TRUE(player.ok());
            Particles particles;
            hashes.push_back(player->game().hash());
            particleCounts.push_back(0);
            while (!player->done()) {
                ASSERT_FALSE(player->step());
                particles.spawnFor(player->game().events(), player->game().tickCount());
                particles.tick(dt);
                hashes.push_back(player->game().hash());
                particleCounts.push_back(particles.size());
                if (std::find(drawn.begin(), drawn.end(), player->game().tickCount()) != drawn.end())
                    frames[player->game().tickCount()] = frameOf(player->game(), sprites, particles);
            }
        }
        Result<ReplayPlayer> player = ReplayPlayer::start(*replay, assets);
        ASSERT_TRUE(player.ok());
        Particles particles;
        ReplaySeek seek(*player, particles, dt, 25);  // a small interval: many keyframes in a short replay
        std::vector<std::uint64_t> targets;
        for (int k = 0; k < 30; ++k) targets.push_back(pick.below(static_cast<std::uint32_t>(total + 1)));
        for (std::uint64_t t : drawn) targets.push_back(t);
        targets.push_back(total / 2);
        targets.push_back(total / 2 - 1);  // one back: a restore, not a step
        for (std::uint64_t t : targets) {
            ASSERT_FALSE(seek.seek(t)) << file << " seeking to " << t;
            ASSERT_EQ(player->game().tickCount(), t);
            ASSERT_EQ(player->game().hash(), hashes[t]) << file << " after seeking to " << t;
            ASSERT_EQ(particles.size(), particleCounts[t]) << file << " after seeking to " << t;
            if (frames.count(t)) {
                EXPECT_EQ(frameOf(player->game(), sprites, particles), frames[t]) << file << " at " << t;
            }
        }
        EXPECT_GT(seek.keyframes(), 1u);
        // From the last seek to the end, every later checkpoint is checked and matches.
        seek.seek(0);
        while (!player->done()) ASSERT_FALSE(seek.advance()) << file;
        EXPECT_EQ(player->checkpointsMatched(), replay->checkpoints.size()) << file;
    }
}

TEST(ReplaySeek, ADesyncAfterASeekIsReported) {
    AssetFs assets{POLAR_ASSET_DIR};
    Result<Replay> replay = readReplay(std::string(POLAR_REPLAY_DIR) + "/short.replay");
    ASSERT_TRUE(replay.ok());
    ASSERT_GE(replay->checkpoints.size(), 2u);
    // The last checkpoint recorded wrong: a seek past the one before it must still find it.
    Checkpoint& last = replay->checkpoints.back();
    last.hash ^= 1;
    Result<ReplayPlayer> player = ReplayPlayer::start(*replay, assets);
    ASSERT_TRUE(player.ok());
    Particles particles;
    ReplaySeek seek(*player, particles, 1.0 / 60, 20);
    ASSERT_FALSE(seek.seek(replay->checkpoints[replay->checkpoints.size() - 2].tick + 1));
    ASSERT_FALSE(seek.seek(5));  // back, then forward past it again
    std::optional<Desync> desync = seek.seek(replay->actions.size());
    ASSERT_TRUE(desync);
    EXPECT_EQ(desync->checkpointTick, last.tick);
    EXPECT_EQ(desync->line, last.line);
}

TEST(ReplaySeek, KeyframesStayInTheirBudget) {
    AssetFs assets{POLAR_ASSET_DIR};
    Result<Replay> replay = readReplay(std::string(POLAR_REPLAY_DIR) + "/crowded.replay");
    ASSERT_TRUE(replay.ok());
    Result<ReplayPlayer> player = ReplayPlayer::start(*replay, assets);
    ASSERT_TRUE(player.ok());
    Particles particles;
    const std::size_t budget = 64 * 1024;
    ReplaySeek seek(*player, particles, 1.0 / 60, 10, budget);
    seek.seek(replay->actions.size());
    EXPECT_LE(seek.heldBytes(), budget + budget / 2);  // at most one keyframe over before thinning
    EXPECT_GT(seek.interval(), 10u);                   // it had to thin
    seek.seek(replay->actions.size() / 3);
    Result<ReplayPlayer> straight = ReplayPlayer::start(*replay, assets);
    while (straight->game().tickCount() < replay->actions.size() / 3) straight->step();
    EXPECT_EQ(player->game().hash(), straight->game().hash());
}

TEST(ReplaySeek, PolarcadeSeekScreenshotIsStraightPlays) {
    fs::path folder = polar::testing::freshTestFolder("polar-seek");
    const std::string replay = std::string(POLAR_REPLAY_DIR) + "/short.replay";
    auto straight = polar::testing::run(POLARCADE_EXE,
                                        {"--headless", "--replay", replay, "--screenshot", "600:straight.png",
                                         "--screenshot", "450:straight-450.png"},
                                        folder);
    ASSERT_EQ(straight.exitCode, 0) << straight.err;
    auto sought = polar::testing::run(POLARCADE_EXE,
                                      {"--headless", "--replay", replay, "--seek", "450", "--screenshot",
                                       "600:seek.png", "--screenshot", "450:seek-450.png"},
                                      folder);
    ASSERT_EQ(sought.exitCode, 0) << sought.err;
    EXPECT_NE(sought.out.find("checkpoints match"), std::string::npos) << sought.out;
    std::string a = polar::testing::readFile(folder / "straight.png");
    ASSERT_FALSE(a.empty());
    EXPECT_EQ(a, polar::testing::readFile(folder / "seek.png"));
    EXPECT_EQ(polar::testing::readFile(folder / "straight-450.png"),
              polar::testing::readFile(folder / "seek-450.png"));
    EXPECT_EQ(a, polar::testing::readFile(std::string(POLAR_REPLAY_DIR) + "/short-600.png"));
    auto bad = polar::testing::run(POLARCADE_EXE, {"--headless", "--seek", "10"}, folder);
    EXPECT_EQ(bad.exitCode, 2) << "--seek without --replay";
    fs::remove_all(folder);
}

}  // namespace
}  // namespace polar::game
