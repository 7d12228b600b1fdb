#pragma once
#include <cstdint>
#include <string>

namespace polar::game {

// A line for the player, shown for a few seconds in the notice corner (overlay_layout.h) and
// printed on stderr: a scene that did not load, a recording that stopped. Its clock is the loop's
// ticks, so a script sees it come and go on the same frames every run.
class Notice {
  public:
    void tell(std::string message);
    const std::string& text() const { return text_; }
    // True while the notice is shown (for kTicks after it was told).
    bool fresh() const;
    static constexpr std::uint64_t kTicks = 300;  // 5 s
    // Counts the loop's ticks (the notice clock).
    void countTick() { ++ticks_; }

  private:
    std::string text_;
    std::uint64_t ticks_ = 0, toldAt_ = 0;
};

}  // namespace polar::game
