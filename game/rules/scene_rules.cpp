#include "rules/scene_rules.h"

#include "polar/json_doc.h"

namespace polar::game {

namespace {
constexpr const char* kBackdropNames[kBackdropCount] = {"plain", "starfield", "fog", "storm", "cavern"};
constexpr const char* kFoeNames[kFoeCount] = {"saucer", "mine", "hunter"};
constexpr const char* kPowerUpNames[kPowerUpCount] = {"spread", "rapid", "barrier"};

// The names quoted and joined for an error message: "a", "b" or "c".
std::string quotedNames(const char* const* names, int count) {
    std::string out;
    for (int i = 0; i < count; ++i)
        out += std::string(i == 0 ? "" : i + 1 == count ? " or " : ", ") + "\"" + names[i] + "\"";
    return out;
}

// A list of names, each one of `names`, each once, as bits; an unknown or repeated name is refused
// at its place.
std::uint8_t readNameSet(const JsonNode& list, const char* const* names, int count, const std::string& what,
                         std::vector<int>* order = nullptr) {
    const std::string expected = "a list of " + what + ": " + quotedNames(names, count);
    std::uint8_t bits = 0;
    for (const JsonNode& item : list.items(expected.c_str())) {
        const std::string name = item.string(expected.c_str());
        int found = -1;
        for (int i = 0; i < count; ++i)
            if (name == names[i]) found = i;
        if (found < 0) item.fail("unknown " + what + " \"" + name + "\"", expected);
        if ((bits >> found) & 1u) item.fail("\"" + name + "\" is listed twice", "each name once");
        bits = static_cast<std::uint8_t>(bits | (1u << found));
        if (order) order->push_back(found);
    }
    return bits;
}
}  // namespace

const char* foeName(Foe foe) {
    return kFoeNames[static_cast<int>(foe)];
}

const char* powerUpName(PowerUp powerUp) {
    return kPowerUpNames[static_cast<int>(powerUp)];
}

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
        game->allowKeys({"edges", "field", "bullets", "bullet_speed", "bullet_life", "backdrop", "accent",
                         "foes", "powerups"});
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
        if (auto accent = game->find("accent")) {
            const char* expected = "an accent colour [red, green, blue], each 0 to 255";
            const std::vector<JsonNode> parts = accent->items(expected);
            if (parts.size() != 3) accent->fail(std::to_string(parts.size()) + " numbers", expected);
            std::array<std::uint8_t, 3> rgb{};
            for (std::size_t i = 0; i < 3; ++i) {
                const JsonNode& part = parts[i];
                const double value = part.number(expected);
                if (!(value >= 0 && value <= 255) || value != static_cast<int>(value))
                    part.fail(std::to_string(value) + " is not a colour level", expected);
                rgb[i] = static_cast<std::uint8_t>(value);
            }
            rules.accent = rgb;
        }
        if (auto foes = game->find("foes")) {
            std::vector<int> order;
            rules.foes = readNameSet(*foes, kFoeNames, kFoeCount, "foes", &order);
            for (int foe : order) rules.foeOrder.push_back(static_cast<Foe>(foe));
        }
        if (auto powerUps = game->find("powerups"))
            rules.powerUps = readNameSet(*powerUps, kPowerUpNames, kPowerUpCount, "powerups");
        return rules;
    });
}

}  // namespace polar::game
