// libFuzzer target: the bytes are a replay file's text, read as polarcade --replay and
// polarcade-replay read one (parseReplay). A replay that reads must survive formatReplay →
// parseReplay unchanged, since the tools rewrite replays with formatReplay.
#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz_contract.h"
#include "replay/replay.h"

namespace {

using polar::game::Replay;

bool sameCheckpoints(const Replay& a, const Replay& b) {
    if (a.checkpoints.size() != b.checkpoints.size()) return false;
    for (std::size_t i = 0; i < a.checkpoints.size(); ++i) {
        const polar::game::Checkpoint& x = a.checkpoints[i];
        const polar::game::Checkpoint& y = b.checkpoints[i];
        if (x.tick != y.tick || x.hash != y.hash || x.rng != y.rng || x.score != y.score ||
            x.lives != y.lives || x.wave != y.wave || x.objects != y.objects)
            return false;
    }
    return true;
}

bool sameTuning(const polar::game::Tuning& a, const polar::game::Tuning& b) {
    return a.tickRate == b.tickRate && a.turnRate == b.turnRate && a.thrust == b.thrust &&
           a.maxShipSpeed == b.maxShipSpeed && a.shipDamping == b.shipDamping &&
           a.bulletSpeed == b.bulletSpeed && a.bulletLife == b.bulletLife &&
           a.fireCooldown == b.fireCooldown && a.maxBullets == b.maxBullets &&
           a.respawnDelay == b.respawnDelay && a.invulnerableAfterRespawn == b.invulnerableAfterRespawn &&
           a.shieldTime == b.shieldTime && a.pickupLife == b.pickupLife && a.pickupChance == b.pickupChance &&
           a.waveDelay == b.waveDelay && a.startLives == b.startLives && a.extraLifeEvery == b.extraLifeEvery;
}

// What differs between two readings of a replay ("" when nothing does).
std::string difference(const Replay& a, const Replay& b) {
    const polar::game::ReplayHeader& x = a.header;
    const polar::game::ReplayHeader& y = b.header;
    if (x.gameVersion != y.gameVersion) return "game version";
    if (x.scene != y.scene || x.sceneIsFile != y.sceneIsFile) return "scene";
    if (x.seed != y.seed) return "seed";
    if (!sameTuning(x.tuning, y.tuning)) return "tuning";
    if (x.mods != y.mods) return "mods";
    if (x.assets.size() != y.assets.size()) return "asset count";
    for (std::size_t i = 0; i < x.assets.size(); ++i)
        if (x.assets[i].name != y.assets[i].name || x.assets[i].hash != y.assets[i].hash) return "assets";
    if (x.screenshots.size() != y.screenshots.size()) return "screenshot count";
    for (std::size_t i = 0; i < x.screenshots.size(); ++i)
        if (x.screenshots[i].tick != y.screenshots[i].tick || x.screenshots[i].png != y.screenshots[i].png)
            return "screenshots";
    if (x.comments != y.comments) return "comments";
    if (a.actions != b.actions) return "actions";
    if (a.trace != b.trace) return "trace";
    if (!sameCheckpoints(a, b)) return "checkpoints";
    if (a.end.has_value() != b.end.has_value()) return "end";
    if (a.end && (a.end->tick != b.end->tick || a.end->reason != b.end->reason)) return "end";
    return "";
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string path = "replays/fuzz.replay";
    std::string text(reinterpret_cast<const char*>(data), size);
    polar::Result<Replay> replay = polar::game::parseReplay(path, text);
    if (!replay) {
        polar::fuzz::checkError(replay.error(), text);
        return 0;
    }
    (void)polar::game::replayNotes(*replay);
    // Rewriting a run of a million ticks is slow and says nothing new.
    if (replay->actions.size() > 100'000) return 0;
    std::string rewritten = polar::game::formatReplay(*replay);
    polar::Result<Replay> again = polar::game::parseReplay(path, rewritten);
    if (!again) polar::fuzz::broken("a rewritten replay does not read again", again.error().message());
    std::string what = difference(*replay, *again);
    if (!what.empty()) polar::fuzz::broken("formatReplay → parseReplay changed the " + what, rewritten);
    return 0;
}
