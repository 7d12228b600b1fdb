#include "polar/scene_file.h"

#include <map>

#include "files/bounds_reader.h"
#include "polar/bounds_file.h"
#include "polar/broad_phase.h"
#include "polar/json_doc.h"
#include "polar/json_writer.h"

namespace polar {
namespace {

// Which effect a flag needs, if any.
std::optional<Effect> effectNeededBy(ObjectFlag flag) {
    switch (flag) {
        case kPhysics:
            return kEffectPhysics;
        case kCollisions:
            return kEffectCollisions;
        case kContainer:
            return kEffectContainers;
        case kFast:
            return kEffectCcd;
        default:
            return std::nullopt;
    }
}

std::string inQuotes(const std::string& s) {
    return "\"" + s + "\"";
}

class SceneReader {
  public:
    SceneReader(const JsonDoc& doc, const FileReader& reader) : doc_(doc), reader_(reader) {}

    SceneDef read() {
        JsonNode root = JsonNode::root(doc_);
        // "game" is the game's own block (its rules for this scene); the engine never reads it.
        root.allowKeys({"format", "effects", "broad_phase", "restitution", "objects", "accuracy", "game"});
        JsonNode format = root.require("format", "\"format\": 1 at the top of a scene file");
        int version = format.integer("the format number 1");
        if (version != kSceneFormat)
            format.fail("unsupported format " + std::to_string(version), "\"format\": 1");

        SceneDef scene;
        scene.path = doc_.path();
        if (auto effects = root.find("effects")) scene.world.effects = readEffects(*effects);
        if (auto method = root.find("broad_phase")) {
            std::string name = method->string("a broad phase name");
            std::optional<BroadPhase> known = broadPhaseFromName(name);
            if (!known) method->fail("unknown broad phase " + inQuotes(name), "one of " + broadPhaseList());
            scene.world.broadPhase = *known;
        }
        if (auto restitution = root.find("restitution")) {
            scene.world.restitution = restitution->number("a restitution between 0 and 1");
            if (scene.world.restitution < 0 || scene.world.restitution > 1)
                restitution->fail(
                    "restitution " + jsonNumberText(scene.world.restitution) + " is out of range",
                    "a restitution between 0 and 1");
        }
        if (auto accuracy = root.find("accuracy")) {
            std::string name = accuracy->string("an accuracy level name");
            std::optional<Accuracy> level = accuracyFromName(name);
            if (!level)
                accuracy->fail("unknown accuracy level " + inQuotes(name), "one of " + accuracyNameList());
            scene.world.accuracy = *level;
        }
        std::map<std::string, std::string> names;  // name → pointer of its first use
        if (auto objects = root.find("objects")) {
            for (const JsonNode& node : objects->items("an array of objects")) {
                SceneObject object = readObject(node, scene.world.effects);
                JsonNode name = node.require("name", "a unique, non-empty \"name\"");
                if (!names.emplace(object.name, name.pointer()).second) {
                    int firstLine = doc_.errorAt(names[object.name], "", "").line;
                    name.fail("duplicate object name " + inQuotes(object.name) + " (first used on line " +
                                  std::to_string(firstLine) + ")",
                              "a name no other object has");
                }
                scene.objects.push_back(std::move(object));
            }
        }
        return scene;
    }

  private:
    Effects readEffects(const JsonNode& node) {
        Effects effects = 0;
        std::vector<JsonNode> items = node.items("an array of effect names");
        for (const JsonNode& item : items) {
            std::string name = item.string("an effect name");
            std::optional<Effect> effect = effectFromName(name);
            if (!effect) item.fail("unknown effect " + inQuotes(name), "one of " + effectList());
            effects |= *effect;
        }
        for (const JsonNode& item : items) {
            Effect effect = *effectFromName(item.string(""));
            if ((effect == kEffectResponse || effect == kEffectContainers) && !(effects & kEffectCollisions))
                item.fail(inQuotes(effectName(effect)) +
                              " acts on what detection finds, but \"collisions\" is not listed",
                          "\"collisions\" in \"effects\" too");
            if (effect == kEffectCcd &&
                (effects & (kEffectCollisions | kEffectPhysics)) != (kEffectCollisions | kEffectPhysics))
                item.fail(
                    "\"ccd\" casts the motion \"physics\" integrates against what \"collisions\" detects, "
                    "but the scene does not list both",
                    "\"physics\" and \"collisions\" in \"effects\" too");
        }
        return effects;
    }

    static std::string effectList() {
        std::string list;
        for (Effect e : kAllEffects) list += (list.empty() ? "" : ", ") + inQuotes(effectName(e));
        return list;
    }

