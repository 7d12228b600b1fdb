#include "files/high_scores.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "scratch_folder.h"

namespace polar::game {
namespace {

namespace fs = std::filesystem;

class HighScoresTest : public ::testing::Test {
  protected:
    void SetUp() override {
        dir_ = polar::testing::freshTestFolder("polar-hs");
        path_ = (dir_ / "highscores.json").string();
    }
    void TearDown() override { fs::remove_all(dir_); }
    std::string read(const std::string& p) {
        std::ifstream in(p);
        return std::string(std::istreambuf_iterator<char>(in), {});
    }
    fs::path dir_;
    std::string path_;
};

TEST_F(HighScoresTest, MissingFileIsAnEmptyTable) {
    std::optional<Error> problem;
    HighScores table = HighScores::load(path_, &problem);
    EXPECT_FALSE(problem);
    EXPECT_TRUE(table.entries().empty());
    EXPECT_TRUE(table.qualifies(10));
    EXPECT_FALSE(table.qualifies(0));
}

TEST_F(HighScoresTest, KeepsTheBestTenInOrderAndSurvivesASaveAndLoad) {
    HighScores table = HighScores::load(path_);
    for (int i = 1; i <= 12; ++i) table.insert({"P" + std::to_string(i % 10), i * 100, i});
    ASSERT_EQ(table.entries().size(), HighScores::kSize);
    EXPECT_EQ(table.entries().front().score, 1200);
    EXPECT_EQ(table.entries().back().score, 300);
    EXPECT_FALSE(table.qualifies(300)) << "a tie with the last place does not push it out";
    EXPECT_EQ(table.insert({"NEW", 650, 4}), std::optional<std::size_t>(6));
    ASSERT_FALSE(table.save());
    HighScores again = HighScores::load(path_);
    ASSERT_EQ(again.entries().size(), table.entries().size());
    for (std::size_t i = 0; i < again.entries().size(); ++i) {
        EXPECT_EQ(again.entries()[i].name, table.entries()[i].name);
        EXPECT_EQ(again.entries()[i].score, table.entries()[i].score);
        EXPECT_EQ(again.entries()[i].wave, table.entries()[i].wave);
    }
}

TEST_F(HighScoresTest, AnUnreadableTableIsReportedAndKeptAside) {
    std::ofstream(path_) << "{\"format\": 1, \"scores\": [{\"name\": \"ACE\", \"score\": 12,}]}";
    std::string original = read(path_);
    std::optional<Error> problem;
    HighScores table = HighScores::load(path_, &problem);
    ASSERT_TRUE(problem);
    EXPECT_EQ(problem->file, path_);
    EXPECT_EQ(problem->line, 1);
    EXPECT_TRUE(table.entries().empty());
    table.insert({"BOB", 50, 1});
    ASSERT_FALSE(table.save());
    EXPECT_EQ(read(path_ + ".bad"), original) << "the player's old file is not lost";
    EXPECT_EQ(HighScores::load(path_).entries().size(), 1u);
}

TEST_F(HighScoresTest, AFullDiskLeavesTheOldTable) {
    HighScores table = HighScores::load(path_);
    table.insert({"ACE", 900, 3});
    ASSERT_FALSE(table.save());
    std::string before = read(path_);
    table.insert({"BOB", 950, 3});
    for (AtomicWriteStep failing : {AtomicWriteStep::kOpen, AtomicWriteStep::kWrite, AtomicWriteStep::kSync,
                                    AtomicWriteStep::kRename}) {
        std::optional<Error> error = table.save([&](AtomicWriteStep step) { return step == failing; });
        ASSERT_TRUE(error) << static_cast<int>(failing);
        EXPECT_EQ(error->file, path_);
        EXPECT_EQ(read(path_), before) << "step " << static_cast<int>(failing);
        EXPECT_EQ(std::distance(fs::directory_iterator(dir_), fs::directory_iterator()), 1)
            << "no temporary file left";
    }
    ASSERT_FALSE(table.save());
    EXPECT_EQ(HighScores::load(path_).entries().front().name, "BOB");
}

}  // namespace
}  // namespace polar::game
