// polarcade-bench difficulty run as a user runs it, short: two games of one scene under a low cap
// give a CSV of the promised shape, the same bytes at one thread and at two, and a bad flag is one
// line and exit 2 with nothing measured and nothing written.
#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "run_command.h"
#include "scratch_folder.h"

namespace {

namespace fs = std::filesystem;
using polar::testing::CommandOutcome;
using polar::testing::readFile;

const std::string kHeader =
    "scene,games,capped,median_survival_minutes,median_score,median_wave,wave,reached,fraction_reached,"
    "median_minutes_at_wave,median_score_at_wave";

std::vector<std::string> split(const std::string& text, char separator) {
    std::vector<std::string> parts;
    std::stringstream in(text);
    for (std::string part; std::getline(in, part, separator);) parts.push_back(part);
    return parts;
}

std::size_t lineCount(const std::string& text) {
    return split(text, '\n').size();
}

class BenchDifficulty : public ::testing::Test {
  protected:
    void SetUp() override { folder_ = polar::testing::freshTestFolder("polar-bench-difficulty"); }
    void TearDown() override { fs::remove_all(folder_); }

    CommandOutcome difficulty(std::vector<std::string> args) {
        args.insert(args.begin(), "difficulty");
        return polar::testing::run(POLARCADE_BENCH, args, folder_);
    }

    fs::path folder_;
};

TEST_F(BenchDifficulty, TwoShortGamesGiveOneCsvRowPerWaveAtAnyThreadCount) {
    const std::vector<std::string> game{"--seeds", "2", "--scenes", "cave", "--max-minutes", "0.5"};
    std::vector<std::string> one = game, two = game;
    one.insert(one.end(), {"--threads", "1", "--csv", "one.csv"});
    two.insert(two.end(), {"--threads", "2", "--csv", "two.csv", "--plot", "two.png"});
    const CommandOutcome r1 = difficulty(one), r2 = difficulty(two);
    ASSERT_EQ(r1.exitCode, 0) << r1.err;
    ASSERT_EQ(r2.exitCode, 0) << r2.err;
    EXPECT_NE(r1.out.find("\ncave "), std::string::npos) << r1.out;
    EXPECT_NE(r1.err.find("difficulty: 2/2 games (100%)"), std::string::npos) << "progress: " << r1.err;

    const std::string csv = readFile(folder_ / "one.csv");
    EXPECT_EQ(csv, readFile(folder_ / "two.csv")) << "the figures depend on the thread count";
    EXPECT_GT(fs::file_size(folder_ / "two.png"), 0u);
    const std::vector<std::string> lines = split(csv, '\n');
    ASSERT_GE(lines.size(), 2u) << csv;
    EXPECT_EQ(lines[0], kHeader);
    for (std::size_t k = 1; k < lines.size(); ++k) {
        const std::vector<std::string> cells = split(lines[k], ',');
        ASSERT_EQ(cells.size(), 11u) << lines[k];
        EXPECT_EQ(cells[0], "cave");
        EXPECT_EQ(cells[1], "2");                                          // games
        EXPECT_LE(std::stoi(cells[2]), 2);                                 // capped
        EXPECT_GT(std::stod(cells[3]), 0.0);                               // median survival, minutes
        EXPECT_LE(std::stod(cells[3]), 0.5);                               // within the cap
        EXPECT_EQ(std::stoi(cells[6]), static_cast<int>(k));               // waves 1, 2, … in order
        EXPECT_GE(std::stoi(cells[7]), 1);                                 // a listed wave was reached
        EXPECT_DOUBLE_EQ(std::stod(cells[8]), std::stoi(cells[7]) / 2.0);  // share = reached / games
        EXPECT_LE(std::stod(cells[9]), 0.5);                               // reached within the cap
    }
    EXPECT_EQ(split(lines[1], ',')[8], "1.0000") << "every game starts in wave 1";
}

TEST_F(BenchDifficulty, ABadFlagIsOneLineAndExitTwoBeforeAnythingIsPlayed) {
    const std::vector<std::pair<std::vector<std::string>, std::string>> cases{
        {{"--seeds", "0"}, "--seeds: expected a whole number from 1 to 100000, got 0"},
        {{"--max-minutes", "0"}, "--max-minutes: expected a number from 0.05 to 1000, got 0"},
        {{"--max-minutes", "nan"}, "--max-minutes: expected a number from 0.05 to 1000, got nan"},
        {{"--threads", "0"}, "--threads: expected a whole number from 1 to 256, got 0"},
        {{"--scenes", "cave,nowhere"},
         "difficulty: --scenes: nowhere: no such scene file or scene name; expected"},
        {{"--csv", "no-such-folder/out.csv"}, "--csv: no-such-folder/out.csv: the folder "},
    };
    for (const auto& [args, message] : cases) {
        std::vector<std::string> withCsv = args;
        if (args[0] != "--csv") withCsv.insert(withCsv.end(), {"--csv", "out.csv"});
        const CommandOutcome r = difficulty(withCsv);
        EXPECT_EQ(r.exitCode, 2) << args[0] << ": " << r.err;
        EXPECT_EQ(lineCount(r.err), 1u) << args[0] << ": " << r.err;
        EXPECT_NE(r.err.find(message), std::string::npos) << r.err;
        EXPECT_TRUE(r.out.empty()) << args[0] << " played before refusing: " << r.out;
        EXPECT_TRUE(fs::is_empty(folder_)) << args[0] << " wrote a file";
    }
}

}  // namespace
