#include "app/screens/screen_stack.h"

namespace polar::game {

std::optional<int> ScreenStack::update(Session& session, const Input::Commands& commands) {
    return apply(session, top().update(session, commands));
}

std::optional<int> ScreenStack::apply(Session& session, Next next) {
    switch (next.kind) {
        case Next::Kind::Stay:
            return std::nullopt;
        case Next::Kind::Push:
            screens_.push_back(std::move(next.screen));
            break;
        case Next::Kind::Replace:
            screens_.back() = std::move(next.screen);
            break;
        case Next::Kind::Back:
            if (screens_.size() == 1) return 0;
            screens_.pop_back();
            break;
        case Next::Kind::ToRoot:
            screens_.resize(1);
            break;
        case Next::Kind::Exit:
            return next.exitCode;
    }
    top().enter(session);
    return std::nullopt;
}

void ScreenStack::draw(Session& session, render::Canvas& canvas, double alpha) {
    std::size_t first = screens_.size() - 1;
    while (first > 0 && screens_[first]->overlay()) --first;
    for (std::size_t i = first; i < screens_.size(); ++i)
        screens_[i]->draw(session, canvas, i + 1 == screens_.size() ? alpha : 1.0);
}

const Game* ScreenStack::shownGame(const Session& session) const {
    std::size_t first = screens_.size() - 1;
    while (first > 0 && screens_[first]->overlay()) --first;
    for (std::size_t i = screens_.size(); i-- > first;)
        if (const Game* shown = screens_[i]->shownGame(session)) return shown;
    return nullptr;
}

}  // namespace polar::game
