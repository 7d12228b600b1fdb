#include "files/high_scores.h"

#include <algorithm>
#include <filesystem>

#include "polar/atomic_file.h"
#include "polar/json_doc.h"
#include "polar/json_writer.h"

namespace polar::game {

namespace {

using Entry = HighScores::Entry;

std::vector<Entry> readScores(const JsonNode& scores) {
    std::vector<Entry> out;
    for (const JsonNode& item : scores.items("an array of scores")) {
        item.allowKeys({"name", "score", "wave"});
        Entry e;
        e.name = item.require("name", "a name").string("a name of up to 3 letters");
        e.score = item.require("score", "a score").integer("a whole score");
        e.wave = item.find("wave") ? item.find("wave")->integer("a wave number") : 0;
        if (e.name.size() > 3 || e.score < 0)
            item.fail("an invalid entry", "a name of up to 3 letters and a score ≥ 0");
        out.push_back(e);
    }
    std::stable_sort(out.begin(), out.end(),
                     [](const Entry& a, const Entry& b) { return a.score > b.score; });
    if (out.size() > HighScores::kSize) out.resize(HighScores::kSize);
    return out;
}

}  // namespace

HighScores HighScores::load(const std::string& path, std::optional<Error>* problem) {
    HighScores book;
    book.path_ = path;
    std::optional<SourceFile> file = diskReader()(path);
    if (!file) return book;
    auto fail = [&](const Error& error) {
        if (problem) *problem = error;
        book.tables_.clear();
        book.setAsideOnSave_ = true;
        return book;
    };
    Result<JsonDoc> doc = JsonDoc::parse(*file);
    if (!doc) return fail(doc.error());
    using Tables = std::map<TableKey, std::vector<Entry>>;
    std::string lastName;
    Result<Tables> tables = catchLoadFailure<Tables>([&] {
        JsonNode root = JsonNode::root(*doc);
        JsonNode format = root.require("format", "\"format\": 2");
        int version = format.integer("the format number 1 or 2");
        Tables out;
        if (version == 1) {
            root.allowKeys({"format", "scores"});
            out[TableKey{}] = readScores(root.require("scores", "\"scores\": [...]"));
            return out;
        }
        if (version != 2) format.fail("unsupported format " + std::to_string(version), "\"format\": 1 or 2");
        root.allowKeys({"format", "last_name", "tables"});
        if (auto name = root.find("last_name")) {
            lastName = name->string("a name of up to 3 letters");
            if (lastName.size() > 3)
                name->fail("a name of " + std::to_string(lastName.size()) + " letters",
                           "a name of up to 3 letters");
        }
        for (const JsonNode& table :
             root.require("tables", "\"tables\": [...]").items("an array of tables")) {
            table.allowKeys({"scene", "mods", "speed", "scores"});
            TableKey key;
            key.scene = table.require("scene", "a scene's logical path").string("a scene's logical path");
            if (auto mods = table.find("mods"))
                for (const JsonNode& mod : mods->items("an array of mod names"))
                    key.mods.push_back(mod.string("a mod's name"));
            std::sort(key.mods.begin(), key.mods.end());
            if (auto speed = table.find("speed")) {
                key.speed = speed->integer("a game speed in percent, 50 to 100");
                if (key.speed < 50 || key.speed > 100)
                    speed->fail("a game speed of " + std::to_string(key.speed) + " %",
                                "a game speed in percent, 50 to 100");
            }
            if (out.count(key))
                table.fail("a second table for the same scene, mods and speed", "one table for each");
            out[key] = readScores(table.require("scores", "\"scores\": [...]"));
        }
        return out;
    });
    if (!tables) return fail(tables.error());
    book.tables_ = std::move(*tables);
    book.lastName_ = std::move(lastName);
    return book;
}

std::vector<std::string> modSetOf(const std::vector<std::string>& modFolders) {
    std::vector<std::string> names;
    for (const std::string& folder : modFolders) {
        std::filesystem::path path = std::filesystem::path(folder).lexically_normal();
        if (!path.has_filename()) path = path.parent_path();  // "mods/gold/" → "gold"
        names.push_back(path.filename().string());
    }
    std::sort(names.begin(), names.end());
    return names;
}

void HighScores::select(std::string scene, std::vector<std::string> mods, int speed) {
    std::sort(mods.begin(), mods.end());
    selected_ = TableKey{std::move(scene), std::move(mods), speed};
}

const std::vector<HighScores::Entry>& HighScores::entriesOf(const TableKey& key) const {
    static const std::vector<Entry> kEmpty;
    auto it = tables_.find(key);
    return it == tables_.end() ? kEmpty : it->second;
}

int HighScores::best(const TableKey& key) const {
    const std::vector<Entry>& entries = entriesOf(key);
    return entries.empty() ? 0 : entries.front().score;
}

bool HighScores::qualifies(int score) const {
    const std::vector<Entry>& entries = this->entries();
    return score > 0 && (entries.size() < kSize || score > entries.back().score);
}

std::optional<std::size_t> HighScores::insert(const Entry& entry) {
    if (!qualifies(entry.score)) return std::nullopt;
    std::vector<Entry>& entries = tables_[selected_];
    auto at =
        std::find_if(entries.begin(), entries.end(), [&](const Entry& e) { return entry.score > e.score; });
    std::size_t rank = static_cast<std::size_t>(at - entries.begin());
    entries.insert(at, entry);
    if (entries.size() > kSize) entries.resize(kSize);
    lastName_ = entry.name;
    return rank;
}

std::string HighScores::toJson() const {
    JsonWriter w(2);
    w.beginObject().member("format", 2);
    if (!lastName_.empty()) w.member("last_name", lastName_);
    w.key("tables").beginArray();
    for (const auto& [key, entries] : tables_) {
        if (entries.empty()) continue;
        w.beginObject().member("scene", key.scene).key("mods").beginArray();
        for (const std::string& mod : key.mods) w.value(mod);
        w.endArray();
        if (key.speed != 100) w.member("speed", key.speed);
        w.key("scores").beginArray();
        for (const Entry& e : entries)
            w.beginObject()
                .member("name", e.name)
                .member("score", e.score)
                .member("wave", e.wave)
                .endObject();
        w.endArray().endObject();
    }
    w.endArray().endObject();
    return w.text() + "\n";
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
