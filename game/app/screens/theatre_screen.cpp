#include "app/screens/theatre_screen.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <utility>

#include "app/hud/overlays.h"
#include "app/screens/session.h"
#include "app/screens/widgets/button_row.h"
#include "app/screens/widgets/screen_style.h"
#include "app/screens/widgets/seek_bar.h"
#include "app/theatre/replay_playback.h"
#include "polar/render/text.h"

namespace polar::game {
namespace {

using platform::GamepadButton;
using platform::Key;

constexpr double kSpeeds[] = {0.25, 0.5, 1, 2, 4, 8};
constexpr int kNormalSpeed = 2;
constexpr int kFastest = 5;
// How much of the replay is read ahead each frame (not each tick: a slow frame must not read more)
// before watching starts. In a window, what fits in 6 ms, so the frame keeps its 60 a second on a
// slow device too (here about 1000 ticks natively and 400 in chromium: a 10-minute replay is read in
// about a second here); under a script, where a frame is one tick by design, a fixed 600 ticks, so
// the frames a script sees do not depend on the machine.
constexpr double kReadMsPerFrame = 6;
constexpr std::uint64_t kReadTicksPerScriptFrame = 600;
constexpr std::uint64_t kReadClockEvery = 50;  // ticks between looks at the clock
constexpr int kBarLines = 2;
constexpr int kControls = ButtonRow::kHeight + 2 + SeekBar::kHeight;

// What the theatre's buttons, keys and pad buttons ask for.
enum class Verb {
    None,
    Restart,
    PreviousMarker,
    Back5s,
    StepBack,
    PlayPause,
    Step,
    Ahead5s,
    NextMarker,
    Slower,
    Faster,
    Leave,
    End,
    Hide
};
constexpr Verb kButtons[] = {Verb::Restart,   Verb::PreviousMarker, Verb::Back5s,  Verb::StepBack,
                             Verb::PlayPause, Verb::Step,           Verb::Ahead5s, Verb::NextMarker,
                             Verb::Slower,    Verb::Faster,         Verb::Leave};

const char* buttonLabel(Verb verb, bool paused) {
    switch (verb) {
        case Verb::Restart:
            return "RESTART";
        case Verb::PreviousMarker:
            return "< MARK";
        case Verb::Back5s:
            return "-5 S";
        case Verb::StepBack:
            return "< TICK";
        case Verb::PlayPause:
            return paused ? "PLAY" : "PAUSE";
        case Verb::Step:
            return "TICK >";
        case Verb::Ahead5s:
            return "+5 S";
        case Verb::NextMarker:
            return "MARK >";
        case Verb::Slower:
            return "SLOWER";
        case Verb::Faster:
            return "FASTER";
        case Verb::Leave:
            return "BACK";
        case Verb::End:
        case Verb::Hide:
        case Verb::None:
            break;
    }
    return "";
}

// The keys and pad buttons only the theatre reads (the rest come as menu commands).
Verb rawVerb(const platform::Event& event) {
    if (const auto* press = std::get_if<platform::KeyPressed>(&event)) {
        switch (press->key) {
            case Key::Comma:
                return Verb::StepBack;
            case Key::Period:
                return Verb::Step;
            case Key::PageUp:
                return Verb::PreviousMarker;
            case Key::PageDown:
                return Verb::NextMarker;
            case Key::Home:
                return Verb::Restart;
            case Key::End:
                return Verb::End;
            case Key::H:
                return Verb::Hide;
            default:
                return Verb::None;
        }
    }
    if (const auto* button = std::get_if<platform::GamepadButtonPressed>(&event)) {
        switch (button->button) {
            case GamepadButton::LeftShoulder:
                return Verb::PreviousMarker;
            case GamepadButton::RightShoulder:
                return Verb::NextMarker;
            case GamepadButton::X:
                return Verb::StepBack;
            case GamepadButton::Y:
                return Verb::Step;
            default:
                return Verb::None;
        }
    }
    return Verb::None;
}

// "1:23.4": ticks as minutes, seconds and tenths.
std::string clock(std::uint64_t ticks, double tickRate) {
    const auto tenths = static_cast<unsigned long long>(static_cast<double>(ticks) * 10 / tickRate);
    char text[32];
    std::snprintf(text, sizeof text, "%llu:%02llu.%llu", tenths / 600, tenths / 10 % 60, tenths % 10);
    return text;
}

class TheatreScreen : public Screen {
  public:
    TheatreScreen(std::unique_ptr<Playback> play, bool standalone, std::uint64_t startTick)
        : play_(std::move(play)), standalone_(standalone), startTick_(startTick) {}

