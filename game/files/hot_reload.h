#pragma once
#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "files/assets.h"
#include "polar/error.h"
#include "rules/game.h"

namespace polar::game {

// Watches the bounds files, sprite images and scene a running game uses, in assets/ and in every
// mod, and applies a modder's edits between ticks. Bounds apply at once; a scene edit is checked at
// once and applies to the next game started.
//
// Why poll, and why here? A look is one stat() per file (a few dozen small files), cheap enough
// twice a second, the same on every platform and for every mod folder, with no thread: update()
// runs in the game loop between two ticks, so a reload never lands inside a step. An edit is
// applied only when the game's own loader accepts it; otherwise the running games keep their
// bounds and the loader's error (file:line:column) stays in problems() until the file is fixed, so
// a typo never stops the game. Games started meanwhile read through reader(), which serves the last
// valid version of a broken file, so they get the same bounds the running game has.
//
// Reloading changes a game's future (Game::modified); a recording or a replay must not see it, so
// the app disables reloading while it records or replays.
class HotReload {
  public:
    // What one update() did.
    struct Report {
        bool looked = false;                      // the files were examined
        std::vector<std::string> reloaded;        // bounds files applied, logical paths
        std::vector<std::string> scenes;          // scene files changed (valid), for the next game
        std::vector<std::size_t> objects;         // objects changed, per reloaded file (all games)
        std::vector<Error> errors;                // new or changed problems
        std::vector<std::string> fixed;           // files whose problem went away
        std::vector<std::string> spritesChanged;  // sprite images to read again, logical paths
    };

    // Looks at the files every `lookEvery` calls of update() (30 ticks: half a second at 60 Hz).
    explicit HotReload(const AssetFs& assets, int lookEvery = kLookEvery);
    static constexpr int kLookEvery = 30;

    // Turns reloading off; update(…, true) then only notes `reason` for the HUD.
    void disable(std::string reason);
    bool enabled() const { return disabledReason_.empty(); }

    // Reads logical paths through the asset overlay, except that a bounds or scene file whose
    // current edit is invalid is served as its last valid version.
    FileReader reader() const;

    // Called once per frame or tick, between ticks: on the first call, every lookEvery-th call
    // after it, and whenever `now` (F5) is true, looks at the files `games` use (null entries are
    // skipped) and applies every valid edit to all of them.
    Report update(const std::vector<Game*>& games, bool now = false);

    // Bounds and scene files whose current edit is invalid, by logical path, with the loader's error.
    const std::map<std::string, Error>& problems() const { return problems_; }
    // The last thing worth telling the player ("reloaded sprites/ship.bounds.json …"), and how many
    // update() calls ago it happened.
    const std::string& notice() const { return notice_; }
    std::uint64_t noticeAge() const { return calls_ - noticeAt_; }

  private:
    // What a file on disk looked like at the last look: which layer had it, when it was written, its size.
    struct Stamp {
        std::optional<std::string> disk;
        std::filesystem::file_time_type time{};
        std::uintmax_t size = 0;
        bool operator==(const Stamp&) const = default;
    };
    Stamp stampOf(const std::string& logical) const;
    void look(const std::vector<Game*>& games, bool force, Report& report);
    enum class Kind { Bounds, Scene };
    void checkFile(const std::string& logical, Kind kind, const std::vector<Game*>& games, bool force,
                   Report& report);
    void tell(std::string notice);

    const AssetFs& assets_;
    int lookEvery_;
    std::uint64_t calls_ = 0;
    std::uint64_t lastLook_ = 0;
    bool lookedOnce_ = false;
    std::string disabledReason_;
    std::map<std::string, Stamp> stamps_;      // bounds files and sprites, by logical path
    std::map<std::string, std::string> good_;  // the text of each bounds or scene file the games now use
    std::map<std::string, Error> problems_;
    std::string notice_;
    std::uint64_t noticeAt_ = 0;
    std::string lastReloaded_;  // the last bounds file applied, as on disk
};

}  // namespace polar::game
