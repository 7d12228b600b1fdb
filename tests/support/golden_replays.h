#pragma once
// The golden replays of tests/replays/ (POLAR_REPLAY_DIR), for tests that play every one.
#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

namespace polar::testing {

// Every tests/replays/*.replay, sorted by name.
inline std::vector<std::string> goldenReplays() {
    std::vector<std::string> files;
    for (const std::filesystem::directory_entry& entry :
         std::filesystem::directory_iterator(POLAR_REPLAY_DIR))
        if (entry.path().extension() == ".replay") files.push_back(entry.path().string());
    std::sort(files.begin(), files.end());
    return files;
}

}  // namespace polar::testing
