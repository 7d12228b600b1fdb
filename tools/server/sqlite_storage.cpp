#include "sqlite_storage.h"

#include <sqlite3.h>

#include <mutex>

#include "migrations.h"

namespace polar::server {
namespace {

// One prepared statement, finalized when it goes out of scope; values are always bound, never
// pasted into the SQL.
class Statement {
  public:
    Statement(sqlite3* db, const char* sql) : db_(db) {
        if (sqlite3_prepare_v2(db, sql, -1, &stmt_, nullptr) != SQLITE_OK)
            throw StorageError(std::string("sqlite: ") + sqlite3_errmsg(db));
    }
    ~Statement() { sqlite3_finalize(stmt_); }
    Statement(const Statement&) = delete;
    Statement& operator=(const Statement&) = delete;

    Statement& bind(int i, const std::string& text) {
        check(sqlite3_bind_text(stmt_, i, text.data(), static_cast<int>(text.size()), SQLITE_TRANSIENT));
        return *this;
    }
    Statement& bindBlob(int i, const std::string& bytes) {
        check(sqlite3_bind_blob(stmt_, i, bytes.data(), static_cast<int>(bytes.size()), SQLITE_TRANSIENT));
        return *this;
    }
    Statement& bind(int i, std::int64_t value) {
        check(sqlite3_bind_int64(stmt_, i, value));
        return *this;
    }
    // True while there is a row; false when done; throws on an error.
    bool step() {
        int rc = sqlite3_step(stmt_);
        if (rc == SQLITE_ROW) return true;
        if (rc == SQLITE_DONE) return false;
        throw StorageError(std::string("sqlite: ") + sqlite3_errmsg(db_));
    }
    // Runs a statement that returns no rows; the SQLite result code (SQLITE_CONSTRAINT is returned,
    // every other failure thrown).
    int run() {
        int rc = sqlite3_step(stmt_);
        if (rc == SQLITE_DONE || (rc & 0xff) == SQLITE_CONSTRAINT) return rc & 0xff;
        throw StorageError(std::string("sqlite: ") + sqlite3_errmsg(db_));
    }
    std::int64_t integer(int column) const { return sqlite3_column_int64(stmt_, column); }
    std::string text(int column) const {
        const void* bytes = sqlite3_column_blob(stmt_, column);
        return bytes ? std::string(static_cast<const char*>(bytes), sqlite3_column_bytes(stmt_, column))
                     : std::string();
    }

  private:
    void check(int rc) {
        if (rc != SQLITE_OK) throw StorageError(std::string("sqlite: ") + sqlite3_errmsg(db_));
    }
    sqlite3* db_;
    sqlite3_stmt* stmt_ = nullptr;
};

void exec(sqlite3* db, const char* sql) {
    char* message = nullptr;
    if (sqlite3_exec(db, sql, nullptr, nullptr, &message) != SQLITE_OK) {
        std::string text = message ? message : "unknown error";
        sqlite3_free(message);
        throw StorageError("sqlite: " + text);
    }
}

// The columns every run query reads, in RunRecord's order (the replay bytes last, when wanted).
constexpr const char* kRunColumns =
    "id, name, public_key, scene, mode, rules, speed, seed, score, wave, ticks, ranked, submitted_ms, "
    "run_hash, bytes_hash";

RunRecord readRun(const Statement& s, bool withReplay) {
    RunRecord r;
    r.id = s.integer(0);
    r.name = s.text(1);
    r.publicKey = s.text(2);
    r.scene = s.text(3);
    r.mode = s.text(4);
    r.rules = static_cast<int>(s.integer(5));
    r.speed = static_cast<int>(s.integer(6));
    r.seed = std::stoull(s.text(7));
    r.score = static_cast<int>(s.integer(8));
    r.wave = static_cast<int>(s.integer(9));
    r.ticks = static_cast<std::uint64_t>(s.integer(10));
    r.ranked = s.integer(11) != 0;
    r.submittedMs = s.integer(12);
    r.runHash = s.text(13);
    r.bytesHash = s.text(14);
    if (withReplay) r.replay = s.text(15);
    return r;
}

class SqliteStorage final : public Storage {
  public:
    explicit SqliteStorage(sqlite3* db) : db_(db) {}
    ~SqliteStorage() override { sqlite3_close(db_); }

