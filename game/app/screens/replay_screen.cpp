#include "app/screens/replay_screen.h"

#include <algorithm>
#include <cstdio>

#include "app/replay_playback.h"
#include "app/screens/screen_style.h"
#include "app/session.h"
#include "polar/render/text.h"

namespace polar::game {
namespace {

constexpr double kSpeeds[] = {0.25, 0.5, 1, 2, 4, 8};
constexpr int kNormalSpeed = 2;
constexpr int kFastest = 5;

class ReplayScreen : public Screen {
  public:
    ReplayScreen(std::unique_ptr<Playback> play, bool standalone)
        : play_(std::move(play)), standalone_(standalone) {}

    const char* name() const override { return "replay"; }

    Next update(Session& session, const Input::Commands& commands) override {
        if (commands.back || stopped_) return leave(session);
        if (commands.pause || commands.confirm || commands.click) paused_ = !paused_;
        if (commands.up) speed_ = std::min(speed_ + 1, kFastest);
        if (commands.down) speed_ = std::max(speed_ - 1, 0);
        if (paused_ && commands.right) stepOnce_ = true;
        if (paused_ && commands.left) stepBack_ = true;
        return Next::stay();
    }

    void tick(Session& session) override {
        const double tickSeconds = 1.0 / play_->replay().header.tuning.tickRate;
        // Back one tick by the keyframes: the state is straight play's at that tick.
        const std::uint64_t now = play_->player().game().tickCount();
        if (stepBack_ && now > 0 && !play_->seekTo(now - 1, standalone_ && session.options.verify))
            stopped_ = true;
        stepBack_ = false;
        if (!paused_) accumulator_ += kSpeeds[speed_] / 60.0;
        while ((accumulator_ >= tickSeconds || stepOnce_) && !play_->player().done() && !stopped_) {
            accumulator_ = std::max(0.0, accumulator_ - tickSeconds);
            stepOnce_ = false;
            if (!play_->tick(standalone_ && session.options.verify)) stopped_ = true;
        }
        if (play_->player().done()) accumulator_ = 0;
    }

    void draw(Session& session, render::Canvas& canvas, double) override {
        const double tickSeconds = 1.0 / play_->replay().header.tuning.tickRate;
        const double alpha =
            paused_ || play_->player().done() ? 1.0 : std::min(1.0, accumulator_ / tickSeconds);
        play_->draw(canvas, session.sprites, session.tasks, alpha, session.debug);
        session.shown = &play_->player().game();
        if (play_->desync()) {
            char line[80];
            std::snprintf(line, sizeof line, "DESYNC AFTER TICK %llu",
                          static_cast<unsigned long long>(play_->desync()->firstTick));
            drawCentredText(canvas, line, 40, 2, kWarnColor);
        }
        if (play_->player().done()) drawCentredText(canvas, "END OF REPLAY", 150, 3, kTitleColor);
    }

    std::vector<OverlayLine> bar(const Session&) const override {
        char line[160];
        std::snprintf(line, sizeof line, "REPLAY  TICK %llu/%llu  x%g%s   P PAUSE%s  UP/DOWN SPEED  ESC %s",
                      static_cast<unsigned long long>(play_->player().game().tickCount()),
                      static_cast<unsigned long long>(play_->player().totalTicks()), kSpeeds[speed_],
                      paused_ ? "  PAUSED" : "", paused_ ? "  RIGHT STEPS" : "",
                      standalone_ ? "QUIT" : "BACK");
        return {{line, render::Color{200, 210, 255, 255}}};
    }

  private:
    Next leave(Session& session) {
        if (standalone_) return Next::exit(play_->finish(session.options.verify));
        return Next::back();
    }

    std::unique_ptr<Playback> play_;
    bool standalone_;
    bool paused_ = false, stepOnce_ = false, stepBack_ = false, stopped_ = false;
    int speed_ = kNormalSpeed;
    double accumulator_ = 0;
};

}  // namespace

std::unique_ptr<Screen> makeReplayScreen(Session& session, const std::string& path, bool standalone) {
    Result<std::unique_ptr<Playback>> play = Playback::open(path, session.assets, session.tasks);
    if (!play) {
        session.tell(play.error().message());
        return nullptr;
    }
    // --replay FILE --seek TICK: the window opens there (a desync on the way is reported as in play).
    if (standalone && session.options.seek >= 0 &&
        !(*play)->seekTo(static_cast<std::uint64_t>(session.options.seek), session.options.verify))
        return nullptr;
    return std::make_unique<ReplayScreen>(std::move(*play), standalone);
}

}  // namespace polar::game
