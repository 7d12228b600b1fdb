#include "migrations.h"

namespace polar::server {
namespace {

// Names are compared by name_key (nameKey in storage.h); runs keep the name as it was written.
// A run's id orders ties: the earlier run has the lower id.
constexpr Migration kMigrations[] = {
    {1, "players, run tokens and runs",
     "CREATE TABLE players (name_key TEXT PRIMARY KEY, name TEXT NOT NULL, public_key TEXT NOT NULL,"
     " created_ms BIGINT NOT NULL);"
     "CREATE TABLE tokens (token TEXT PRIMARY KEY, issued_ms BIGINT NOT NULL, used INTEGER NOT NULL);"
     "CREATE TABLE runs (id INTEGER PRIMARY KEY AUTOINCREMENT, name TEXT NOT NULL, name_key TEXT NOT NULL,"
     " public_key TEXT NOT NULL, scene TEXT NOT NULL, mode TEXT NOT NULL, rules INTEGER NOT NULL,"
     " speed INTEGER NOT NULL, seed TEXT NOT NULL, score INTEGER NOT NULL, wave INTEGER NOT NULL,"
     " ticks BIGINT NOT NULL, ranked INTEGER NOT NULL, submitted_ms BIGINT NOT NULL,"
     " run_hash TEXT NOT NULL UNIQUE, bytes_hash TEXT NOT NULL, replay BLOB NOT NULL);"
     "CREATE INDEX runs_board ON runs (scene, mode, ranked, score DESC, id);"
     "CREATE INDEX runs_player ON runs (name_key, score DESC, id)"},
    {2, "an index for the week's and the day's boards",
     "CREATE INDEX runs_season ON runs (scene, mode, ranked, submitted_ms)"},
};

}  // namespace

std::span<const Migration> migrations() {
    return kMigrations;
}

}  // namespace polar::server
