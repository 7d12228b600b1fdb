#pragma once
// The words of the replay text and the pieces it is written in, shared by the code that writes it
// (formatReplay, ReplayWriter), the code that reads it (parseReplay) and the reports that quote it
// (desyncs). The functions are defined in replay_format.cpp.
#include <cstdint>
#include <span>
#include <string>

#include "replay/replay_format.h"
#include "rules/actions.h"
#include "rules/game.h"

namespace polar::game::detail {

// The first word of every replay file.
inline constexpr const char* kMagic = "polarcade-replay";
// Two characters of this alphabet (base64url) hold one tick's 12-bit trace.
inline constexpr char kTraceAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789-_";
// Action letters in the order they are written.
struct ActionLetter {
    char letter;
    Actions bit;
};
inline constexpr ActionLetter kActionLetters[] = {
    {'L', kTurnLeft}, {'R', kTurnRight}, {'T', kThrust}, {'F', kFire}};

// Tuning values as the "tuning" line names them. tickRate has a line of its own ("tick-rate").
struct TuningField {
    const char* name;
    double Tuning::*real;
    int Tuning::*whole;
};
inline constexpr TuningField kTuningFields[] = {
    {"turn-rate", &Tuning::turnRate, nullptr},
    {"thrust", &Tuning::thrust, nullptr},
    {"max-ship-speed", &Tuning::maxShipSpeed, nullptr},
    {"ship-damping", &Tuning::shipDamping, nullptr},
    {"bullet-speed", &Tuning::bulletSpeed, nullptr},
    {"bullet-life", &Tuning::bulletLife, nullptr},
    {"fire-cooldown", &Tuning::fireCooldown, nullptr},
    {"max-bullets", nullptr, &Tuning::maxBullets},
    {"respawn-delay", &Tuning::respawnDelay, nullptr},
    {"invulnerable-after-respawn", &Tuning::invulnerableAfterRespawn, nullptr},
    {"shield-time", &Tuning::shieldTime, nullptr},
    {"pickup-life", &Tuning::pickupLife, nullptr},
    {"pickup-chance", &Tuning::pickupChance, nullptr},
    {"wave-delay", &Tuning::waveDelay, nullptr},
    {"start-lives", nullptr, &Tuning::startLives},
    {"extra-life-every", nullptr, &Tuning::extraLifeEvery},
};
// 14 doubles and 3 ints (plus one int of padding after maxBullets). A new Tuning field changes the
// size: list it above so replays record it.
static_assert(sizeof(Tuning) == 14 * sizeof(double) + 4 * sizeof(int),
              "add the new Tuning field to kTuningFields");

// A 64-bit hash as the replay writes it: 16 hexadecimal digits.
std::string hex64(std::uint64_t v);

// The header, from the first line to "begin".
std::string headerText(const ReplayHeader& h);
// An "in" line: the actions as runs of letters (nothing for no ticks).
void appendInputs(std::string& out, std::span<const Actions> actions);
// A "trace" line: two characters of kTraceAlphabet per tick (nothing for no ticks).
void appendTrace(std::string& out, std::span<const std::uint16_t> trace);
// A "check" line and its "objects" line.
void appendCheckpoint(std::string& out, const Checkpoint& c);

}  // namespace polar::game::detail
