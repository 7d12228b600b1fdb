#include "app/screens/scenes_screen.h"

#include <cstdio>
#include <optional>

#include "app/hud/backdrop.h"
#include "app/hud/game_drawing.h"
#include "app/hud/scene_thumbnail.h"
#include "app/input/hints.h"
#include "app/screens/demo_backdrop_screen.h"
#include "app/screens/playing_screen.h"
#include "app/screens/session.h"
#include "app/screens/widgets/menu.h"
#include "app/screens/widgets/screen_style.h"
#include "files/high_scores.h"
#include "files/scene_list.h"
#include "polar/render/sprite.h"
#include "polar/render/text.h"
#include "polar/scene_file.h"
#include "rules/scene_rules.h"

namespace polar::game {
namespace {

// What the screen shows of a scene beside the list: its picture, what happens there, its best score.
struct SceneCard {
    std::optional<render::Image> picture;  // none when the scene cannot be drawn (its error is told)
    std::string about;                     // what happens there, in a player's words
    int best = 0;                          // the best score of its table for the mods in use
};

// What happens in a scene, said as a player would, from what its file asks of the engine and the
// game (the engine's names for its effects are the debug panel's, F1).
std::string aboutScene(const SceneDef& scene, const SceneRules& rules, double tuningBulletSpeed,
                       const std::string& look) {
    std::string about = look.empty() ? "" : look + " ";
    const Effects effects = scene.world.effects;
    if (rules.edges == SceneRules::Edges::Wrap)
        about += "NO WALLS: FLY OFF ONE EDGE AND YOU COME BACK ON THE OTHER.";
    else if (effects & kEffectContainers)
        about += "A CAVE HOLDS YOU IN: ROCKS AND SHIP BOUNCE OFF ITS WALL.";
    else
        about += "THE WALLS DO NOT STOP A THING.";
    const bool foes = rules.foes || rules.powerUps;  // rules 3's: their words take the room
    if (effects & kEffectResponse)
        about += foes ? "" : " ROCKS KNOCK INTO EACH OTHER AND SHOVE YOUR SHIP.";
    else
        about += " ROCKS DRIFT THROUGH EACH OTHER LIKE GHOSTS, BUT ONE TOUCH STILL COSTS A LIFE.";
    const double speed = rules.bulletSpeed.value_or(tuningBulletSpeed);
    if (speed > 2 * tuningBulletSpeed)
        about += " YOUR SHOTS ARE LIGHTNING FAST" + std::string(rules.bulletLife ? " BUT SHORT." : ".");
    else if (rules.bulletLife)
        about += " YOUR SHOTS FADE SOON.";
    // Rules 3's foes and power-ups, in the order the file calls for them.
    for (Foe foe : rules.foeOrder) {
        switch (foe) {
            case Foe::Saucer:
                about += " SAUCERS HUNT YOU; SMALL ONES AIM.";
                break;
            case Foe::Mine:
                about += " MINES BURST INTO HOMING SHARDS.";
                break;
            case Foe::Hunter:
                about += " HUNTERS CRAWL THE EDGE AND SHOOT.";
                break;
        }
    }
    if (rules.powerUps) {
        std::vector<const char*> names;
        if (rules.callsFor(PowerUp::Spread)) names.push_back("SPREAD");
        if (rules.callsFor(PowerUp::Rapid)) names.push_back("RAPID FIRE");
        if (rules.callsFor(PowerUp::Barrier)) names.push_back("BARRIERS");
        about += " WRECKS DROP ";
        for (std::size_t i = 0; i < names.size(); ++i)
            about += std::string(i == 0 ? "" : i + 1 == names.size() ? " AND " : ", ") + names[i];
        about += ".";
    }
    return about;
}

SceneCard cardOf(Session& session, const SceneEntry& scene) {
    SceneCard card;
    if (Result<render::Canvas> picture =
            sceneThumbnail(session.context.assets, session.context.sprites, scene.logical))
        card.picture = render::Image::fromCanvas(*picture);
    const FileReader reader = session.context.hotReload.reader();
    if (Result<SceneDef> def = loadScene(scene.logical, reader))
        if (std::optional<SourceFile> file = reader(scene.logical))
            if (Result<SceneRules> rules = parseSceneRules(*file))
                card.about = aboutScene(*def, *rules, Tuning{}.bulletSpeed,
                                        aboutBackdrop(backdropFor(*rules, scene.logical)));
    card.best = session.scores.best({scene.logical, modSetOf(session.context.options.mods)});
    return card;
}

class ScenesScreen : public DemoBackdropScreen {
  public:
    const char* name() const override { return "scenes"; }

