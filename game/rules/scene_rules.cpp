#include "rules/scene_rules.h"

#include "polar/json_doc.h"

namespace polar::game {

namespace {
constexpr const char* kBackdropNames[kBackdropCount] = {"plain", "starfield", "fog", "storm", "cavern"};
}  // namespace

const char* backdropName(Backdrop backdrop) {
    return kBackdropNames[static_cast<int>(backdrop)];
}

std::optional<Backdrop> backdropFromName(const std::string& name) {
    for (int i = 0; i < kBackdropCount; ++i)
        if (name == kBackdropNames[i]) return static_cast<Backdrop>(i);
    return std::nullopt;
}

std::string backdropNames() {
    std::string names;
    for (int i = 0; i < kBackdropCount; ++i)
        names += std::string(i == 0                    ? ""
                             : i + 1 == kBackdropCount ? " or "
                                                       : ", ") +
                 "\"" + kBackdropNames[i] + "\"";
    return names;
}

Result<SceneRules> parseSceneRules(const SourceFile& file) {
    Result<JsonDoc> doc = JsonDoc::parse(file);
    if (!doc) return doc.error();
    return catchLoadFailure<SceneRules>([&] {
        SceneRules rules;
        std::optional<JsonNode> game = JsonNode::root(*doc).find("game");
        if (!game) return rules;
        if (!game->isObject()) game->fail("\"game\" is " + game->kindName(), "an object of the game's rules");
        game->allowKeys({"edges", "field", "bullets", "bullet_speed", "bullet_life", "backdrop"});
        if (auto edges = game->find("edges")) {
            std::string name = edges->string("\"container\" or \"wrap\"");
            if (name == "wrap")
                rules.edges = SceneRules::Edges::Wrap;
            else if (name != "container")
                edges->fail("unknown edges \"" + name + "\"", "\"container\" or \"wrap\"");
        }
        if (auto field = game->find("field")) {
            rules.field = field->vec2("the field's size [width, height]");
            if (rules.field.x() < 64 || rules.field.y() < 64 || rules.field.x() > 4096 ||
                rules.field.y() > 4096)
                field->fail("a field of " + std::to_string(rules.field.x()) + " by " +
                                std::to_string(rules.field.y()) + " is out of range",
                            "a width and height from 64 to 4096");
        }
        if (auto bullets = game->find("bullets")) {
            std::string name = bullets->string("\"plain\" or \"fast\"");
            if (name == "fast")
                rules.fastBullets = true;
            else if (name != "plain")
                bullets->fail("unknown bullets \"" + name + "\"", "\"plain\" or \"fast\"");
        }
        auto positive = [](const JsonNode& node, double most, const char* expected) {
            double value = node.number(expected);
            if (value <= 0 || value > most) node.fail(std::to_string(value) + " is out of range", expected);
            return value;
        };
        if (auto speed = game->find("bullet_speed"))
            rules.bulletSpeed =
                positive(*speed, 5000, "a bullet speed above 0, at most 5000 units per second");
        if (auto life = game->find("bullet_life"))
            rules.bulletLife = positive(*life, 10, "a bullet life above 0, at most 10 seconds");
        if (auto backdrop = game->find("backdrop")) {
            const std::string expected = "a backdrop: " + backdropNames();
            std::string name = backdrop->string(expected.c_str());
            rules.backdrop = backdropFromName(name);
            if (!rules.backdrop) backdrop->fail("unknown backdrop \"" + name + "\"", expected);
        }
        return rules;
    });
}

}  // namespace polar::game
