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

// The rules of the table's order (game/files/high_scores.h): best first; a score equal to one
// already there ranks below it (the earlier game keeps its place); a full table takes only a score
// above its last, which then drops out.
TEST_F(HighScoresTest, ATieRanksBelowTheScoreThatWasThereFirst) {
    HighScores table = HighScores::load(path_);
    ASSERT_EQ(table.insert({"AAA", 500, 1}), std::optional<std::size_t>(0));
    ASSERT_EQ(table.insert({"BBB", 300, 1}), std::optional<std::size_t>(1));
    EXPECT_EQ(table.insert({"CCC", 300, 2}), std::optional<std::size_t>(2)) << "a tie goes below";
    EXPECT_EQ(table.insert({"DDD", 500, 2}), std::optional<std::size_t>(1)) << "a tie with the first";
    std::vector<std::string> names;
    for (const HighScores::Entry& e : table.entries()) names.push_back(e.name);
    EXPECT_EQ(names, (std::vector<std::string>{"AAA", "DDD", "BBB", "CCC"}));
}

TEST_F(HighScoresTest, AFullTableTakesOnlyAScoreAboveItsLastAndDropsTheLast) {
    HighScores table = HighScores::load(path_);
    for (int i = 0; i < static_cast<int>(HighScores::kSize); ++i)
        ASSERT_TRUE(table.insert({"P", 1000 - 100 * i, 1}));  // 1000 … 100
    ASSERT_EQ(table.entries().size(), HighScores::kSize);
    EXPECT_FALSE(table.qualifies(100)) << "equal to the last";
    EXPECT_FALSE(table.insert({"TIE", 100, 1}));
    EXPECT_TRUE(table.qualifies(101));
    EXPECT_EQ(table.insert({"ONE", 101, 1}), std::optional<std::size_t>(HighScores::kSize - 1));
    ASSERT_EQ(table.entries().size(), HighScores::kSize);
    EXPECT_EQ(table.entries().back().name, "ONE");
    EXPECT_EQ(table.insert({"TOP", 1001, 1}), std::optional<std::size_t>(0));
    ASSERT_EQ(table.entries().size(), HighScores::kSize);
    EXPECT_EQ(table.entries().front().name, "TOP");
    EXPECT_EQ(table.entries().back().score, 200) << "the old tenth dropped out";
}

TEST_F(HighScoresTest, AFileIsReadBestFirstTiesInFileOrderAndCutToTen) {
    // Twelve entries out of order, with ties: the table keeps the ten best, ties as the file has them.
    std::ofstream(path_) << R"({"format": 2, "tables": [{"scene": "scenes/cave.json", "mods": [], "scores": [
        {"name": "L1", "score": 10}, {"name": "T1", "score": 700}, {"name": "A", "score": 900},
        {"name": "T2", "score": 700}, {"name": "L2", "score": 10}, {"name": "B", "score": 800},
        {"name": "T3", "score": 700}, {"name": "C", "score": 600}, {"name": "D", "score": 500},
        {"name": "E", "score": 400}, {"name": "F", "score": 300}, {"name": "G", "score": 200}]}]})";
    std::optional<Error> problem;
    HighScores table = HighScores::load(path_, &problem);
    ASSERT_FALSE(problem) << problem->message();
    std::vector<std::string> names;
    for (const HighScores::Entry& e : table.entries()) names.push_back(e.name);
    EXPECT_EQ(names, (std::vector<std::string>{"A", "B", "T1", "T2", "T3", "C", "D", "E", "F", "G"}));
    EXPECT_EQ(table.entries().front().wave, 0) << "a wave left out is 0";

    // Forty entries, three scores among them: more than a sort keeps in order by chance (small
    // ranges are sorted by insertion, which happens to keep ties); the ten best are the first ten
    // scores of 200 in the file, in file order.
    std::string scores;
    std::vector<std::string> best;
    for (int i = 0; i < 40; ++i) {
        const std::string name = (i < 10 ? "N0" : "N") + std::to_string(i);
        scores += std::string(i ? ", " : "") + "{\"name\": \"" + name +
                  "\", \"score\": " + std::to_string((i % 3) * 100) + "}";
        if (i % 3 == 2 && best.size() < 10) best.push_back(name);
    }
    std::ofstream(path_)
        << R"({"format": 2, "tables": [{"scene": "scenes/cave.json", "mods": [], "scores": [)" + scores +
               "]}]}";
    table = HighScores::load(path_, &problem);
    ASSERT_FALSE(problem) << problem->message();
    names.clear();
    for (const HighScores::Entry& e : table.entries()) names.push_back(e.name);
    EXPECT_EQ(names, best);
}

