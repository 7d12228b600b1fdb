#pragma once
#include <map>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include "polar/atomic_file.h"
#include "polar/error.h"

namespace polar::game {

// The best ten games of each scene, set of mods and game speed, kept in the player's data folder as
// highscores.json:
//   {"format": 2, "last_name": "ACE",
//    "tables": [{"scene": "scenes/cave.json", "mods": [], "speed": 75,
//                "scores": [{"name": "ACE", "score": 12340, "wave": 5}, ...]}, ...]}
// A table without "speed" is for games at full speed (100 %); the file has no "last_name" until a
// name was entered.
// An older file (format 1: one "scores" table, from before there were scenes to choose) is read as
// the cave's table without mods, and the next save writes it back in format 2 with the others.
//
// Why so careful? A high-score table is the one thing a player would be sad to lose. It is written
// atomically (temporary file, then rename), so a crash leaves the old table or the new one. A table
// that cannot be read is never overwritten: it is kept beside the new one as highscores.json.bad
// (.bad-2, .bad-3, … when an earlier one is already there).
class HighScores {
  public:
    struct Entry {
        std::string name;  // up to 3 letters A–Z
        int score = 0;
        int wave = 0;
    };
    static constexpr std::size_t kSize = 10;
    // Which table: a scene's logical path, the names of the mods laid over it, sorted, and the game
    // speed in percent (the speed assist: a slower game is an easier one, so it has its own table).
    struct TableKey {
        std::string scene = kDefaultScene;
        std::vector<std::string> mods;
        int speed = 100;
        // Ordered by scene, then mods, then speed (spelt out: emscripten's libc++ has no <=> for
        // strings).
        bool operator<(const TableKey& other) const {
            return std::tie(scene, mods, speed) < std::tie(other.scene, other.mods, other.speed);
        }
        bool operator==(const TableKey& other) const = default;
    };
    static constexpr const char* kDefaultScene = "scenes/cave.json";

    // Reads the table at `path`. A missing file is an empty table; an unreadable one is an empty
    // table plus the Error (and the file is set aside before the first save).
    static HighScores load(const std::string& path, std::optional<Error>* problem = nullptr);

    // Chooses the table that entries, qualifies and insert work on (the cave's until then); the mods
    // are a set, so their order does not matter.
    void select(std::string scene, std::vector<std::string> mods = {}, int speed = 100);
    const TableKey& selected() const { return selected_; }
    // The selected table, best first.
    const std::vector<Entry>& entries() const { return entriesOf(selected_); }
    const std::vector<Entry>& entriesOf(const TableKey& key) const;
    // The best score of a table, 0 when it is empty.
    int best(const TableKey& key) const;
    // Every table that has an entry, in key order.
    const std::map<TableKey, std::vector<Entry>>& tables() const { return tables_; }
    // Whether a score earns a place.
    bool qualifies(int score) const;
    // Inserts an entry in rank order; returns its rank (0-based) or nothing if it did not place. A
    // placed entry's name becomes the last name used.
    std::optional<std::size_t> insert(const Entry& entry);
    // The name the player entered last (kept with the tables), empty before the first.
    const std::string& lastName() const { return lastName_; }
    // Writes the table atomically. Returns the Error, if any; the old file then stays as it was.
    // `fault` injects I/O failures in tests (a full disk, say).
    std::optional<Error> save(const AtomicWriteFault& fault = {});

    std::string toJson() const;
    const std::string& path() const { return path_; }

  private:
    std::string path_;
    std::map<TableKey, std::vector<Entry>> tables_;
    TableKey selected_;
    std::string lastName_;
    bool setAsideOnSave_ = false;
};

// The mod set a table is kept for: each mod folder's name (its last path part), sorted.
std::vector<std::string> modSetOf(const std::vector<std::string>& modFolders);

}  // namespace polar::game