    static std::string broadPhaseList() {
        std::string list;
        for (BroadPhase m : kAllBroadPhases) list += (list.empty() ? "" : ", ") + inQuotes(broadPhaseName(m));
        return list;
    }

    static std::string flagList() {
        std::string list;
        for (ObjectFlag f : kAllFlags) list += (list.empty() ? "" : ", ") + inQuotes(flagName(f));
        return list;
    }

    SceneObject readObject(const JsonNode& node, Effects effects) {
        node.allowKeys({"name", "sprite", "bounds", "position", "rotation", "scale", "velocity", "spin",
                        "damping", "flags"});
        SceneObject object;
        JsonNode name = node.require("name", "a unique, non-empty \"name\"");
        object.name = name.string("a unique, non-empty name");
        if (object.name.empty()) name.fail("an empty object name", "a unique, non-empty name");

        if (auto sprite = node.find("sprite"))
            object.sprite = resolveRelative(
                doc_.path(), sprite->string("a path to a sprite image (PNG, GIF, WebP, TGA, …)"));
        if (auto bounds = node.find("bounds")) readObjectBounds(*bounds, object);

        Vec2 position = Vec2::Zero(), scale = Vec2::Ones();
        double rotation = 0.0;
        if (auto p = node.find("position")) position = p->vec2("a position [x, y]");
        if (auto r = node.find("rotation"))
            rotation = degToRad(reduceDegrees(r->number("a rotation in degrees")));
        if (auto s = node.find("scale")) {
            scale = s->isNumber() ? Vec2::Constant(s->number("a scale: a number or [sx, sy]"))
                                  : s->vec2("a scale: a number or [sx, sy]");
        }
        object.transform = Transform(position, rotation, scale);
        if (auto v = node.find("velocity"))
            object.velocity = v->vec2("a velocity [vx, vy] in units per second");
        if (auto s = node.find("spin")) object.spin = degToRad(s->number("a spin in degrees per second"));
        if (auto d = node.find("damping")) {
            object.damping = d->number("a damping factor ≥ 0 per second");
            if (object.damping < 0) d->fail("a negative damping", "a damping factor ≥ 0 per second");
        }
        if (auto flags = node.find("flags")) {
            for (const JsonNode& item : flags->items("an array of flag names")) {
                std::string flagText = item.string("a flag name");
                std::optional<ObjectFlag> flag = flagFromName(flagText);
                if (!flag) item.fail("unknown flag " + inQuotes(flagText), "one of " + flagList());
                std::optional<Effect> needed = effectNeededBy(*flag);
                if (needed && !(effects & *needed))
                    item.fail("flag " + inQuotes(flagText) + " needs the " + inQuotes(effectName(*needed)) +
                                  " effect, which the scene does not list",
                              inQuotes(effectName(*needed)) + " in \"effects\", or no " + inQuotes(flagText) +
                                  " flag");
                object.flags |= *flag;
            }
        }
        return object;
    }

    void readObjectBounds(const JsonNode& node, SceneObject& object) {
        if (node.isObject()) {
            object.bounds = std::make_shared<const Bounds>(buildBounds(readBounds(node, false)));
            return;
        }
        std::string path =
            resolveRelative(doc_.path(), node.string("a bounds file path or an inline bounds object"));
        object.boundsPath = path;
        if (auto cached = boundsByPath_.find(path); cached != boundsByPath_.end()) {
            object.bounds = cached->second;
            return;
        }
        std::optional<SourceFile> file = reader_(path);
        if (!file)
            node.fail("cannot read bounds file " + inQuotes(path),
                      "an existing .bounds.json file, relative to this scene");
        Result<BoundsSpec> spec = parseBounds(*file);
        if (!spec) throw LoadFailure{spec.error()};
        object.bounds = std::make_shared<const Bounds>(buildBounds(*spec));
        boundsByPath_.emplace(path, object.bounds);
    }

    const JsonDoc& doc_;
    const FileReader& reader_;
    std::map<std::string, BoundsPtr> boundsByPath_;
};

}  // namespace

Result<SceneDef> parseScene(const SourceFile& file, const FileReader& reader) {
    Result<JsonDoc> doc = JsonDoc::parse(file);
    if (!doc) return doc.error();
    return catchLoadFailure<SceneDef>([&] { return SceneReader(*doc, reader).read(); });
}

Result<SceneDef> loadScene(const std::string& path, const FileReader& reader) {
    std::optional<SourceFile> file = reader(path);
    if (!file)
        return Error{path, 0, 0, "cannot read the scene file", "an existing, readable scene .json file"};
    return parseScene(*file, reader);
}

World buildWorld(const SceneDef& scene) {
    World world(scene.world);
    for (const ObjectDef& object : scene.objects) world.add(object);
    return world;
}

}  // namespace polar
