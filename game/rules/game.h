#pragma once
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "polar/error.h"
#include "polar/scene_file.h"
#include "polar/world.h"
#include "polar/world_snapshot.h"
#include "rules/actions.h"
#include "rules/rng.h"
#include "rules/scene_rules.h"

namespace polar::game {

// The numbers that make the game feel the way it does, in world units (screen pixels) and seconds.
struct Tuning {
    double tickRate = 60.0;
    double turnRate = 4.2;  // radians per second
    double thrust = 260.0;  // acceleration, units per second²
    double maxShipSpeed = 260.0;
    double shipDamping = 0.35;
    double bulletSpeed = 430.0;
    double bulletLife = 0.85;  // seconds
    double fireCooldown = 0.14;
    int maxBullets = 6;
    double respawnDelay = 2.0;
    double invulnerableAfterRespawn = 2.5;
    double shieldTime = 6.0;
    double pickupLife = 9.0;
    double pickupChance = 0.10;  // per rock destroyed
    double waveDelay = 2.0;      // pause between a cleared wave and the next
    int startLives = 3;
    int extraLifeEvery = 10000;
};

// The rules a game plays by, numbered. A replay records the number its game was played under and is
// replayed under the same one, so a change to the rules never breaks a replay saved before it; a new
// game plays by the newest.
//   1  the first rules (every replay without a "rules" line).
//   2  hit-stop: the game holds still for a few ticks after a big hit (a large rock split, a comet
//      shot, a life lost); a rock's pieces keep its look (rock-large-2 splits into rock-medium-2s);
//      a wave's rocks start farther from the ship and never head straight at it.
//   3  foes, power-ups and the score multiplier, in a scene that calls for them ("foes",
//      "powerups" in its "game" block); a scene that calls for none plays exactly as under rules 2.
inline constexpr int kRulesVersion = 3;
// The game-speed assist: each tick advances the game by speed/100 of 1/tickRate seconds, so a game
// at 50 runs half as fast, tick for tick. A replay records it; 100 plays as every game did before.
inline constexpr int kMinGameSpeed = 50;
inline constexpr int kMaxGameSpeed = 100;

// What kind of thing a world object is, to the game.
enum class Kind : std::uint8_t { Arena, Ship, Rock, Bullet, Pickup, Comet, Scenery, Foe, FoeShot };
// What a pickup gives: Shield and Life always; the power-ups (rules 3) where the scene calls for them.
enum class PickupKind : std::uint8_t { Shield, Life, Spread, Rapid, Barrier };
// Each foe a scene's Foe brings: a saucer is large (shoots anywhere) or small (aims at the ship); a
// mine bursts into shards that home on the ship.
enum class FoeKind : std::uint8_t { Saucer, SmallSaucer, Mine, Shard, Hunter };
inline constexpr int kFoeKindCount = 5;

// Something that happened during a tick, for sound, particles and the tests. What an event says
// beyond its type and place (the look, angle and motion of the thing it happened to, the points it
// scored) is for the picture only: the rules never read an event back.
struct GameEvent {
    enum Type : std::uint8_t {
        Shot,
        RockSplit,
        RockDestroyed,
        ShipHit,
        ShipRespawn,
        PickupTaken,
        WaveStart,
        CometIn,
        CometShot,
        Bounce,
        WallHit,
        ExtraLife,
        GameOver,
        WaveCleared,  // the last rock of a wave is gone
        Thrust,       // the ship thrusts this tick (where: its tail; angle: its heading)
        // Rules 3 (size: the FoeKind, or for PowerUpEnd the PickupKind):
        FoeIn,         // a foe enters
        FoeFired,      // a foe shoots (angle: the shot's direction)
        FoeHit,        // a shot hurts a foe that lives on
        FoeDestroyed,  // a foe is destroyed (points: what it scored)
        PowerUpEnd,    // a power-up runs out
        ChainUp,       // the score multiplier rises (points: the new multiplier)
    };
    static constexpr Type kLastType = ChainUp;
    Type type;
    Vec2 where = Vec2::Zero();
    int size = 0;                // a rock's size (3 large … 1 small), where it matters
    std::uint32_t look = 0;      // the look (Game::looks) of the thing hit, shot or destroyed; 0: none
    double angle = 0;            // its rotation, or the direction a shot or a thrust goes, radians
    Vec2 motion = Vec2::Zero();  // its velocity, units per second
    int points = 0;              // the score it earned
};

// What one kind of thing is drawn with and where its bounds came from, as logical asset paths. Each
// object of the game's world names its look by index in userData (Game::lookOf).
struct Look {
    std::string sprite;  // empty: not drawn as a sprite
    std::string bounds;  // empty: inline bounds, or none
};

// One kind of thing the game spawns: its look and its bounds.
struct Prototype {
    std::uint32_t look = 0;  // index in the game's looks
    BoundsPtr bounds;
};

// The demo game's rules: a ship in a cave that is a container, tumbling rocks that bounce and split,
// bullets and pickups as ghosts, and comets that ignore the cave wall. A scene's "game" block
// (SceneRules) varies them: an open field whose edges wrap instead of a cave, fast bullets. It knows nothing
// of windows, input devices or drawing: one tick takes the player's Actions and advances everything by 1/60
// s.
//
// Why so strict? Replays and headless tests must reproduce a game exactly. All randomness comes
// from the seeded Rng, objects are visited in creation order, and the only input is Actions.
// The threads a game's world steps on: WorldDef's workers, tasks and parallelMin. A game plays the
// same, to the bit, on any of them.
struct StepThreads {
    std::uint32_t workers = 1;
    TaskSystem* tasks = nullptr;  // when set, it is used and `workers` is not
    std::uint32_t parallelMin = WorldDef::kDefaultParallelMin;
};

// A game's whole state between ticks: its world's snapshot and the game's own part (score, lives,
// waves, timers, the Rng, the kinds table, the last tick's events), in the same versioned,
// checksummed layout (snapshot_bytes.h). What a game is made from (scene path, seed, tuning,
// prototypes) is not in it: a snapshot is restored into a Game created from the same Config.
struct GameSnapshot {
    WorldSnapshot world;
    std::vector<std::uint8_t> bytes;

