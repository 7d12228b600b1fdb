// Every numeric flag of every executable, run as a user runs it: what the flag cannot hold (a
// negative for an unsigned value, an overflow, a non-number, a value outside its range) is refused
// with one line that states the range in words, exit code 2, before anything runs or is written.
// The rows are the table in tests/README.md ("Flags").
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "run_command.h"
#include "scratch_folder.h"

namespace polar::game {
namespace {

namespace fs = std::filesystem;
using polar::testing::CommandOutcome;

struct Row {
    const char* exe;
    std::vector<std::string> args;
    int exitCode;
    std::string said;  // a fragment of the message (stderr)
};

class FlagTable : public ::testing::Test {
  protected:
    void SetUp() override {
        folder_ = polar::testing::freshTestFolder("polar-flag-table");
        fs::create_directories(folder_ / "a-folder");
    }
    void TearDown() override { fs::remove_all(folder_); }

    // What the scratch folder holds besides a-folder (empty).
    std::vector<std::string> written() const {
        std::vector<std::string> found;
        for (const auto& entry : fs::recursive_directory_iterator(folder_))
            if (entry.path() != folder_ / "a-folder") found.push_back(entry.path().string());
        return found;
    }

    // Runs each row in the scratch folder; a refusal is one line on stderr, nothing on stdout and
    // nothing written.
    void check(const std::vector<Row>& rows) {
        for (const Row& row : rows) {
            const CommandOutcome r = polar::testing::run(row.exe, row.args, folder_);
            std::string what = fs::path(row.exe).filename().string();
            for (const std::string& arg : row.args) what += " " + arg;
            EXPECT_EQ(r.exitCode, row.exitCode) << what << "\n" << r.err;
            EXPECT_NE(r.err.find(row.said), std::string::npos) << what << "\nsaid: " << r.err;
            if (row.exitCode != 2) continue;
            EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << what << "\n" << r.err;
            EXPECT_EQ(r.out, "") << what << ": refused before it ran";
            EXPECT_EQ(written(), std::vector<std::string>()) << what << " wrote something";
        }
    }