    // WAL, a wait for a lock held by another process, and the migrations.
    void prepare() {
        exec(db_, "PRAGMA journal_mode=WAL");
        exec(db_, "PRAGMA synchronous=FULL");
        sqlite3_busy_timeout(db_, 5000);
        exec(db_, "CREATE TABLE IF NOT EXISTS schema_version (version INTEGER NOT NULL)");
        int current = schemaVersion();
        const int newest = migrations().back().version;
        if (current > newest)
            throw StorageError("the database is at schema version " + std::to_string(current) +
                               ", newer than this server's " + std::to_string(newest) +
                               "; expected a database this server or an older one made");
        for (const Migration& m : migrations()) {
            if (m.version <= current) continue;
            exec(db_, "BEGIN IMMEDIATE");
            try {
                exec(db_, m.sql);
                exec(db_, "DELETE FROM schema_version");
                Statement(db_, "INSERT INTO schema_version (version) VALUES (?)").bind(1, m.version).run();
                exec(db_, "COMMIT");
            } catch (...) {
                sqlite3_exec(db_, "ROLLBACK", nullptr, nullptr, nullptr);
                throw;
            }
        }
    }

    int schemaVersion() override {
        std::lock_guard lock(mutex_);
        Statement s(db_, "SELECT MAX(version) FROM schema_version");
        return s.step() ? static_cast<int>(s.integer(0)) : 0;
    }

    void issueToken(const std::string& token, std::int64_t nowMs) override {
        std::lock_guard lock(mutex_);
        Statement(db_, "INSERT INTO tokens (token, issued_ms, used) VALUES (?, ?, 0)")
            .bind(1, token)
            .bind(2, nowMs)
            .run();
    }

    std::optional<std::int64_t> tokenIssued(const std::string& token) override {
        std::lock_guard lock(mutex_);
        Statement s(db_, "SELECT issued_ms FROM tokens WHERE token = ? AND used = 0");
        s.bind(1, token);
        if (!s.step()) return std::nullopt;
        return s.integer(0);
    }

    std::optional<std::string> nameOwner(const std::string& name) override {
        std::lock_guard lock(mutex_);
        return ownerLocked(nameKey(name));
    }

    bool hasRun(const std::string& runHash) override {
        std::lock_guard lock(mutex_);
        Statement s(db_, "SELECT 1 FROM runs WHERE run_hash = ?");
        s.bind(1, runHash);
        return s.step();
    }

    StoreOutcome store(const RunRecord& run, const std::string& token, std::int64_t& id) override {
        std::lock_guard lock(mutex_);
        exec(db_, "BEGIN IMMEDIATE");
        try {
            StoreOutcome outcome = storeLocked(run, token, id);
            exec(db_, outcome == StoreOutcome::kStored ? "COMMIT" : "ROLLBACK");
            return outcome;
        } catch (...) {
            sqlite3_exec(db_, "ROLLBACK", nullptr, nullptr, nullptr);
            throw;
        }
    }

    BoardPage top(const BoardQuery& q) override {
        std::lock_guard lock(mutex_);
        BoardPage page;
        Statement count(
            db_,
            "SELECT COUNT(*) FROM runs WHERE scene = ? AND mode = ? AND ranked = ? AND submitted_ms >= ?");
        bindSlice(count, q);
        if (count.step()) page.total = count.integer(0);
        std::string sql = std::string("SELECT ") + kRunColumns +
                          " FROM runs WHERE scene = ? AND mode = ? AND ranked = ? AND submitted_ms >= ?"
                          " ORDER BY score DESC, id ASC LIMIT ? OFFSET ?";
        Statement s(db_, sql.c_str());
        bindSlice(s, q);
        s.bind(5, static_cast<std::int64_t>(q.count)).bind(6, q.from - 1);
        for (std::int64_t rank = q.from; s.step(); ++rank) page.entries.push_back({rank, readRun(s, false)});
        return page;
    }

    std::optional<std::int64_t> bestRank(const BoardQuery& q, const std::string& name) override {
        std::lock_guard lock(mutex_);
        Statement best(
            db_,
            "SELECT score, id FROM runs WHERE scene = ? AND mode = ? AND ranked = ? AND submitted_ms >= ?"
            " AND name_key = ? ORDER BY score DESC, id ASC LIMIT 1");
        bindSlice(best, q);
        best.bind(5, nameKey(name));
        if (!best.step()) return std::nullopt;
        const std::int64_t score = best.integer(0), id = best.integer(1);
        Statement ahead(
            db_,
            "SELECT COUNT(*) FROM runs WHERE scene = ? AND mode = ? AND ranked = ? AND submitted_ms >= ?"
            " AND (score > ? OR (score = ? AND id < ?))");
        bindSlice(ahead, q);
        ahead.bind(5, score).bind(6, score).bind(7, id);
        ahead.step();
        return ahead.integer(0) + 1;
    }