    std::size_t heldBytes() const { return world.heldBytes() + bytes.size(); }
};

inline constexpr std::uint32_t kGameSnapshotVersion = 4;  // 4: rules 3's foes, power-ups, multiplier

class Game {
  public:
    struct Config {
        std::string scene = "scenes/cave.json";  // logical path (or absolute)
        FileReader reader;                       // how to read scenes and bounds (the asset overlay)
        std::uint64_t seed = 1;
        Tuning tuning;
        StepThreads threads;
        int rules = kRulesVersion;  // the rules to play by, 1 … kRulesVersion (a replay's own)
        int speed = kMaxGameSpeed;  // the game-speed assist, kMinGameSpeed … kMaxGameSpeed percent
    };

    static Result<Game> create(const Config& config);

    // Advances the game by one fixed step.
    void tick(Actions actions);

    const World& world() const { return world_; }
    World& world() { return world_; }
    const Tuning& tuning() const { return tuning_; }
    const SceneRules& rules() const { return rules_; }  // the scene's "game" block
    double bulletSpeed() const { return rules_.bulletSpeed.value_or(tuning_.bulletSpeed); }
    const std::vector<GameEvent>& events() const { return events_; }  // of the last tick

    int score() const { return score_; }
    int lives() const { return lives_; }
    int wave() const { return wave_; }
    std::uint64_t tickCount() const { return ticks_; }
    bool over() const { return over_; }
    int rulesVersion() const { return rulesVersion_; }
    int speed() const { return speed_; }
    // Ticks left of the hit-stop under way (0: the game moves); the game holds still while it lasts.
    int hitStop() const { return hitStop_; }
    const std::string& scenePath() const { return scenePath_; }
    std::uint64_t seed() const { return seed_; }
    const Rng& rng() const { return rng_; }