TEST_F(HighScoresTest, EntriesAndFormatsAreCheckedAtTheirBoundaries) {
    auto problemOf = [&](const std::string& format, const std::string& entry) {
        std::ofstream(path_) << "{\"format\": " + format + ",\n \"scores\": [" + entry + "]}\n";
        std::optional<Error> problem;
        HighScores::load(path_, &problem);
        return problem;
    };
    EXPECT_FALSE(problemOf("1", R"({"name": "ABC", "score": 0})")) << "three letters and a score of 0";
    EXPECT_FALSE(problemOf("1", R"({"name": "", "score": 5})")) << "up to three letters: none is fine";
    for (const char* bad : {R"({"name": "ABCD", "score": 5})", R"({"name": "ABC", "score": -1})"}) {
        std::optional<Error> problem = problemOf("1", bad);
        ASSERT_TRUE(problem) << bad;
        EXPECT_EQ(problem->line, 2) << problem->message();
        EXPECT_NE(problem->message().find("up to 3 letters and a score"), std::string::npos)
            << problem->message();
    }
    for (const char* format : {"0", "3"}) {
        std::optional<Error> problem = problemOf(format, "");
        ASSERT_TRUE(problem) << "format " << format;
        EXPECT_NE(problem->message().find("unsupported format"), std::string::npos) << problem->message();
    }
}

TEST_F(HighScoresTest, TheSameModsInAnotherOrderAreTheSameTable) {
    std::ofstream(path_)
        << "{\"format\": 2, \"tables\": [\n"
           "  {\"scene\": \"scenes/cave.json\", \"mods\": [\"b\", \"a\"], \"scores\": []},\n"
           "  {\"scene\": \"scenes/cave.json\", \"mods\": [\"a\", \"b\"], \"scores\": []}]}\n";
    std::optional<Error> problem;
    HighScores::load(path_, &problem);
    ASSERT_TRUE(problem) << "the mods are a set";
    EXPECT_EQ(problem->line, 3);
    EXPECT_NE(problem->message().find("a second table"), std::string::npos) << problem->message();
}

TEST_F(HighScoresTest, AnEarlierSetAsideTableIsNotOverwritten) {
    std::ofstream(path_ + ".bad") << "the first broken table";
    std::ofstream(path_) << "{\"format\": 2, \"tables\": [";
    std::optional<Error> problem;
    HighScores table = HighScores::load(path_, &problem);
    ASSERT_TRUE(problem);
    table.insert({"NEW", 10, 1});
    ASSERT_FALSE(table.save());
    EXPECT_EQ(read(path_ + ".bad"), "the first broken table");
    EXPECT_EQ(read(path_ + ".bad-2"), "{\"format\": 2, \"tables\": [");
    EXPECT_EQ(HighScores::load(path_).entries().size(), 1u);
}

TEST(ModSet, EachModFolderIsItsLastNameAndTheSetIsSorted) {
    EXPECT_EQ(modSetOf({"mods/zeta/", "/home/p/alpha", "gold"}),
              (std::vector<std::string>{"alpha", "gold", "zeta"}));
    EXPECT_EQ(modSetOf({"a/b/../gold/."}), std::vector<std::string>{"gold"});
}

}  // namespace
}  // namespace polar::game
