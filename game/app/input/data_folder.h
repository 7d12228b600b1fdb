#pragma once
#include <optional>
#include <string>

#include "polar/error.h"

namespace polar::game {

// The environment variable that names the data folder instead of the platform's per-user folder.
inline constexpr const char* kDataFolderVariable = "POLARCADE_DATA";

// The player's data folder (high scores, replays) and whether anything can be saved there.
struct DataFolder {
    std::string path;              // ends with '/'; empty when there is none at all
    std::optional<Error> problem;  // why nothing can be written there
    bool writable() const { return !path.empty() && !problem; }
};

// --data DIR (`asked`), else $POLARCADE_DATA, else the platform's per-user folder; created if
// missing, then probed by writing a file, so a read-only or non-folder path is found before a game
// is lost to it.
DataFolder openDataFolder(const std::string& asked);

}  // namespace polar::game
