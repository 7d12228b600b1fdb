#pragma once
#include <string>
#include <vector>

#include "polar/error.h"
#include "polar/world.h"

namespace polar {

// A scene file, loaded and checked:
//   {"format": 1, "effects": ["physics", "collisions", "response"], "restitution": 0.8,
//    "objects": [{"name": "rock-1", "sprite": "../sprites/rock.png", "bounds": "../bounds/rock.bounds.json",
//                 "position": [120, 40], "rotation": 30, "scale": 1.5, "velocity": [10, 0],
//                 "spin": 45, "damping": 0.1, "flags": ["physics", "collisions"]}]}
// Paths are relative to the file that names them; `bounds` may also be an inline bounds object;
// `scale` is a number or [sx, sy]; angles are degrees, spin degrees per second. An optional
// "accuracy" names the narrow phase's level (accuracy.h); without it each bounds file's interpolate
// flag decides. An optional "game" value (any JSON) belongs to the game that plays the scene: the
// engine accepts it and never reads it, so a game keeps its own rules beside the scene's objects.
// One object of a scene: what the world gets, plus the files the scene names for it, which are the
// game's to use (the world never reads them).
struct SceneObject : ObjectDef {
    std::string sprite;      // the sprite image's path, resolved against the scene's; may be empty
    std::string boundsPath;  // the bounds file's path, resolved likewise; empty for inline bounds
};

struct SceneDef {
    std::string path;  // as given to loadScene
    WorldDef world;
    std::vector<SceneObject> objects;  // in file order, which is creation order
};

inline constexpr int kSceneFormat = 1;

// Parses a scene; bounds files it names are read through `reader` and shared between objects.
Result<SceneDef> parseScene(const SourceFile& file, const FileReader& reader);
Result<SceneDef> loadScene(const std::string& path, const FileReader& reader);

// A world holding the scene's objects in file order (their ObjectDef part; userData as set).
World buildWorld(const SceneDef& scene);

}  // namespace polar