    // The game's object kinds, for drawing.
    Kind kindOf(ObjectId id) const;
    int rockSize(ObjectId id) const;  // 3 large, 2 medium, 1 small; 0 if not a rock
    PickupKind pickupKind(ObjectId id) const;
    ObjectId shipId() const { return ship_; }  // 0 while the ship is waiting to respawn
    bool shipProtected() const { return shield_ > 0 || invulnerable_ > 0 || barrier_ > 0; }
    double shieldLeft() const { return shield_; }
    // Rules 3, in a scene that calls for foes or power-ups (arcade()): the foe an object is, the
    // seconds left of each power-up (0: off; Shield and Life: 0), and the score multiplier with the
    // seconds left before it drops a step.
    bool arcade() const { return arcade_; }
    FoeKind foeKind(ObjectId id) const;
    double powerUpLeft(PickupKind kind) const;
    int multiplier() const { return multiplier_; }
    double chainLeft() const { return chainTimer_; }
    // Between ticks, in an arcade game: brings a foe in now, as a wave would (its id), and gives the
    // ship a pickup's effect now, as touching one would. For scripted tests and practice: a replay
    // records no such call, so a game that made one is not reproduced by its inputs.
    ObjectId bringFoe(FoeKind kind);
    void give(PickupKind kind) { takePickup(kind); }
    // How an object of this game's world looks (its userData read back); the empty look for an
    // object the game did not make.
    const Look& lookOf(const GameObject& object) const;
    const std::string& shipSprite() const { return looks_[ship_proto_.look].sprite; }
    // A look by its index (GameEvent::look); the empty look for an index the game did not make.
    const Look& look(std::uint32_t index) const { return index < looks_.size() ? looks_[index] : looks_[0]; }

    // The logical paths of the bounds files and sprite images the game uses (its prototypes and
    // its objects), sorted, each once. Objects with inline bounds name no file.
    std::vector<std::string> boundsPaths() const;
    std::vector<std::string> spritePaths() const;
    // Between ticks: gives every object and prototype that uses bounds file `logical` the radii
    // `bounds`, so objects spawned later get them too; returns how many objects changed. Counts an
    // edit (see boundsEdits), because the game's future no longer follows from seed and inputs.
    std::size_t replaceBounds(const std::string& logical, BoundsPtr bounds);
    // How many times bounds were replaced while the game ran (hot reload). A game with edits is
    // modified: a replay of it cannot reproduce it, and hash() says so by including the count.
    std::uint32_t boundsEdits() const { return boundsEdits_; }
    bool modified() const { return boundsEdits_ > 0; }

    // Saves the state into `out`, reusing its memory (game_snapshot.cpp).
    void save(GameSnapshot& out) const;
    // Restores the state saved in `snapshot`: afterwards hash() is the one at the save and ticking on
    // gives the same bits. On a damaged snapshot, returns the error and leaves the game as it was;
    // nothing on success.
    std::optional<Error> restore(const GameSnapshot& snapshot);

    // A hash of everything that decides the future: every object's transform, motion and flags
    // (World::hash) plus score, lives, wave, timers, the kinds table and the Rng state.
    std::uint64_t hash() const;

  private:
    struct Entity {
        Kind kind = Kind::Scenery;
        int size = 0;  // rocks
        PickupKind pickup = PickupKind::Shield;
        double life = 0.0;  // bullets, pickups, comets, foes and their shots: seconds left
        // Foes (rules 3):
        FoeKind foe = FoeKind::Saucer;
        int hits = 0;          // hits it takes yet
        double timer = 0.0;    // seconds to its next shot
        double heading = 0.0;  // a saucer's course; a hunter's angle round the arena, radians
        double turn = 0.0;     // seconds to a saucer's next turn; a hunter's crawl, +1 or -1
    };

