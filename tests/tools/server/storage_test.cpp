// The SQLite storage: numbered migrations, boards ordered by score with ties to the earlier run,
// pages both ways, seasons, name ownership and run tokens used once.
#include <gtest/gtest.h>
#include <sqlite3.h>

#include "migrations.h"
#include "scratch_folder.h"
#include "sqlite_storage.h"

namespace polar::server {
namespace {

RunRecord runOf(const std::string& name, int score, std::int64_t submittedMs, const std::string& hash) {
    RunRecord r;
    r.name = name;
    r.publicKey = "key-of-" + nameKey(name);
    r.scene = "scenes/cave.json";
    r.mode = "rules-2";
    r.rules = 2;
    r.speed = 100;
    r.seed = 1;
    r.score = score;
    r.wave = 1;
    r.ticks = 600;
    r.ranked = true;
    r.submittedMs = submittedMs;
    r.runHash = hash;
    r.bytesHash = "bytes-" + hash;
    r.replay = "replay " + hash;
    return r;
}

class StorageTest : public ::testing::Test {
  protected:
    void SetUp() override {
        folder = polar::testing::freshTestFolder("polar-storage");
        path = (folder / "runs.sqlite").string();
        std::string error;
        storage = openSqliteStorage(path, error);
        ASSERT_TRUE(storage) << error;
    }
    void TearDown() override {
        storage.reset();
        std::filesystem::remove_all(folder);
    }
    std::int64_t store(const RunRecord& run) {
        std::int64_t id = 0;
        EXPECT_EQ(storage->store(run, "", id), StoreOutcome::kStored);
        return id;
    }
    std::filesystem::path folder;
    std::string path;
    std::unique_ptr<Storage> storage;
};

TEST_F(StorageTest, MigrationsAreNumberedInOrderAndAllApplied) {
    int expected = 1;
    for (const Migration& m : migrations()) EXPECT_EQ(m.version, expected++);
    EXPECT_EQ(storage->schemaVersion(), migrations().back().version);
    const std::int64_t id = store(runOf("Ada", 10, 1000, "a"));
    storage.reset();
    std::string error;
    storage = openSqliteStorage(path, error);  // opened again: nothing applied twice, nothing lost
    ASSERT_TRUE(storage) << error;
    EXPECT_EQ(storage->schemaVersion(), migrations().back().version);
    std::optional<RunRecord> run = storage->run(id, true);
    ASSERT_TRUE(run);
    EXPECT_EQ(run->replay, "replay a");
}

TEST_F(StorageTest, ADatabaseFromANewerServerIsRefused) {
    storage.reset();
    sqlite3* db = nullptr;
    ASSERT_EQ(sqlite3_open(path.c_str(), &db), SQLITE_OK);
    ASSERT_EQ(sqlite3_exec(db, "UPDATE schema_version SET version = 99", nullptr, nullptr, nullptr),
              SQLITE_OK);
    sqlite3_close(db);
    std::string error;
    EXPECT_FALSE(openSqliteStorage(path, error));
    EXPECT_NE(error.find("schema version 99"), std::string::npos) << error;
}

TEST_F(StorageTest, TiesGoToTheEarlierRunAndPagesGoBothWays) {
    const std::int64_t first = store(runOf("Ada", 500, 1000, "a"));
    const std::int64_t second = store(runOf("Bob", 500, 2000, "b"));
    store(runOf("Cy", 900, 3000, "c"));
    store(runOf("Di", 100, 4000, "d"));
    BoardQuery q{"scenes/cave.json", "rules-2", true, 0, 1, 2};
    BoardPage page = storage->top(q);
    EXPECT_EQ(page.total, 4);
    ASSERT_EQ(page.entries.size(), 2u);
    EXPECT_EQ(page.entries[0].run.name, "Cy");
    EXPECT_EQ(page.entries[1].run.id, first);  // 500 first scored by Ada
    EXPECT_EQ(page.entries[1].rank, 2);
    q.from = 3;
    page = storage->top(q);
    ASSERT_EQ(page.entries.size(), 2u);
    EXPECT_EQ(page.entries[0].run.id, second);
    EXPECT_EQ(page.entries[0].rank, 3);
    EXPECT_EQ(page.entries[1].run.name, "Di");
    EXPECT_EQ(storage->bestRank(q, "bob"), 3);  // names compare without case
    EXPECT_EQ(storage->bestRank(q, "Nobody"), std::nullopt);
}

TEST_F(StorageTest, ASeasonHoldsOnlyItsRunsAndRankedAndUnrankedAreApart) {
    store(runOf("Ada", 900, 1000, "a"));
    store(runOf("Bob", 100, 50'000, "b"));
    RunRecord offline = runOf("Cy", 5000, 60'000, "c");
    offline.ranked = false;
    store(offline);
    BoardQuery q{"scenes/cave.json", "rules-2", true, 40'000, 1, 10};
    BoardPage page = storage->top(q);
    ASSERT_EQ(page.entries.size(), 1u);
    EXPECT_EQ(page.entries[0].run.name, "Bob");
    EXPECT_EQ(page.entries[0].rank, 1);
    q.ranked = false;
    q.sinceMs = 0;
    page = storage->top(q);
    ASSERT_EQ(page.entries.size(), 1u);
    EXPECT_EQ(page.entries[0].run.name, "Cy");
}

TEST_F(StorageTest, ANameBelongsToTheFirstKeyAndATokenIsUsedOnce) {
    store(runOf("Ada", 10, 1000, "a"));
    RunRecord impostor = runOf("ADA", 20, 2000, "b");
    impostor.publicKey = "another key";
    std::int64_t id = 0;
    EXPECT_EQ(storage->store(impostor, "", id), StoreOutcome::kNameTaken);
    EXPECT_EQ(storage->nameOwner("aDa"), "key-of-ada");
    storage->issueToken("t1", 5000);
    EXPECT_EQ(storage->tokenIssued("t1"), 5000);
    EXPECT_EQ(storage->store(runOf("Bob", 1, 6000, "c"), "t1", id), StoreOutcome::kStored);
    EXPECT_EQ(storage->tokenIssued("t1"), std::nullopt);
    EXPECT_EQ(storage->store(runOf("Bob", 2, 7000, "d"), "t1", id), StoreOutcome::kTokenUsed);
    EXPECT_FALSE(storage->hasRun("d"));  // nothing of a refused run is kept
    EXPECT_EQ(storage->store(runOf("Bob", 3, 8000, "c"), "", id), StoreOutcome::kDuplicate);
    std::vector<RunRecord> best = storage->playerBest("bob");
    ASSERT_EQ(best.size(), 1u);
    EXPECT_EQ(best[0].score, 1);
}

}  // namespace
}  // namespace polar::server
