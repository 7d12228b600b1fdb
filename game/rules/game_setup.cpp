// The game's set-up: a scene file read once, its objects placed, the arena and the ship found, the
// first wave started (game.h).
#include "rules/game.h"

namespace polar::game {

Result<Game> Game::create(const Config& config) {
    if (config.rules < 1 || config.rules > kRulesVersion)
        return Error{config.scene, 0, 0, "rules version " + std::to_string(config.rules) + " is unknown",
                     "rules 1 to " + std::to_string(kRulesVersion) + "; a newer game plays it"};
    if (config.speed < kMinGameSpeed || config.speed > kMaxGameSpeed)
        return Error{config.scene, 0, 0, "a game speed of " + std::to_string(config.speed) + " %",
                     "a game speed of " + std::to_string(kMinGameSpeed) + " to " +
                         std::to_string(kMaxGameSpeed) + " %"};
    // One read of the scene file for the engine's part and the game's: a replay stamps each read.
    std::optional<SourceFile> file = config.reader(config.scene);
    if (!file)
        return Error{config.scene, 0, 0, "cannot read the scene file",
                     "an existing, readable scene .json file"};
    Result<SceneDef> scene = parseScene(*file, config.reader);
    if (!scene) return scene.error();
    Result<SceneRules> rules = parseSceneRules(*file);
    if (!rules) return rules.error();
    if (rules->fastBullets && !(scene->world.effects & kEffectCcd))
        return Error{scene->path, 0, 0, "the game's \"bullets\": \"fast\" needs the effect \"ccd\"",
                     "\"ccd\" in \"effects\", or plain bullets"};
    bool wrap = rules->edges == SceneRules::Edges::Wrap;
    scene->world.workers = config.threads.workers;
    scene->world.tasks = config.threads.tasks;
    scene->world.parallelMin = config.threads.parallelMin;
    Game game(config, *rules, World(scene->world));
    Error error;
    if (!game.loadPrototypes(config.reader, error)) return error;
    // The scene's objects, in file order, each pointing at its look through userData.
    for (SceneObject& object : scene->objects) {
        object.userData = game.lookFor(Look{object.sprite, object.boundsPath});
        game.world_.add(object);
    }

    // The scene gives the arena (its container) and the ship; everything else stays as scenery.
    for (const GameObject& object : game.world_.objects()) {
        Entity entity;
        if (!wrap && object.has(kContainer) && game.arena_ == 0) {
            entity.kind = Kind::Arena;
            game.arena_ = object.id;
            game.arenaCentre_ = object.transform.position();
        } else if (object.name == "ship") {
            entity.kind = Kind::Ship;
            game.ship_ = object.id;
            game.shipStart_ = object.transform.position();
            game.ship_proto_ = Prototype{static_cast<std::uint32_t>(object.userData), object.bounds};
        }
        game.entities_.emplace(object.id, std::move(entity));
    }
    if (wrap) game.arenaCentre_ = game.rules_.field * 0.5;
    if (game.arena_ == 0 && !wrap)
        return Error{scene->path, 0, 0, "the scene has no container object for the arena",
                     "one object flagged \"container\" (the cave)"};
    if (game.ship_ == 0)
        return Error{scene->path, 0, 0, "the scene has no object named \"ship\"", "an object named \"ship\""};
    // Rules 3's foes and power-ups, where the scene calls for them; their looks come after the
    // scene's, so every other look keeps its index.
    game.arcade_ = config.rules >= 3 && (rules->foes != 0 || rules->powerUps != 0);
    if (game.arcade_ && !game.loadArcadePrototypes(config.reader, error)) return error;
    game.invulnerable_ = game.tuning_.invulnerableAfterRespawn;
    game.startWave();
    return game;
}

Game::Game(const Config& config, SceneRules rules, World world)
    : tuning_(config.tuning),
      rules_(rules),
      world_(std::move(world)),
      rng_(config.seed),
      seed_(config.seed),
      scenePath_(config.scene),
      nextExtraLife_(config.tuning.extraLifeEvery),
      lives_(config.tuning.startLives),
      rulesVersion_(config.rules),
      speed_(config.speed),
      speedScale_(config.speed == kMaxGameSpeed ? 1.0 : config.speed / 100.0) {}

}  // namespace polar::game