    // The scene folders are read when the screen opens, never while it draws.
    void enter(Session& session) override {
        scenes_ = listScenes(session.context.assets);
        std::vector<Menu::Item> items;
        std::size_t current = 0;
        cards_.clear();
        for (std::size_t i = 0; i < scenes_.size(); ++i) {
            const std::string name = upperCase(scenes_[i].name);
            cards_.push_back(cardOf(session, scenes_[i]));
            items.push_back({name, scenes_[i].mod.empty() ? "" : "MOD " + scenes_[i].mod, true});
            if (scenes_[i].logical == session.games.scenePath) current = i;
        }
        menu_ = Menu(std::move(items), Menu::Layout{180, 90, 260, 20, 2, 8});
        menu_.setFocus(current);
    }

    Next update(Session& session, const Input::Commands& commands) override {
        if (commands.back) return Next::back();
        const Menu::Result chosen = menu_.update(commands);
        if (chosen.action != Menu::Action::Activate || scenes_.empty()) return Next::stay();
        const std::string before = session.games.scenePath;
        session.games.scenePath = scenes_[chosen.item].logical;
        if (!session.games.startGame()) {  // the reason is on screen; the old scene stays chosen
            session.games.scenePath = before;
            return Next::stay();
        }
        return Next::replace(makePlayingScreen());
    }

    void draw(Session& session, render::Canvas& canvas, double alpha) override {
        drawDemo(session, canvas, alpha);
        drawBand(canvas, 40, 272);
        drawHeading(canvas, "SCENES", 52);
        menu_.draw(canvas);
        if (menu_.focus() < cards_.size()) drawCard(canvas, cards_[menu_.focus()]);
    }

    std::string helpLine(const Session& session) const override {
        const Device device = session.input.device();
        if (device == Device::Touch) return "TAP A SCENE TO PLAY IT";
        return confirmWord(device) + (device == Device::Keyboard ? " OR CLICK PLAYS   " : " PLAYS   ") +
               backWord(device) + " BACK";
    }

  private:
    // The focused scene's card, right of the list: picture, what happens there (wrapped), best score.
    static void drawCard(render::Canvas& canvas, const SceneCard& card) {
        constexpr int kLeft = 370, kTop = 90, kWidth = 160, kHeight = 90;
        if (card.picture)
            render::drawSprite(canvas, *card.picture, Vec2(kLeft + kWidth / 2.0, kTop + kHeight / 2.0));
        int y = kTop + kHeight + 10;
        std::string line;
        auto flush = [&] {
            render::drawText(canvas, line, kLeft, y, 1, kTextColor);
            y += 12;
            line.clear();
        };
        std::size_t start = 0;
        while (start < card.about.size()) {  // one word at a time, lines of at most 30 letters
            std::size_t end = card.about.find(' ', start);
            if (end == std::string::npos) end = card.about.size();
            const std::string word = card.about.substr(start, end - start);
            if (!line.empty() && line.size() + 1 + word.size() > 30) flush();
            line += (line.empty() ? "" : " ") + word;
            start = end + 1;
        }
        if (!line.empty()) flush();
        char best[48];
        std::snprintf(best, sizeof best, "BEST %d", card.best);
        render::drawText(canvas, best, kLeft, y + 4, 1, kGold);
    }

    std::vector<SceneEntry> scenes_;
    std::vector<SceneCard> cards_;
    Menu menu_;
};

}  // namespace

std::unique_ptr<Screen> makeScenesScreen() {
    return std::make_unique<ScenesScreen>();
}

}  // namespace polar::game
