#include "shard.h"

#include <algorithm>
#include <charconv>

namespace polar::game {
namespace {

// A whole decimal number filling `text`, or nothing (no sign, no blanks, no overflow).
std::optional<std::size_t> wholeNumber(const std::string& text) {
    std::size_t value = 0;
    const char* end = text.data() + text.size();
    auto [at, ec] = std::from_chars(text.data(), end, value);
    if (text.empty() || ec != std::errc() || at != end) return std::nullopt;
    return value;
}

}  // namespace

std::optional<Shard> parseShard(const std::string& text, std::string& problem) {
    const std::size_t slash = text.find('/');
    std::optional<std::size_t> k, n;
    if (slash != std::string::npos) {
        k = wholeNumber(text.substr(0, slash));
        n = wholeNumber(text.substr(slash + 1));
    }
    if (!k || !n) {
        problem = "not two whole numbers K/N";
        return std::nullopt;
    }
    if (*n == 0) {
        problem = "N is 0; there must be at least one shard";
        return std::nullopt;
    }
    if (*k < 1 || *k > *n) {
        problem = "K is " + std::to_string(*k) + ", outside 1.." + std::to_string(*n);
        return std::nullopt;
    }
    return Shard{*k, *n};
}

std::vector<std::string> shardOf(std::vector<std::string> files, const Shard& shard) {
    std::sort(files.begin(), files.end());
    std::vector<std::string> out;
    for (std::size_t i = shard.index - 1; i < files.size(); i += shard.count) out.push_back(files[i]);
    return out;
}

}  // namespace polar::game