    const char* name() const override { return "replay"; }

    Next update(Session& session, const Input::Commands& commands) override {
        layOut(session);
        if (commands.back || stopped_) return leave(session);
        if (reading_) {  // a slice a frame, however many ticks a slow frame is due
            read(session);
            return stopped_ ? leave(session) : Next::stay();
        }
        std::vector<Verb> verbs;
        if (commands.pause || commands.confirm) verbs.push_back(Verb::PlayPause);
        if (commands.up) verbs.push_back(Verb::Faster);
        if (commands.down) verbs.push_back(Verb::Slower);
        if (commands.left) verbs.push_back(Verb::Back5s);
        if (commands.right) verbs.push_back(Verb::Ahead5s);
        for (const platform::Event& event : commands.events)
            if (Verb verb = rawVerb(event); verb != Verb::None) verbs.push_back(verb);
        // The wheel steps a tick a notch, forward when rolled away from the player.
        for (int notch = 0; notch < static_cast<int>(std::abs(commands.wheel)); ++notch)
            verbs.push_back(commands.wheel > 0 ? Verb::Step : Verb::StepBack);

        bool released = false;
        for (const platform::Event& event : commands.events)
            if (const auto* up = std::get_if<platform::MouseButtonReleased>(&event))
                released = released || up->button == platform::MouseButton::Left;
        const bool onBar = commands.click && bar_.contains(*commands.click);
        if (std::optional<std::size_t> pressed = buttons_.update(commands.pointer, commands.click))
            verbs.push_back(kButtons[*pressed]);
        else if (commands.click && !onBar)
            verbs.push_back(Verb::PlayPause);  // a click on the picture
        const std::optional<std::uint64_t> scrub =
            seekBar_.update(commands.pointer, commands.click, released, play_->markers().all());

        for (Verb verb : verbs)
            if (Verb::Leave == verb || !apply(session, verb)) return leave(session);
        if (scrub && !goTo(session, *scrub)) return leave(session);
        return Next::stay();
    }

    void tick(Session& session) override {
        if (reading_) return;
        const double tickSeconds = 1.0 / play_->replay().header.tuning.tickRate;
        if (!paused_ && !seekBar_.dragging()) accumulator_ += kSpeeds[speed_] / 60.0;
        while (accumulator_ >= tickSeconds && !play_->player().done() && !stopped_) {
            accumulator_ -= tickSeconds;
            if (!play_->tick(stopAtDesync(session))) stopped_ = true;
        }
        if (play_->player().done()) accumulator_ = 0;
    }

    const Game* shownGame(const Session&) const override {
        return reading_ ? nullptr : &play_->player().game();
    }

    void draw(Session& session, render::Canvas& canvas, double) override {
        if (reading_) {
            canvas.clear(render::Color{8, 10, 22, 255});
            char line[64];
            std::snprintf(line, sizeof line, "READING THE REPLAY  %llu%%",
                          static_cast<unsigned long long>(100 * play_->tickNow() /
                                                          std::max<std::uint64_t>(1, total())));
            drawCentredText(canvas, line, 150, 2, kTextColor);
            return;
        }
        const double tickSeconds = 1.0 / play_->replay().header.tuning.tickRate;
        const bool still = paused_ || seekBar_.dragging() || play_->player().done();
        const double alpha = still ? 1.0 : std::min(1.0, accumulator_ / tickSeconds);
        const auto drawStart = std::chrono::steady_clock::now();
        play_->draw(canvas, session.context.sprites, session.context.pool, alpha, session.debug);
        if (std::exchange(timeNextDraw_, false))  // the frame after a seek: reported, never used
            session.lastSeek.drawingMs =
                std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - drawStart)
                    .count();
        if (play_->desync()) {
            const Desync& desync = *play_->desync();
            char line[80];
            std::snprintf(line, sizeof line, "%s %s TICK %llu",
                          desync.kind == Desync::Kind::kGame    ? "DESYNC"
                          : desync.kind == Desync::Kind::kTrace ? "DAMAGED TRACE"
                                                                : "DAMAGED CHECKPOINT",
                          desync.kind == Desync::Kind::kTrace ? "AT" : "AFTER",
                          static_cast<unsigned long long>(desync.firstTick));
            drawCentredText(canvas, line, 40, 2, kWarnColor);
        }
        if (play_->player().done() && !hidden_) {
            drawCentredText(canvas, "END OF REPLAY", 150, 3, kGold);
            if (play_->incomplete())
                drawCentredText(canvas, "INCOMPLETE: THE RECORDING WAS INTERRUPTED HERE", 185, 1, kWarnColor);
        }
    }

