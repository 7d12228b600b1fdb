#pragma once
#include <optional>
#include <string>
#include <vector>

#include "polar/atomic_file.h"
#include "polar/error.h"

namespace polar::game {

// The best ten games, kept in the player's data folder as highscores.json:
//   {"format": 1, "scores": [{"name": "ACE", "score": 12340, "wave": 5}, ...]}
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

    // Reads the table at `path`. A missing file is an empty table; an unreadable one is an empty
    // table plus the Error (and the file is set aside before the first save).
    static HighScores load(const std::string& path, std::optional<Error>* problem = nullptr);

    const std::vector<Entry>& entries() const { return entries_; }
    // Whether a score earns a place.
    bool qualifies(int score) const;
    // Inserts an entry in rank order; returns its rank (0-based) or nothing if it did not place.
    std::optional<std::size_t> insert(const Entry& entry);
    // Writes the table atomically. Returns the Error, if any; the old file then stays as it was.
    // `fault` injects I/O failures in tests (a full disk, say).
    std::optional<Error> save(const AtomicWriteFault& fault = {});

    std::string toJson() const;
    const std::string& path() const { return path_; }

  private:
    std::string path_;
    std::vector<Entry> entries_;
    bool setAsideOnSave_ = false;
};

}  // namespace polar::game
