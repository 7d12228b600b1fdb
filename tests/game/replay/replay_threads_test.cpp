// The golden replays verify, every checkpoint hash, whatever the threads their world steps on:
// parallelMin 1 sends the game's small worlds through every parallel phase of the step.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "replay/replay.h"

namespace polar::game {
namespace {

namespace fs = std::filesystem;

TEST(ReplayThreads, TheGoldenReplaysVerifyAtEveryWorkerCount) {
    AssetFs assets{POLAR_ASSET_DIR};
    std::vector<std::string> files;
    for (const fs::directory_entry& entry : fs::directory_iterator(POLAR_REPLAY_DIR))
        if (entry.path().extension() == ".replay") files.push_back(entry.path().string());
    std::sort(files.begin(), files.end());
    ASSERT_EQ(files.size(),
              8u);  // the cave's three, one each for field, ghosts and storm, minefield, saucers
    for (const std::string& file : files) {
        Result<Replay> replay = readReplay(file);
        ASSERT_TRUE(replay.ok()) << replay.error().message();
        for (std::uint32_t workers : {1u, 2u, 3u, 4u, 5u, 7u, 8u, 16u, 31u, 64u}) {
            StepThreads threads;
            threads.workers = workers;
            threads.parallelMin = 1;
            Result<Verification> v = verifyReplay(*replay, assets, threads);
            ASSERT_TRUE(v.ok()) << file << ": " << v.error().message();
            EXPECT_FALSE(v->desync.has_value())
                << file << " at " << workers << " workers, tick " << (v->desync ? v->desync->firstTick : 0);
            EXPECT_EQ(v->ticks, replay->actions.size()) << file << " at " << workers << " workers";
            EXPECT_GT(v->checkpoints, 0u) << file;
        }
    }
}

}  // namespace
}  // namespace polar::game
