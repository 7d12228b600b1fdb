#include "app/hud/notice.h"

#include <cstdio>

namespace polar::game {

bool Notice::fresh() const {
    return !text_.empty() && ticks_ - toldAt_ < kTicks;
}

void Notice::tell(std::string message) {
    std::fprintf(stderr, "polarcade: %s\n", message.c_str());
    text_ = std::move(message);
    toldAt_ = ticks_;
}

}  // namespace polar::game
