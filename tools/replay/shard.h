#pragma once
// One runner's share of a replay suite split across N runners (--shard K/N).
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace polar::game {

struct Shard {
    std::size_t index = 1;  // K, 1-based
    std::size_t count = 1;  // N
};

// Reads "K/N" with 1 <= K <= N. On bad text, nothing, and `problem` says what is wrong.
std::optional<Shard> parseShard(const std::string& text, std::string& problem);

// Shard K of N: the files sorted by path, then every N-th one starting at the K-th. The N shards are
// disjoint and together hold every file once, and a file's shard depends only on the sorted suite,
// never on the order the paths were given in.
std::vector<std::string> shardOf(std::vector<std::string> files, const Shard& shard);

}  // namespace polar::game
