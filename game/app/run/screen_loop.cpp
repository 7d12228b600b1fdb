#include "app/run/screen_loop.h"

#include <algorithm>
#include <cstdio>

#include "app/hud/overlays.h"
#include "app/screens/theatre_screen.h"

namespace polar::game {
namespace {

constexpr double kTickSeconds = 1.0 / 60.0;
constexpr double kMaxFrameSeconds = 0.25;  // a longer frame is clamped: no spiral of death

}  // namespace

ScreenLoop::ScreenLoop(AppContext& context, platform::Window* window, std::string scenePath,
                       const std::function<std::unique_ptr<Screen>(Session&)>& root)
    : context_(context) {
    // A script is a test: no sound device, whatever --mute says.
    audio_.emplace(window != nullptr && !context.options.mute);
    const DataFolder& data = context.dataFolder();
    std::optional<Error> scoreProblem;
    // A folder that cannot be written may still be read: its table is shown, never saved.
    scores_ = HighScores::load(data.path.empty() ? "" : data.path + "highscores.json", &scoreProblem);
    scores_.select(scenePath, modSetOf(context.options.mods));  // a table per scene and set of mods
    if (scoreProblem)
        std::fprintf(stderr, "%s (%s)\n", scoreProblem->message().c_str(),
                     data.writable() ? "kept aside; a new table starts" : "a new table starts");
    recorder_.emplace(GameRecorder::Options{
        context.options.record, data.writable() ? data.path + "replays" : "", 20, context.options.mods, {}});
    session_.emplace(Session::Parts{context, scores_, *recorder_, *audio_, input_, window},
                     std::move(scenePath));
    std::unique_ptr<Screen> first = root(*session_);
    if (!first) return;
    stack_ = std::make_unique<ScreenStack>(std::move(first));
    stack_->top().enter(*session_);
}

ScreenLoop::~ScreenLoop() = default;

std::optional<int> ScreenLoop::frame(const std::vector<platform::Event>& events, double seconds) {
    Session& s = *session_;
    if (context_.options.deviceOfPage)
        if (std::optional<Device> device = context_.options.deviceOfPage()) input_.pinDevice(*device);
    for (const platform::Event& event : events) input_.handle(event);
    const Input::Commands commands = input_.takeCommands();
    if (commands.quit) return finish(0);
    if (commands.debugOverlay) s.debug = !s.debug;
    if (std::optional<int> code = stack_->update(s, commands)) return finish(*code);
    s.audio.setPaused(stack_->top().silent());

    s.fps = s.fps * 0.95 + (seconds > 0 ? 0.05 / seconds : 0);
    accumulator_ += std::min(seconds, kMaxFrameSeconds);
    const HotReload::Report reload = context_.reloadBetweenTicks(
        {s.games.attract ? &*s.games.attract : nullptr, s.games.player ? &*s.games.player : nullptr},
        commands.reload);
    stopRecordingIfReloaded(reload);
    while (accumulator_ >= kTickSeconds) {
        accumulator_ -= kTickSeconds;
        s.notice.countTick();
        stack_->tick(s);
    }
    stack_->draw(s, context_.canvas, accumulator_ / kTickSeconds);
    drawOverlays();
    context_.reportSpriteProblems();
    return std::nullopt;
}

void ScreenLoop::stopRecordingIfReloaded(const HotReload::Report& reload) {
    Session& s = *session_;
    if (!s.games.player || !s.games.player->modified() || !recorder_->recording()) return;
    recorder_->abandon();
    const std::string file =
        reload.reloaded.empty()
            ? std::string("a file")
            : context_.assets.resolve(reload.reloaded.front()).value_or(reload.reloaded.front());
    char tick[32];
    std::snprintf(tick, sizeof tick, "%llu", static_cast<unsigned long long>(s.games.player->tickCount()));
    s.notice.tell(
        "RECORDING STOPPED at tick " + std::string(tick) + ": " + file +
        " was reloaded, and a replay can only play the files its game started with. This game is not kept; "
        "the next one is recorded again.");
}

OverlayLayout ScreenLoop::drawOverlays() {
    Session& s = *session_;
    OverlayContent content;
    const Screen& top = stack_->top();
    content.bar = top.bar(s);
    content.help = top.helpLine(s);
    content.message = top.message(s);
    content.barControls = top.barControls();
    if (content.barControls > 0)
        content.drawBarControls = [&](render::Canvas& canvas, const PixelRect& box) {
            top.drawBarControls(s, canvas, box);
        };
    if (s.debug)
        if (const Game* shown = stack_->shownGame(s)) content.debugWorld = &shown->world();
    content.fps = s.fps;
    content.frameTime = s.showFrameTime;
    content.effectMs = &context_.effectMs;
    content.reload = &context_.hotReload;
    if (s.notice.fresh()) content.notice = s.notice.text();
    return polar::game::drawOverlays(context_.canvas, content);
}

double ScreenLoop::idleSeconds() const {
    return kTickSeconds - accumulator_ - 0.002;
}

std::optional<FrameView> ScreenLoop::view() const {
    const Game* shown = stack_->shownGame(*session_);
    if (!shown) return std::nullopt;
    return FrameView{*shown, stack_->top().name(), scores_, session_->lastSeek};
}

void ScreenLoop::openReplay(const std::string& path) {
    if (std::unique_ptr<Screen> theatre = makeTheatreScreen(*session_, path, false))
        stack_->apply(*session_, Next::push(std::move(theatre)));
}

int ScreenLoop::finish(int code) {
    session_->games.endGame("quit");
    context_.printStats();
    return code;
}

}  // namespace polar::game
