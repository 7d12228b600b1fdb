// The prototype catalogue: the looks (sprite and bounds file) of everything the game spawns, the
// bounds loaded once, and hot reload's edits to them (game.h).
#include "rules/game.h"

#include <set>

#include "polar/bounds_file.h"

namespace polar::game {
namespace {

constexpr const char* kRockSizeNames[] = {"", "small", "medium", "large"};

}  // namespace

bool Game::loadPrototypes(const FileReader& reader, Error& error) {
    auto load = [&](const std::string& name, Prototype& proto) {
        proto.look = lookFor(Look{"sprites/" + name + ".png", "sprites/" + name + ".bounds.json"});
        Result<BoundsPtr> bounds = loadBounds(looks_[proto.look].bounds, reader);
        if (!bounds) {
            error = bounds.error();
            return false;
        }
        proto.bounds = *bounds;
        return true;
    };
    for (int size = 1; size <= 3; ++size) {
        for (int v = 1; v <= kRockVariants; ++v) {
            Prototype proto;
            if (!load("rock-" + std::string(kRockSizeNames[size]) + "-" + std::to_string(v), proto))
                return false;
            rocks_[size].push_back(proto);
        }
    }
    return load("bullet", bullet_) && load("comet", comet_) && load("pickup-shield", pickups_[0]) &&
           load("pickup-life", pickups_[1]);
}

std::uint32_t Game::lookFor(const Look& look) {
    for (std::uint32_t k = 0; k < looks_.size(); ++k)
        if (looks_[k].sprite == look.sprite && looks_[k].bounds == look.bounds) return k;
    looks_.push_back(look);
    return static_cast<std::uint32_t>(looks_.size() - 1);
}

const Look& Game::lookOf(const GameObject& object) const {
    return object.userData < looks_.size() ? looks_[object.userData] : looks_.front();
}

template <class G>
auto Game::allPrototypes(G& game) {
    using Pointer = decltype(&game.bullet_);
    std::vector<Pointer> all{&game.ship_proto_, &game.bullet_, &game.comet_, &game.foeShot_};
    for (auto& proto : game.pickups_) all.push_back(&proto);
    for (auto& proto : game.foes_) all.push_back(&proto);
    for (auto& size : game.rocks_)
        for (auto& proto : size) all.push_back(&proto);
    return all;
}

std::vector<std::string> Game::boundsPaths() const {
    std::set<std::string> paths;
    for (const Look& look : looks_)
        if (!look.bounds.empty()) paths.insert(look.bounds);
    return {paths.begin(), paths.end()};
}

std::vector<std::string> Game::spritePaths() const {
    std::set<std::string> paths;
    for (const Look& look : looks_)
        if (!look.sprite.empty()) paths.insert(look.sprite);
    return {paths.begin(), paths.end()};
}

std::size_t Game::replaceBounds(const std::string& logical, BoundsPtr bounds) {
    if (logical.empty()) return 0;
    for (Prototype* proto : allPrototypes(*this))
        if (looks_[proto->look].bounds == logical) proto->bounds = bounds;
    std::size_t changed = 0;
    for (GameObject& object : world_.objects()) {
        if (lookOf(object).bounds != logical) continue;
        object.bounds = bounds;
        ++changed;
    }
    ++boundsEdits_;
    return changed;
}

}  // namespace polar::game
