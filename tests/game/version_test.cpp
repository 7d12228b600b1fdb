// --version on every executable prints the project's version, the one replays record.
#include <gtest/gtest.h>

#include <filesystem>

#include "replay/replay_format.h"
#include "run_command.h"
#include "scratch_folder.h"

namespace {

namespace fs = std::filesystem;
using polar::testing::CommandOutcome;
using polar::testing::run;

TEST(Version, EveryExecutablePrintsTheProjectVersion) {
    const std::pair<const char*, const char*> executables[] = {
        {"polarcade", POLARCADE_EXE},
        {"polarcade-replay", POLARCADE_REPLAY_EXE},
        {"polarcade-bounds", POLARCADE_BOUNDS_EXE},
        {"polarcade-collide", POLARCADE_COLLIDE_EXE},
        {"polarcade-bench", POLARCADE_BENCH_EXE},
        {"polarcade-art", POLARCADE_ART_EXE},
        {"polarcade-server", POLARCADE_SERVER_EXE},
        {"polarcade-boards", POLARCADE_BOARDS_EXE},
    };
    for (const auto& [name, path] : executables) {
        CommandOutcome r = run(path, {"--version"});
        EXPECT_EQ(r.exitCode, 0) << name << ": " << r.err;
        EXPECT_EQ(r.out, std::string(name) + " " + POLARCADE_VERSION + "\n") << name;
        EXPECT_EQ(r.err, "") << name;
        CommandOutcome help = run(path, {"--help"});
        EXPECT_NE(help.out.find("--version"), std::string::npos) << name << " --help lists it";
    }
}

TEST(Version, ARecordedReplayCarriesTheProjectVersion) {
    EXPECT_STREQ(polar::game::gameVersion(), POLARCADE_VERSION);
    const fs::path folder = polar::testing::freshTestFolder("polar-version");
    CommandOutcome r = run(
        POLARCADE_EXE, {"--headless", "--ticks", "30", "--record", (folder / "v.replay").string()}, folder);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const std::string text = polar::testing::readFile(folder / "v.replay");
    EXPECT_NE(text.find(std::string("\ngame ") + POLARCADE_VERSION + "\n"), std::string::npos) << text;
    fs::remove_all(folder);
}

}  // namespace