    std::vector<RunRecord> playerBest(const std::string& name) override {
        std::lock_guard lock(mutex_);
        std::string sql = std::string("SELECT ") + kRunColumns +
                          " FROM (SELECT *, ROW_NUMBER() OVER (PARTITION BY scene, mode, ranked"
                          " ORDER BY score DESC, id ASC) AS place FROM runs WHERE name_key = ?)"
                          " WHERE place = 1 ORDER BY ranked DESC, scene, mode";
        Statement s(db_, sql.c_str());
        s.bind(1, nameKey(name));
        std::vector<RunRecord> runs;
        while (s.step()) runs.push_back(readRun(s, false));
        return runs;
    }

    std::optional<RunRecord> run(std::int64_t id, bool withReplay) override {
        std::lock_guard lock(mutex_);
        std::string sql =
            std::string("SELECT ") + kRunColumns + (withReplay ? ", replay" : "") + " FROM runs WHERE id = ?";
        Statement s(db_, sql.c_str());
        s.bind(1, id);
        if (!s.step()) return std::nullopt;
        return readRun(s, withReplay);
    }

  private:
    std::optional<std::string> ownerLocked(const std::string& key) {
        Statement s(db_, "SELECT public_key FROM players WHERE name_key = ?");
        s.bind(1, key);
        if (!s.step()) return std::nullopt;
        return s.text(0);
    }

    StoreOutcome storeLocked(const RunRecord& run, const std::string& token, std::int64_t& id) {
        const std::string key = nameKey(run.name);
        if (std::optional<std::string> owner = ownerLocked(key)) {
            if (*owner != run.publicKey) return StoreOutcome::kNameTaken;
        } else {
            Statement(db_, "INSERT INTO players (name_key, name, public_key, created_ms) VALUES (?, ?, ?, ?)")
                .bind(1, key)
                .bind(2, run.name)
                .bind(3, run.publicKey)
                .bind(4, run.submittedMs)
                .run();
        }
        if (!token.empty()) {
            Statement use(db_, "UPDATE tokens SET used = 1 WHERE token = ? AND used = 0");
            use.bind(1, token).run();
            if (sqlite3_changes(db_) != 1) return StoreOutcome::kTokenUsed;
        }
        Statement insert(
            db_,
            "INSERT INTO runs (name, name_key, public_key, scene, mode, rules, speed, seed, score,"
            " wave, ticks, ranked, submitted_ms, run_hash, bytes_hash, replay)"
            " VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?)");
        insert.bind(1, run.name)
            .bind(2, key)
            .bind(3, run.publicKey)
            .bind(4, run.scene)
            .bind(5, run.mode)
            .bind(6, std::int64_t{run.rules})
            .bind(7, std::int64_t{run.speed})
            .bind(8, std::to_string(run.seed))
            .bind(9, std::int64_t{run.score})
            .bind(10, std::int64_t{run.wave})
            .bind(11, static_cast<std::int64_t>(run.ticks))
            .bind(12, std::int64_t{run.ranked ? 1 : 0})
            .bind(13, run.submittedMs)
            .bind(14, run.runHash)
            .bind(15, run.bytesHash)
            .bindBlob(16, run.replay);
        if (insert.run() == SQLITE_CONSTRAINT) return StoreOutcome::kDuplicate;
        id = sqlite3_last_insert_rowid(db_);
        return StoreOutcome::kStored;
    }

    static void bindSlice(Statement& s, const BoardQuery& q) {
        s.bind(1, q.scene).bind(2, q.mode).bind(3, std::int64_t{q.ranked ? 1 : 0}).bind(4, q.sinceMs);
    }

    sqlite3* db_;
    std::mutex mutex_;  // one connection, one statement at a time
};

}  // namespace

std::unique_ptr<Storage> openSqliteStorage(const std::string& path, std::string& error) {
    sqlite3* db = nullptr;
    if (sqlite3_open_v2(path.c_str(), &db, SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE | SQLITE_OPEN_FULLMUTEX,
                        nullptr) != SQLITE_OK) {
        error = path + ": " + (db ? sqlite3_errmsg(db) : "cannot open") + "; expected a database file path";
        sqlite3_close(db);
        return nullptr;
    }
    auto storage = std::make_unique<SqliteStorage>(db);
    try {
        storage->prepare();
    } catch (const StorageError& e) {
        error = path + ": " + e.what();
        return nullptr;
    }
    return storage;
}

}  // namespace polar::server