    std::vector<OverlayLine> bar(const Session&) const override {
        if (hidden_) return {};
        const double rate = play_->replay().header.tuning.tickRate;
        const std::uint64_t now = reading_ ? startTick_ : play_->tickNow();
        char status[200];
        std::snprintf(status, sizeof status, "%s / %s   TICK %llu / %llu   x%g%s%s", clock(now, rate).c_str(),
                      clock(total(), rate).c_str(), static_cast<unsigned long long>(now),
                      static_cast<unsigned long long>(total()), kSpeeds[speed_],
                      reading_  ? "   READING"
                      : paused_ ? "   PAUSED"
                                : "",
                      play_->incomplete() ? "   INCOMPLETE" : "");
        std::string line = status;
        // The marker under the pointer; else the one PgUp or PgDn reached, for three seconds of play.
        std::optional<ReplayMarker> marker = seekBar_.hovered();
        if (!marker && reached_ && now >= reached_->tick &&
            now < reached_->tick + static_cast<std::uint64_t>(3 * rate))
            marker = reached_;
        if (marker) line += "   " + describe(*marker) + " AT " + clock(marker->tick, rate);
        return {{line, render::Color{200, 210, 255, 255}},
                {std::string("SPACE PLAY  LEFT RIGHT 5 S  , . TICK  PGUP PGDN MARK  UP DOWN SPEED  HOME END  "
                             "H HIDES  ESC ") +
                     (standalone_ ? "QUIT" : "BACK"),
                 kDimColor}};
    }

    int barControls() const override { return hidden_ ? 0 : kControls; }

    void drawBarControls(const Session&, render::Canvas& canvas, const PixelRect&) const override {
        buttons_.draw(canvas);
        seekBar_.draw(canvas, reading_ ? startTick_ : play_->tickNow(), play_->markers().seen(),
                      play_->markers().all());
    }

  private:
    std::uint64_t total() const { return play_->player().totalTicks(); }
    bool stopAtDesync(const Session& session) const { return standalone_ && session.context.options.verify; }

    // The buttons and the seek bar, where the overlay layout puts the bar this frame.
    void layOut(const Session& session) {
        if (hidden_) {  // no bar: a click anywhere plays or pauses
            bar_ = {};
            buttons_.layOut({}, 0, 0);
            seekBar_.layOut({}, total());
            return;
        }
        const render::Canvas& canvas = session.context.canvas;
        bar_ = barBox(canvas.width(), canvas.height(), kBarLines, kControls);
        const PixelRect controls = barControlsRect(bar_, kControls);
        std::vector<std::string> labels;
        for (Verb verb : kButtons) labels.push_back(buttonLabel(verb, paused_));
        buttons_.layOut(std::move(labels), controls.x + controls.width / 2, controls.y);
        seekBar_.layOut({controls.x, controls.y + ButtonRow::kHeight + 2, controls.width, SeekBar::kHeight},
                        total());
    }

    // Reads the replay ahead, a slice a frame: every tick is played once, so its keyframes and its
    // markers are known before watching starts; then back to the start (or to --seek's tick).
    void read(Session& session) {
        const auto start = std::chrono::steady_clock::now();
        auto sliceDone = [&](std::uint64_t ticks) {
            if (!session.window) return ticks >= kReadTicksPerScriptFrame;
            return ticks % kReadClockEvery == 0 &&
                   std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                           .count() >= kReadMsPerFrame;
        };
        for (std::uint64_t i = 0; !play_->player().done() && !(i > 0 && sliceDone(i)); ++i)
            if (!play_->tick(stopAtDesync(session))) {
                stopped_ = true;
                return;
            }
        if (!play_->player().done()) return;
        reading_ = false;
        if (!goTo(session, std::min(startTick_, total()))) stopped_ = true;
    }