    Game(const Config& config, SceneRules rules, World world);
    bool loadPrototypes(const FileReader& reader, Error& error);
    // The index of `look` in looks_, added if new.
    std::uint32_t lookFor(const Look& look);
    ObjectId spawn(const std::string& base, const Prototype& proto, const Vec2& position, double rotation,
                   const Vec2& velocity, double spin, ObjectFlags flags, Entity entity, double damping = 0.0);
    void despawn(ObjectId id);
    // Every prototype of `game`, as pointers to const when the game is const.
    template <class G>
    static auto allPrototypes(G& game);
    void steerShip(Actions actions);
    void fire();
    void startWave();
    void spawnShip();
    void spawnComet();
    // Splits or destroys `rock`; a kill by the player (not a comet) counts toward the multiplier.
    void splitRock(ObjectId rock, const Vec2& hitVelocity, bool byPlayer = true);
    // Rules 3, game_foes.cpp: foes and their shots.
    bool loadArcadePrototypes(const FileReader& reader, Error& error);
    void steerFoes(double dt);
    // Brings the foes a wave calls for, while its rocks last (waveUnderWay).
    void scheduleFoes(double dt, bool waveUnderWay);
    void ageChain(double dt);
    void spawnFoe(FoeKind kind);
    void foeFire(ObjectId foe, Entity& entity, const Vec2& from, double angle);
    // A shot or the barrier hits foe `id`; returns whether it was destroyed.
    bool hitFoe(ObjectId id, const Vec2& hitVelocity, int damage);
    // Rules 3, game_power_ups.cpp: what a broken rock or foe drops, taking a pickup, the timers.
    void dropPickup(const Vec2& at, double foeChance);
    void takePickup(PickupKind kind);
    void agePowerUps(double dt);
    // Rules 3: the score multiplier grows with each kill that follows one soon, more for a kill
    // close to the ship; drops a step when the chain lapses, and goes back to 1 with a life.
    void chainKill(const Vec2& at);
    void handleCollisions();
    void ageThings();
    void wrapEdges();
    // Adds `points` (times the multiplier in an arcade game) and returns what was added.
    int addScore(int points);
    // Starts a hit-stop of `ticks` (under rules 2 and later; a longer one under way is kept).
    void holdStill(int ticks);
    // The seconds one tick advances the game: 1/tickRate, times the speed assist.
    double stepSeconds() const { return 1.0 / tuning_.tickRate * speedScale_; }
    Vec2 randomPointInArena(double margin);
    double arenaRadiusToward(const Vec2& dir) const;

    Tuning tuning_;
    SceneRules rules_;
    World world_;
    Rng rng_;
    std::uint64_t seed_ = 1;
    std::string scenePath_;
    std::map<ObjectId, Entity> entities_;
    std::vector<GameEvent> events_;
    static constexpr int kRockVariants = 3;  // rock-<size>-1..3
    std::vector<Prototype> rocks_[4];        // by size 1..3
    Prototype ship_proto_, bullet_, comet_, pickups_[5];
    Prototype foes_[kFoeKindCount], foeShot_;  // loaded only in an arcade game
    // Every look, made at creation and never changed after (so not in a snapshot); 0 is the empty one.
    std::vector<Look> looks_{Look{}};

    ObjectId arena_ = 0;
    ObjectId ship_ = 0;
    Vec2 arenaCentre_ = Vec2::Zero();
    Vec2 shipStart_ = Vec2::Zero();
    std::uint64_t ticks_ = 0;
    std::uint64_t serial_ = 0;  // for unique object names
    std::uint32_t boundsEdits_ = 0;
    int score_ = 0;
    int nextExtraLife_ = 0;
    int lives_ = 0;
    int wave_ = 0;
    double fireCooldown_ = 0;
    double respawnTimer_ = 0;
    double invulnerable_ = 0;
    double shield_ = 0;
    double waveTimer_ = 0;
    double cometTimer_ = 0;
    int hitStop_ = 0;  // ticks left (rules 2)
    // Rules 3 (arcade_ only):
    bool arcade_ = false;    // rules 3 and the scene calls for foes or power-ups
    int multiplier_ = 1;     // 1 … kMaxMultiplier
    double chainTimer_ = 0;  // seconds before the multiplier drops a step
    double foeTimer_ = 0;    // seconds to the next foe
    double spread_ = 0;      // seconds left of each power-up
    double rapid_ = 0;
    double barrier_ = 0;
    bool over_ = false;
    int rulesVersion_ = kRulesVersion;
    int speed_ = kMaxGameSpeed;
    double speedScale_ = 1.0;  // speed_ / 100: exactly 1 at full speed, so those games keep their bits
};

}  // namespace polar::game
