#include "files/high_scores.h"

#include <algorithm>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "polar/atomic_file.h"
#include "polar/json_doc.h"

namespace polar::game {

HighScores HighScores::load(const std::string& path, std::optional<Error>* problem) {
    HighScores table;
    table.path_ = path;
    std::optional<SourceFile> file = diskReader()(path);
    if (!file) return table;
    auto fail = [&](const Error& error) {
        if (problem) *problem = error;
        table.entries_.clear();
        table.setAsideOnSave_ = true;
        return table;
    };
    Result<JsonDoc> doc = JsonDoc::parse(*file);
    if (!doc) return fail(doc.error());
    Result<std::vector<Entry>> entries = catchLoadFailure<std::vector<Entry>>([&] {
        JsonNode root = JsonNode::root(*doc);
        root.allowKeys({"format", "scores"});
        JsonNode format = root.require("format", "\"format\": 1");
        if (format.integer("the format number 1") != 1) format.fail("unsupported format", "\"format\": 1");
        std::vector<Entry> out;
        for (const JsonNode& item : root.require("scores", "\"scores\": [...]").items("an array of scores")) {
            item.allowKeys({"name", "score", "wave"});
            Entry e;
            e.name = item.require("name", "a name").string("a name of up to 3 letters");
            e.score = item.require("score", "a score").integer("a whole score");
            e.wave = item.find("wave") ? item.find("wave")->integer("a wave number") : 0;
            if (e.name.size() > 3 || e.score < 0)
                item.fail("an invalid entry", "a name of up to 3 letters and a score ≥ 0");
            out.push_back(e);
        }
        return out;
    });
    if (!entries) return fail(entries.error());
    table.entries_ = *entries;
    std::stable_sort(table.entries_.begin(), table.entries_.end(),
                     [](const Entry& a, const Entry& b) { return a.score > b.score; });
    if (table.entries_.size() > kSize) table.entries_.resize(kSize);
    return table;
}

bool HighScores::qualifies(int score) const {
    return score > 0 && (entries_.size() < kSize || score > entries_.back().score);
}

std::optional<std::size_t> HighScores::insert(const Entry& entry) {
    if (!qualifies(entry.score)) return std::nullopt;
    auto at =
        std::find_if(entries_.begin(), entries_.end(), [&](const Entry& e) { return entry.score > e.score; });
    std::size_t rank = static_cast<std::size_t>(at - entries_.begin());
    entries_.insert(at, entry);
    if (entries_.size() > kSize) entries_.resize(kSize);
    return rank;
}

std::string HighScores::toJson() const {
    nlohmann::ordered_json scores = nlohmann::ordered_json::array();
    for (const Entry& e : entries_)
        scores.push_back({{"name", e.name}, {"score", e.score}, {"wave", e.wave}});
    nlohmann::ordered_json root = {{"format", 1}, {"scores", scores}};
    return root.dump(2) + "\n";
}

std::optional<Error> HighScores::save(const AtomicWriteFault& fault) {
    if (setAsideOnSave_) {
        std::error_code ec;
        // An earlier unreadable table already set aside is not overwritten: .bad, .bad-2, .bad-3, …
        std::string aside = path_ + ".bad";
        for (int n = 2; std::filesystem::exists(aside, ec); ++n) aside = path_ + ".bad-" + std::to_string(n);
        if (std::filesystem::exists(path_, ec)) std::filesystem::rename(path_, aside, ec);
        if (ec)
            return Error{path_, 0, 0, "cannot set the unreadable table aside: " + ec.message(),
                         "a writable data folder"};
        setAsideOnSave_ = false;
    }
    return writeFileAtomically(path_, toJson(), fault);
}

}  // namespace polar::game
