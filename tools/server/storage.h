#pragma once
// What the server keeps, behind one small interface: players and the keys that own their names, run
// tokens, and verified runs with their replay bytes.
//
// Why an interface? The server speaks of runs and boards, never of SQL: each database is one
// implementation of this class (sqlite_storage.cpp), so the routes and the verification never
// change with it. Every method is safe to call from several threads at once.
#include <cstdint>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace polar::server {

// A database that failed underneath (a full disk, a lost connection): the request answers 500.
struct StorageError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// One verified run: what the server computed (score, wave, ticks), who signed it, and its bytes.
struct RunRecord {
    std::int64_t id = 0;
    std::string name;       // as the player wrote it
    std::string publicKey;  // hexadecimal Ed25519 public key
    std::string scene;      // the logical scene path ("scenes/cave.json")
    std::string mode;       // the board's mode (boardMode in verification.h)
    int rules = 0;
    int speed = 0;
    std::uint64_t seed = 0;
    int score = 0;
    int wave = 0;
    std::uint64_t ticks = 0;
    bool ranked = false;           // submitted with a run token whose time allowed it
    std::int64_t submittedMs = 0;  // milliseconds since 1970, UTC
    std::string runHash;           // what makes two submissions the same run (verification.h)
    std::string bytesHash;         // SHA-256 of the replay bytes, as signed
    std::string replay;            // the bytes; empty unless asked for
};

// One slice of a board: a scene × mode, ranked or not, runs since a moment (a season).
struct BoardQuery {
    std::string scene;
    std::string mode;
    bool ranked = true;
    std::int64_t sinceMs = 0;  // 0: all time
    std::int64_t from = 1;     // the first rank wanted (1-based)
    int count = 20;
};

struct BoardEntry {
    std::int64_t rank = 0;
    RunRecord run;  // without its bytes
};

struct BoardPage {
    std::int64_t total = 0;  // runs in the slice
    std::vector<BoardEntry> entries;
};

// How storing a run ended: only kStored changed anything.
enum class StoreOutcome { kStored, kDuplicate, kNameTaken, kTokenUsed };

class Storage {
  public:
    virtual ~Storage() = default;

    // The schema version the database is at (the last migration applied).
    virtual int schemaVersion() = 0;

    // Records a new run token issued now.
    virtual void issueToken(const std::string& token, std::int64_t nowMs) = 0;
    // When an unused token was issued; nothing for an unknown or used one.
    virtual std::optional<std::int64_t> tokenIssued(const std::string& token) = 0;
    // The public key that owns `name` (names compare without ASCII case), if any.
    virtual std::optional<std::string> nameOwner(const std::string& name) = 0;
    // Whether a run with this run hash is stored.
    virtual bool hasRun(const std::string& runHash) = 0;
    // In one transaction: the name claimed for the run's key when nobody owns it, the token (when
    // not empty) marked used, the run inserted. Nothing is changed unless the outcome is kStored;
    // `id` is then the new run's.
    virtual StoreOutcome store(const RunRecord& run, const std::string& token, std::int64_t& id) = 0;

    // Runs of a slice from rank `from`, best first; ties go to the earlier run (the lower id).
    virtual BoardPage top(const BoardQuery& query) = 0;
    // The rank of the best run of `name` in the slice (ignoring from and count), if it has one.
    virtual std::optional<std::int64_t> bestRank(const BoardQuery& query, const std::string& name) = 0;
    // The best run of `name` on each board (scene × mode, ranked first), all time.
    virtual std::vector<RunRecord> playerBest(const std::string& name) = 0;
    // One run, with its replay bytes when `withReplay`.
    virtual std::optional<RunRecord> run(std::int64_t id, bool withReplay) = 0;
};

// Opens the database a --db value names ("sqlite:PATH"), migrating it to the newest schema. Nothing
// and `error` set when it cannot.
std::unique_ptr<Storage> openStorage(const std::string& url, std::string& error);

// The key a name is compared by: ASCII letters folded to lower case.
std::string nameKey(const std::string& name);

}  // namespace polar::server
