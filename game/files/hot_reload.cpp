#include "files/hot_reload.h"

#include <chrono>
#include <set>

#include "polar/bounds_file.h"
#include "polar/scene_file.h"

namespace polar::game {

namespace fs = std::filesystem;

namespace {

// How long a freshly written invalid file is given to be finished before its error is shown.
constexpr std::chrono::milliseconds kSettleTime{300};

}  // namespace

HotReload::HotReload(const AssetFs& assets, int lookEvery)
    : assets_(assets), lookEvery_(lookEvery < 1 ? 1 : lookEvery) {}

void HotReload::disable(std::string reason) {
    disabledReason_ = reason.empty() ? "disabled" : std::move(reason);
}

FileReader HotReload::reader() const {
    FileReader overlay = assets_.reader();
    return [this, overlay](const std::string& path) -> std::optional<SourceFile> {
        if (problems_.count(path)) {
            if (auto good = good_.find(path); good != good_.end()) return SourceFile{path, good->second};
        }
        return overlay(path);
    };
}

HotReload::Stamp HotReload::stampOf(const std::string& logical) const {
    Stamp stamp;
    stamp.disk = assets_.resolve(logical);
    if (!stamp.disk) return stamp;
    std::error_code ec;
    stamp.time = fs::last_write_time(*stamp.disk, ec);
    stamp.size = fs::file_size(*stamp.disk, ec);
    if (ec) stamp.size = 0;
    return stamp;
}

HotReload::Report HotReload::update(const std::vector<Game*>& games, bool now) {
    ++calls_;
    Report report;
    if (!enabled()) {
        if (now) tell("hot reload is off: " + disabledReason_);
        return report;
    }
    if (lookedOnce_ && !now && calls_ - lastLook_ < static_cast<std::uint64_t>(lookEvery_)) return report;
    lookedOnce_ = true;
    lastLook_ = calls_;
    look(games, now, report);
    // Nothing left to reload is good news: the edits were applied by themselves already.
    if (now && report.reloaded.empty() && report.errors.empty() && problems_.empty())
        tell(lastReloaded_.empty()
                 ? "F5: the bounds are already current (an edit reloads by itself within half a second)"
                 : "F5: the bounds are already current (" + lastReloaded_ + " was reloaded by itself)");
    return report;
}

void HotReload::look(const std::vector<Game*>& games, bool force, Report& report) {
    report.looked = true;
    std::set<std::string> bounds, sprites, scenes;
    for (const Game* game : games) {
        if (!game) continue;
        for (std::string& path : game->boundsPaths()) bounds.insert(std::move(path));
        for (std::string& path : game->spritePaths()) sprites.insert(std::move(path));
        scenes.insert(game->scenePath());
    }
    for (const std::string& path : bounds) checkFile(path, Kind::Bounds, games, force, report);
    for (const std::string& path : scenes) checkFile(path, Kind::Scene, games, force, report);
    for (const std::string& path : sprites) {
        Stamp stamp = stampOf(path);
        auto [it, first] = stamps_.try_emplace(path, stamp);
        if (first || (!force && it->second == stamp)) continue;
        it->second = stamp;
        report.spritesChanged.push_back(path);
    }
}

void HotReload::checkFile(const std::string& logical, Kind kind, const std::vector<Game*>& games, bool force,
                          Report& report) {
    Stamp stamp = stampOf(logical);
    auto [it, first] = stamps_.try_emplace(logical, stamp);
    if (!first && !force && it->second == stamp) return;
    it->second = stamp;

    auto setProblem = [&](Error error) {
        error = assets_.onDisk(std::move(error));
        auto known = problems_.find(logical);
        if (known != problems_.end() && known->second.message() == error.message()) return;
        problems_[logical] = error;
        report.errors.push_back(error);
    };
    std::optional<SourceFile> file = stamp.disk ? diskReader()(*stamp.disk) : std::nullopt;
    if (file) file->path = logical;  // as the overlay names it, so the paths a scene names stay logical
    const std::string shown = stamp.disk.value_or(logical);
    if (!file) {
        setProblem(Error{logical, 0, 0, "the file is gone from assets/ and every mod (or cannot be read)",
                         "the file back; the game keeps the old one until then"});
        return;
    }
    auto good = good_.find(logical);
    bool hadProblem = problems_.count(logical) != 0;
    if (good != good_.end() && !hadProblem && good->second == file->text) return;  // touched, not changed

    // Exactly the game's loaders decide, on exactly the text just read (a scene's bounds files come
    // through reader(), as a new game would read them).
    std::optional<Error> invalid;
    Result<BoundsPtr> bounds = BoundsPtr{};
    if (kind == Kind::Bounds) {
        bounds = loadBounds(logical, [&file](const std::string&) { return file; });
        if (!bounds) invalid = bounds.error();
    } else {
        FileReader others = reader();
        Result<SceneDef> scene = loadScene(
            logical, [&](const std::string& path) { return path == logical ? file : others(path); });
        if (!scene) invalid = scene.error();
    }
    if (invalid) {
        // An editor that saves in place (truncate, then write) can be caught half way. A file written
        // in the last moments gets another look before its error is shown; F5 shows it at once.
        auto age = fs::file_time_type::clock::now() - stamp.time;
        if (!force && age >= fs::file_time_type::duration::zero() && age < kSettleTime) {
            it->second = Stamp{};  // differs from any real stamp: the next look reads it again
            return;
        }
        setProblem(*invalid);
        return;
    }
    if (hadProblem) {
        problems_.erase(logical);
        report.fixed.push_back(logical);
    }
    if (first) {  // the games loaded this text a moment ago: it is the baseline, nothing to apply
        good_[logical] = file->text;
        return;
    }
    if (good != good_.end() && good->second == file->text) {
        tell(shown + " is valid again (as before the error)");
        return;
    }
    good_[logical] = file->text;
    if (kind == Kind::Scene) {
        report.scenes.push_back(logical);
        tell(shown + " changed: it applies to the next game");
        return;
    }
    std::size_t objects = 0;
    for (Game* game : games)
        if (game) objects += game->replaceBounds(logical, *bounds);
    report.reloaded.push_back(logical);
    report.objects.push_back(objects);
    lastReloaded_ = shown;
    tell("reloaded " + shown + " (" + std::to_string(objects) + (objects == 1 ? " object)" : " objects)"));
}

void HotReload::tell(std::string notice) {
    notice_ = std::move(notice);
    noticeAt_ = calls_;
}

}  // namespace polar::game