    bool goTo(Session& session, std::uint64_t tick) {
        accumulator_ = 0;
        const bool ok = play_->seekTo(std::min(tick, total()), stopAtDesync(session));
        const ReplaySeek::Split& split = play_->lastSeek();
        SeekTiming& timing = session.lastSeek;
        ++timing.seeks;
        timing.ticks = split.ticks;
        timing.restoreMs = split.restoreMs;
        timing.steppingMs = split.steppingMs;
        timing.drawingMs = 0;
        timeNextDraw_ = true;
        return ok;
    }

    // Does what `verb` asks; false when a desync under --verify stops the replay.
    bool apply(Session& session, Verb verb) {
        const std::uint64_t now = play_->tickNow();
        const auto fiveSeconds = static_cast<std::uint64_t>(5 * play_->replay().header.tuning.tickRate);
        switch (verb) {
            case Verb::PlayPause:
                if (play_->player().done()) return restart(session);
                paused_ = !paused_;
                return true;
            case Verb::Faster:
                speed_ = std::min(speed_ + 1, kFastest);
                return true;
            case Verb::Slower:
                speed_ = std::max(speed_ - 1, 0);
                return true;
            case Verb::Back5s:
                return goTo(session, now > fiveSeconds ? now - fiveSeconds : 0);
            case Verb::Ahead5s:
                return goTo(session, now + fiveSeconds);
            case Verb::Step:
                paused_ = true;
                accumulator_ = 0;
                return play_->player().done() || play_->tick(stopAtDesync(session));
            case Verb::StepBack:
                paused_ = true;
                return now == 0 || goTo(session, now - 1);
            case Verb::PreviousMarker:
                if (std::optional<ReplayMarker> marker = play_->markers().previous(now)) {
                    reached_ = marker;
                    return goTo(session, marker->tick);
                }
                return true;
            case Verb::NextMarker:
                if (std::optional<ReplayMarker> marker = play_->markers().next(now)) {
                    reached_ = marker;
                    return goTo(session, marker->tick);
                }
                return true;
            case Verb::Restart:
                return restart(session);
            case Verb::End:
                return goTo(session, total());
            case Verb::Hide:
                hidden_ = !hidden_;
                return true;
            case Verb::Leave:
            case Verb::None:
                return true;
        }
        return true;
    }

    bool restart(Session& session) {
        paused_ = false;
        return goTo(session, 0);
    }

    Next leave(Session& session) {
        if (standalone_)
            return Next::exit(
                play_->finish(session.context.options.verify, session.context.options.allowIncomplete));
        return Next::back();
    }

    std::unique_ptr<Playback> play_;
    bool standalone_;
    std::uint64_t startTick_;
    bool reading_ = true, paused_ = false, stopped_ = false;
    bool hidden_ = false;
    bool timeNextDraw_ = false;  // the next frame is the first after a seek: its drawing is timed  // H: the
                                 // bar and the words over the picture are hidden (a clean view)
    int speed_ = kNormalSpeed;
    double accumulator_ = 0;
    std::optional<ReplayMarker> reached_;  // the marker PgUp or PgDn went to last (its label shows)
    PixelRect bar_;
    ButtonRow buttons_;
    SeekBar seekBar_;
};

}  // namespace

std::unique_ptr<Screen> makeTheatreScreen(Session& session, const std::string& path, bool standalone) {
    Result<std::unique_ptr<Playback>> play =
        Playback::open(path, session.context.assets, session.context.pool, &session.scores);
    if (!play) {
        session.notice.tell(play.error().message());
        return nullptr;
    }
    // --replay FILE --seek TICK: watching starts there, once the replay is read.
    const std::uint64_t start = standalone && session.context.options.seek >= 0
                                    ? static_cast<std::uint64_t>(session.context.options.seek)
                                    : 0;
    return std::make_unique<TheatreScreen>(std::move(*play), standalone, start);
}

}  // namespace polar::game
