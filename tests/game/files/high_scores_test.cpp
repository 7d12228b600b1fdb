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

TEST_F(HighScoresTest, EachSceneAndSetOfModsHasItsOwnTable) {
    HighScores book = HighScores::load(path_);
    book.insert({"CAV", 500, 2});
    book.select("scenes/field.json");
    EXPECT_TRUE(book.entries().empty()) << "the field starts with an empty table";
    book.insert({"FLD", 300, 1});
    book.select("scenes/field.json", {"zeta", "alpha"});
    EXPECT_TRUE(book.entries().empty()) << "a mod set is a table of its own";
    book.insert({"MOD", 700, 4});
    ASSERT_FALSE(book.save());

    HighScores again = HighScores::load(path_);
    EXPECT_EQ(again.tables().size(), 3u);
    EXPECT_EQ(again.best({}), 500) << "the cave's table is the default";
    EXPECT_EQ(again.best({"scenes/field.json", {}}), 300);
    EXPECT_EQ(again.best({"scenes/field.json", {"alpha", "zeta"}}), 700);
    again.select("scenes/field.json", {"alpha", "zeta"});
    ASSERT_EQ(again.entries().size(), 1u) << "the mods are a set: their order does not matter";
    EXPECT_EQ(again.entries()[0].name, "MOD");
}

// The speed assist: a slower game is an easier one, so its scores are kept in a table of their own.
TEST_F(HighScoresTest, AGameAtAnotherSpeedHasItsOwnTable) {
    HighScores book = HighScores::load(path_);
    book.insert({"ACE", 500, 2});
    book.select("scenes/cave.json", {}, 75);
    EXPECT_TRUE(book.entries().empty()) << "75 % starts with an empty table";
    book.insert({"SLO", 900, 3});
    ASSERT_FALSE(book.save());
    EXPECT_NE(read(path_).find("\"speed\": 75"), std::string::npos) << read(path_);
    HighScores again = HighScores::load(path_);
    EXPECT_EQ(again.best({"scenes/cave.json", {}}), 500) << "full speed keeps its own best";
    EXPECT_EQ(again.best({"scenes/cave.json", {}, 75}), 900);

    std::ofstream(path_) << "{\"format\": 2, \"tables\": [{\"scene\": \"scenes/cave.json\", \"speed\": 20, "
                            "\"scores\": []}]}\n";
    std::optional<Error> problem;
    HighScores::load(path_, &problem);
    ASSERT_TRUE(problem);
    EXPECT_EQ(problem->message(),
              path_ + ":1:65: a game speed of 20 %; expected a game speed in percent, 50 to 100");
}

// The name entered last is kept with the tables: the name entry's Esc keeps a score under it.
TEST_F(HighScoresTest, TheLastNameUsedIsKept) {
    HighScores book = HighScores::load(path_);
    EXPECT_EQ(book.lastName(), "");
    book.insert({"JOE", 500, 2});
    book.insert({"ANN", 100, 1});
    EXPECT_EQ(book.lastName(), "ANN") << "the last placed, not the best";
    ASSERT_FALSE(book.save());
    EXPECT_EQ(HighScores::load(path_).lastName(), "ANN");
}

TEST_F(HighScoresTest, AnOlderOneTableFileIsKeptAsTheCavesTable) {
    std::ofstream(path_)
        << "{\"format\": 1, \"scores\": [{\"name\": \"OLD\", \"score\": 4200, \"wave\": 3},\n"
           "  {\"name\": \"TWO\", \"score\": 900, \"wave\": 1}]}\n";
    std::optional<Error> problem;
    HighScores book = HighScores::load(path_, &problem);
    ASSERT_FALSE(problem) << problem->message();
    ASSERT_EQ(book.entriesOf({"scenes/cave.json", {}}).size(), 2u);
    EXPECT_EQ(book.best({"scenes/cave.json", {}}), 4200);
    book.select("scenes/storm.json");
    book.insert({"NEW", 100, 1});
    ASSERT_FALSE(book.save());
    HighScores again = HighScores::load(path_, &problem);
    ASSERT_FALSE(problem) << problem->message();
    ASSERT_EQ(again.entriesOf({}).size(), 2u) << "the old table survives the save in the new format";
    EXPECT_EQ(again.entriesOf({})[0].name, "OLD");
    EXPECT_EQ(again.best({"scenes/storm.json", {}}), 100);
    EXPECT_NE(read(path_).find("\"format\": 2"), std::string::npos);
}

TEST_F(HighScoresTest, TwoTablesForOneSceneAreRefusedWithTheirPlace) {
    std::ofstream(path_) << "{\"format\": 2, \"tables\": [\n"
                            "  {\"scene\": \"scenes/cave.json\", \"scores\": []},\n"
                            "  {\"scene\": \"scenes/cave.json\", \"mods\": [], \"scores\": []}]}\n";
    std::optional<Error> problem;
    HighScores::load(path_, &problem);
    ASSERT_TRUE(problem);
    EXPECT_EQ(problem->line, 3);
    EXPECT_NE(problem->message().find("a second table"), std::string::npos) << problem->message();
}

}  // namespace
}  // namespace polar::game