    fs::path folder_;
};

constexpr const char* kU64 = "a whole number from 0 to 18446744073709551615, got ";
constexpr const char* kI64 = "a whole number from 0 to 9223372036854775807, got ";

std::string expected(const std::string& flag, const std::string& words) {
    return flag + ": expected " + words;
}

std::vector<Row> polarcadeRows() {
    const char* game = POLARCADE_EXE;
    const std::string replay = std::string(POLAR_REPLAY_DIR) + "/short.replay";  // 600 ticks
    return {
        {game, {"--headless", "--ticks", "-1"}, 2, expected("--ticks", kI64) + "-1"},
        {game,
         {"--headless", "--ticks", "9223372036854775808"},
         2,
         expected("--ticks", kI64) + "9223372036854775808"},
        {game, {"--headless", "--ticks", "ten"}, 2, expected("--ticks", kI64) + "ten"},
        {game, {"--headless", "--seed", "-5"}, 2, expected("--seed", kU64) + "-5"},
        {game,
         {"--headless", "--seed", "99999999999999999999999"},
         2,
         expected("--seed", kU64) + "99999999999999999999999"},
        {game, {"--headless", "--seed", "0x10"}, 2, expected("--seed", kU64) + "0x10"},
        {game, {"--headless", "--lives", "0"}, 2, "--lives: expected a whole number from 1 to 99, got 0"},
        {game, {"--headless", "--lives", "100"}, 2, "--lives: expected a whole number from 1 to 99, got 100"},
        {game, {"--headless", "--lives", "3.5"}, 2, "--lives: expected a whole number from 1 to 99, got 3.5"},
        {game,
         {"--headless", "--threads", "0"},
         2,
         "--threads: expected a whole number from 1 to 256, got 0"},
        {game,
         {"--headless", "--threads", "257"},
         2,
         "--threads: expected a whole number from 1 to 256, got 257"},
        {game,
         {"--headless", "--threads", "-1"},
         2,
         "--threads: expected a whole number from 1 to 256, got -1"},
        {game, {"--headless", "--replay", replay, "--seek", "-1"}, 2, expected("--seek", kI64) + "-1"},
        {game,
         {"--headless", "--screenshot", "-5:x.png"},
         2,
         "--screenshot -5:x.png: expected TICK:FILE.png with TICK a whole number from 0 to "
         "18446744073709551615, "
         "got -5"},
        {game,
         {"--headless", "--screenshot", "18446744073709551616:x.png"},
         2,
         "with TICK a whole number from 0 to 18446744073709551615, got 18446744073709551616"},
        {game, {"--headless", "--screenshot", "soon:x.png"}, 2, "got soon"},
        {game, {"--headless", "--screenshot", "x.png"}, 2, "--screenshot x.png: expected TICK:FILE.png"},
        // A tick the run never plays: past --ticks, past the default 600, before the first tick,
        // past a replay's end or before its --seek.
        {game,
         {"--headless", "--screenshot", "50:x.png", "--ticks", "10"},
         2,
         "--screenshot 50:x.png: tick 50 is never played (--ticks 10); expected a tick from 1 to 10"},
        {game, {"--headless", "--screenshot", "11:x.png", "--ticks", "10"}, 2, "tick 11 is never played"},
        {game,
         {"--headless", "--screenshot", "601:x.png"},
         2,
         "tick 601 is never played (the run is 600 ticks by default); expected a tick from 1 to 600"},
        {game, {"--headless", "--screenshot", "0:x.png", "--ticks", "10"}, 2, "tick 0 is never played"},
        {game,
         {"--headless", "--replay", replay, "--screenshot", "601:x.png"},
         2,
         "tick 601 is never played (the replay has 600 ticks); expected a tick from 1 to 600"},
        {game,
         {"--headless", "--replay", replay, "--ticks", "30", "--screenshot", "31:x.png"},
         2,
         "tick 31 is never played (--ticks 30); expected a tick from 1 to 30"},
        {game,
         {"--headless", "--replay", replay, "--seek", "100", "--screenshot", "99:x.png"},
         2,
         "tick 99 is never played (--seek 100; the replay has 600 ticks); expected a tick from 100 to 600"},
        // A --record path that cannot be written: refused before the game starts, no .part left.
        {game,
         {"--headless", "--record", "a-folder"},
         2,
         "--record: a-folder: it is a folder; expected a file in a writable folder"},
        {game,
         {"--headless", "--record", "/proc/nope/x"},
         2,
         "--record: /proc/nope/x: the folder /proc/nope does not exist; expected a file in a writable "
         "folder"},
        {game, {"--headless", "--record", "missing/x.replay"}, 2, "the folder missing does not exist"},
        {game, {"--headless", "--record", "a-folder/"}, 2, "a-folder/: it names a folder, not a file"},
        {game, {"--record", ""}, 2, "--record: expected a file in a writable folder, got nothing"},
        // A picture that could not be saved is refused before the run, as --record is.
        {game,
         {"--headless", "--ticks", "10", "--screenshot", "5:a-folder"},
         2,
         "--screenshot 5:a-folder: a-folder: it is a folder; expected a file in a writable folder"},
        {game,
         {"--headless", "--ticks", "10", "--screenshot", "5:/proc/nope/x.png"},
         2,
         "--screenshot 5:/proc/nope/x.png: /proc/nope/x.png: the folder /proc/nope does not exist"},
    };
}

TEST_F(FlagTable, Polarcade) {
    check(polarcadeRows());
}

// The recording is written to FILE.part until the game ends: a folder of that name would make it
// fail as the game starts, so it is refused before, and the folder is left as it was.
TEST_F(FlagTable, PolarcadeRefusesARecordWhosePartFileIsAFolder) {
    fs::create_directories(folder_ / "a-folder" / "x.part");
    const CommandOutcome r = polar::testing::run(
        POLARCADE_EXE, {"--headless", "--ticks", "10", "--record", "a-folder/x"}, folder_);
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_EQ(
        r.err,
        "polarcade: --record: a-folder/x: a-folder/x.part, where the recording is written until the game "
        "ends, is a folder; expected a file in a writable folder; see polarcade --help\n");
    EXPECT_EQ(r.out, "");
    EXPECT_TRUE(fs::is_empty(folder_ / "a-folder" / "x.part"));
    EXPECT_FALSE(fs::exists(folder_ / "a-folder" / "x"));
}

// The edges of the ranges are accepted: the last tick a run plays is saved.
TEST_F(FlagTable, PolarcadeTakesTheEdgesOfItsRanges) {
    const CommandOutcome r = polar::testing::run(
        POLARCADE_EXE,
        {"--headless", "--ticks", "10", "--lives", "99", "--threads", "256", "--seed", "18446744073709551615",
         "--screenshot", "10:last.png", "--screenshot", "1:first.png", "--record", "a-folder/game.replay"},
        folder_);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_TRUE(fs::exists(folder_ / "last.png"));
    EXPECT_TRUE(fs::exists(folder_ / "first.png"));
    EXPECT_TRUE(fs::exists(folder_ / "a-folder" / "game.replay"));
    EXPECT_FALSE(fs::exists(folder_ / "a-folder" / "game.replay.part"));
    EXPECT_NE(
        polar::testing::readFile(folder_ / "a-folder" / "game.replay").find("seed 18446744073709551615"),
        std::string::npos);
}

std::vector<Row> polarcadeReplayRows() {
    const char* replay = POLARCADE_REPLAY_EXE;
    const std::string dir = POLAR_REPLAY_DIR;
    return {
        {replay, {"-j", "0", dir}, 2, "--jobs: expected a whole number from 1 to 256, got 0"},
        {replay, {"--jobs", "257", dir}, 2, "--jobs: expected a whole number from 1 to 256, got 257"},
        {replay, {"-j", "-1", dir}, 2, "--jobs: expected a whole number from 1 to 256, got -1"},
        {replay, {"-j", "two", dir}, 2, "--jobs: expected a whole number from 1 to 256, got two"},
        {replay,
         {"--step-threads", "0", dir},
         2,
         "--step-threads: expected a whole number from 1 to 64, got 0"},
        {replay,
         {"--step-threads", "65", dir},
         2,
         "--step-threads: expected a whole number from 1 to 64, got 65"},
        {replay,
         {"--shard", "0/3", dir},
         2,
         "--shard 0/3: K is 0, outside 1..3; expected K/N with 1 <= K <= N"},
        {replay, {"--shard", "99999999999999999999/1", dir}, 2, "not two whole numbers K/N"},
        {replay, {"--shard", "-1/2", dir}, 2, "not two whole numbers K/N"},
        {replay, {"--junit", "a-folder", dir}, 2, "--junit a-folder: it is a folder"},
    };
}

TEST_F(FlagTable, PolarcadeReplay) {
    check(polarcadeReplayRows());
}

std::vector<Row> polarcadeBenchRows() {
    const char* bench = POLARCADE_BENCH_EXE;
    auto range = [](const std::string& flag, long long low, long long high, const std::string& got) {
        return flag + ": expected a whole number from " + std::to_string(low) + " to " +
               std::to_string(high) + ", got " + got;
    };
    return {
        {bench, {"accuracy", "--placements", "0"}, 2, range("--placements", 1, 10000000, "0")},
        {bench, {"accuracy", "--placements", "10000001"}, 2, range("--placements", 1, 10000000, "10000001")},
        {bench, {"accuracy", "--seed", "-1"}, 2, expected("--seed", kU64) + "-1"},
        {bench, {"cores", "--threads", "1"}, 2, range("--threads", 2, 1024, "1")},
        {bench, {"cores", "--threads", "1025"}, 2, range("--threads", 2, 1024, "1025")},
        {bench, {"cores", "--runs", "0"}, 2, range("--runs", 1, 1000, "0")},
        {bench, {"difficulty", "--seeds", "0"}, 2, range("--seeds", 1, 100000, "0")},
        {bench, {"difficulty", "--first-seed", "-1"}, 2, expected("--first-seed", kU64) + "-1"},
        {bench,
         {"difficulty", "--max-minutes", "0.01"},
         2,
         "--max-minutes: expected a number from 0.05 to 1000, got 0.01"},
        {bench,
         {"difficulty", "--max-minutes", "inf"},
         2,
         "--max-minutes: expected a number from 0.05 to 1000, got inf"},
        {bench, {"difficulty", "--threads", "257"}, 2, range("--threads", 1, 256, "257")},
        {bench, {"present", "--warmup", "0.4"}, 2, "--warmup: expected a number from 0.5 to 60, got 0.4"},
        {bench, {"present", "--seconds", "601"}, 2, "--seconds: expected a number from 1 to 600, got 601"},
        {bench, {"present", "--seconds", "nan"}, 2, "--seconds: expected a number from 1 to 600, got nan"},
        {bench, {"looks", "--ticks", "119"}, 2, range("--ticks", 120, 1000000, "119")},
        {bench, {"looks", "--seed", "-1"}, 2, expected("--seed", kU64) + "-1"},
        {bench, {"render", "--sprites", "0"}, 2, range("--sprites", 1, 1000000, "0")},
        {bench, {"render", "--sprites", "100,0"}, 2, range("--sprites", 1, 1000000, "0")},
        {bench, {"render", "--threads", "1,257"}, 2, range("--threads", 1, 256, "257")},
        {bench, {"render", "--frames", "0"}, 2, range("--frames", 1, 100000, "0")},
        {bench, {"replay", "--runs", "0"}, 2, range("--runs", 1, 1000, "0")},
        {bench, {"replay", "--ticks", "59"}, 2, range("--ticks", 60, 1000000, "59")},
        {bench, {"replay", "--seed", "-1"}, 2, expected("--seed", kU64) + "-1"},
        {bench, {"scale", "--sizes", "1"}, 2, range("--sizes", 2, 10000000, "1")},
        {bench, {"scale", "--sizes", "1000,-5"}, 2, range("--sizes", 2, 10000000, "-5")},
        {bench, {"scale", "--sizes", "10000001"}, 2, range("--sizes", 2, 10000000, "10000001")},
        {bench, {"scale", "--threads", "0"}, 2, range("--threads", 1, 256, "0")},
        {bench, {"scale", "--all-pairs-max", "-1"}, 2, range("--all-pairs-max", 0, 10000000, "-1")},
        {bench,
         {"scale", "--all-pairs-max", "10000001"},
         2,
         range("--all-pairs-max", 0, 10000000, "10000001")},
        {bench, {"scale", "--steps", "-1"}, 2, range("--steps", 0, 100000, "-1")},
        {bench, {"scale", "--steps", "100001"}, 2, range("--steps", 0, 100000, "100001")},
        {bench, {"seek", "--seeks", "0"}, 2, range("--seeks", 1, 100000, "0")},
        {bench, {"seek", "--ticks", "1000001"}, 2, range("--ticks", 60, 1000000, "1000001")},
        {bench, {"seek", "--interval", "0"}, 2, range("--interval", 1, 100000, "0")},
        {bench, {"seek", "--seed", "x"}, 2, expected("--seed", kU64) + "x"},
        {bench, {"snapshot", "--calls", "19"}, 2, range("--calls", 20, 1000000, "19")},
        {bench, {"snapshot", "--ticks", "0"}, 2, range("--ticks", 1, 1000000, "0")},
        {bench, {"snapshot", "--rocks", "1000001"}, 2, range("--rocks", 1, 1000000, "1000001")},
        {bench, {"snapshot", "--seed", "-1"}, 2, expected("--seed", kU64) + "-1"},
        {bench, {"soak", "--ticks", "999"}, 2, range("--ticks", 1000, 100000000, "999")},
        {bench, {"soak", "--mem-from", "0"}, 2, range("--mem-from", 1, 100000000, "0")},
        {bench, {"soak", "--window", "99"}, 2, range("--window", 100, 1000000, "99")},
        {bench, {"soak", "--draw-every", "-1"}, 2, range("--draw-every", 0, 1000000, "-1")},
        {bench, {"soak", "--seed", "-1"}, 2, expected("--seed", kU64) + "-1"},
        {bench, {"soak", "--noise", "1.5"}, 2, "--noise: expected a number from 0 to 1, got 1.5"},
        {bench,
         {"soak", "--rss-tolerance-kb", "-1"},
         2,
         "--rss-tolerance-kb: expected a number from 0 to 1000000000, got -1"},
        {bench,
         {"soak", "--time-tolerance", "101"},
         2,
         "--time-tolerance: expected a number from 0 to 100, got 101"},
        {bench,
         {"soak", "--csv", "a-folder"},
         2,
         "--csv: a-folder: it is a folder; expected a file in a writable folder"},
    };
}

TEST_F(FlagTable, PolarcadeBench) {
    check(polarcadeBenchRows());
}

std::vector<Row> polarcadeBoundsRows() {
    const char* bounds = POLARCADE_BOUNDS_EXE;
    return {
        {bounds, {"gen", "x.png", "-n", "-1"}, 2, "--samples: expected a whole number from 0 to 720, got -1"},
        {bounds,
         {"gen", "x.png", "--samples", "721"},
         2,
         "--samples: expected a whole number from 0 to 720, got 721"},
        {bounds, {"gen", "x.png", "--radii", "0"}, 2, "--radii: expected a whole number from 1 to 16, got 0"},
        {bounds,
         {"gen", "x.png", "--radii", "17"},
         2,
         "--radii: expected a whole number from 1 to 16, got 17"},
        {bounds,
         {"gen", "x.png", "--centre", "1,two"},
         2,
         "--centre: expected X,Y with two finite numbers, e.g. 1.5,-2, got 1,two"},
        {bounds, {"gen", "x.png", "--centre", "1e999,0"}, 2, "got 1e999,0"},
        {bounds, {"gen", "x.png", "--centre", "0x10,0"}, 2, "got 0x10,0"},
        {bounds, {"gen", "x.png", "--centre", "1,2,3"}, 2, "got 1,2,3"},
        {bounds, {"gen", "x.png", "--centre", "nan,0"}, 2, "got nan,0"},
        {bounds, {"gen", "x.png", "--centre", " 1,2"}, 2, "got  1,2"},
        {bounds,
         {"gen", "x.png", "--threshold", "255"},
         2,
         "--threshold: expected a whole number from 0 to 254, got 255"},
        {bounds,
         {"check", "x.bounds.json", "--threshold", "-1"},
         2,
         "--threshold: expected a whole number from 0 to 254, got -1"},
        {bounds,
         {"view", "x.bounds.json", "-o", "x.png", "--scale", "0"},
         2,
         "--scale: expected a number above 0, got 0"},
        {bounds,
         {"view", "x.bounds.json", "-o", "x.png", "--scale", "-2"},
         2,
         "--scale: expected a number above 0, got -2"},
        {bounds,
         {"view", "x.bounds.json", "-o", "x.png", "--rotate", "nan"},
         2,
         "--rotate: expected a finite number, got nan"},
        {bounds,
         {"view", "x.bounds.json", "-o", "x.png", "--rotate", "1e999"},
         2,
         "--rotate: expected a finite number, got 1e999"},
        {bounds,
         {"view", "x.bounds.json", "-o", "x.png", "--zoom", "201"},
         2,
         "--zoom: expected a number from 0 to 200, got 201"},
        {bounds,
         {"view", "x.bounds.json", "-o", "x.png", "--zoom", "-1"},
         2,
         "--zoom: expected a number from 0 to 200, got -1"},
        {bounds,
         {"edit", "x.png", "--radii", "17"},
         2,
         "--radii: expected a whole number from 1 to 16, got 17"},
        {bounds,
         {"edit", "x.png", "--threshold", "255"},
         2,
         "--threshold: expected a whole number from 0 to 254, got 255"},
    };
}

TEST_F(FlagTable, PolarcadeBounds) {
    check(polarcadeBoundsRows());
}

std::vector<Row> polarcadeArtAndCollideRows() {
    return {
        {POLARCADE_ART_EXE, {"-o", "out", "--seed", "-1"}, 2, expected("--seed", kU64) + "-1"},
        {POLARCADE_ART_EXE,
         {"-o", "out", "--zoom", "0"},
         2,
         "--zoom: expected a whole number from 1 to 16, got 0"},
        {POLARCADE_ART_EXE,
         {"-o", "out", "--zoom", "17"},
         2,
         "--zoom: expected a whole number from 1 to 16, got 17"},
        // polarcade-collide has no numeric flag; its one value is a name, checked the same way.
        {POLARCADE_COLLIDE_EXE, {"scene.json", "--accuracy", "fast"}, 2, "unknown accuracy level \"fast\""},
    };
}

TEST_F(FlagTable, PolarcadeArtAndCollide) {
    check(polarcadeArtAndCollideRows());
}

// The table leaves no numeric flag out: every option that --help of each executable (and of each of
// its subcommands) shows with a number type (INT, UINT, FLOAT) has a row, so a flag added later
// without one fails here.
TEST_F(FlagTable, HasARowForEveryNumericFlagOfEveryExecutable) {
    std::vector<Row> rows;
    for (const auto& some : {polarcadeRows(), polarcadeReplayRows(), polarcadeBenchRows(),
                             polarcadeBoundsRows(), polarcadeArtAndCollideRows()})
        rows.insert(rows.end(), some.begin(), some.end());
    const std::regex optionLine(R"(^  (?:(-\w),)?(--[\w-]+) (\S+))");
    const std::regex numberType(R"(\b(U?INT|FLOAT)\b)");
    const std::regex subcommandLine(R"(^  ([a-z]+) )");
    auto help = [&](const char* exe, const std::vector<std::string>& args) {
        const CommandOutcome r = polar::testing::run(exe, args, folder_);
        EXPECT_EQ(r.exitCode, 0) << exe << " --help\n" << r.err;
        return r.out;
    };
    // Whether a row of `exe` (under `sub`, "" for none) gives the flag by either of its names.
    auto covered = [&](const char* exe, const std::string& sub, const std::string& shortName,
                       const std::string& longName) {
        for (const Row& row : rows) {
            if (std::string(row.exe) != exe) continue;
            if (!sub.empty() && (row.args.empty() || row.args[0] != sub)) continue;
            for (const std::string& arg : row.args)
                if (arg == longName || (!shortName.empty() && arg == shortName)) return true;
        }
        return false;
    };
    int numeric = 0;
    for (const char* exe : {POLARCADE_EXE, POLARCADE_REPLAY_EXE, POLARCADE_BENCH_EXE, POLARCADE_BOUNDS_EXE,
                            POLARCADE_ART_EXE, POLARCADE_COLLIDE_EXE}) {
        const std::string top = help(exe, {"--help"});
        std::vector<std::string> subs{""};
        std::istringstream lines(top);
        bool inSubcommands = false;
        for (std::string line; std::getline(lines, line);) {
            if (line.rfind("Subcommands:", 0) == 0) inSubcommands = true;
            std::smatch m;
            if (inSubcommands && std::regex_search(line, m, subcommandLine)) subs.push_back(m[1]);
        }
        for (const std::string& sub : subs) {
            std::istringstream text(sub.empty() ? top : help(exe, {sub, "--help"}));
            for (std::string line; std::getline(text, line);) {
                std::smatch m;
                if (!std::regex_search(line, m, optionLine)) continue;
                const std::string type = m[3];
                if (!std::regex_search(type, numberType)) continue;
                ++numeric;
                EXPECT_TRUE(covered(exe, sub, m[1], m[2]))
                    << fs::path(exe).filename().string() << (sub.empty() ? "" : " " + sub) << " " << m[2]
                    << " (" << type << ") has no row in the flag table";
            }
        }
    }
    EXPECT_GE(numeric, 40) << "the help texts were read";
}

}  // namespace
}  // namespace polar::game
