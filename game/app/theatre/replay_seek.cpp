#include "app/theatre/replay_seek.h"

#include <algorithm>
#include <chrono>

namespace polar::game {
namespace {

double msSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

ReplaySeek::ReplaySeek(ReplayPlayer& player, Particles& particles, double tickSeconds, std::uint64_t interval,
                       std::size_t budget)
    : player_(player),
      particles_(particles),
      tickSeconds_(tickSeconds),
      interval_(interval),
      budget_(budget) {
    keepIfDue();
}

std::optional<Desync> ReplaySeek::advance() {
    std::optional<Desync> found = player_.step();
    particles_.spawnFor(player_.game().events(), player_.game().tickCount());
    particles_.tick(tickSeconds_);
    keepIfDue();
    return found;
}

void ReplaySeek::keepIfDue() {
    std::uint64_t tick = player_.game().tickCount();
    if (tick % interval_ != 0 || tick / interval_ != frames_.size()) return;
    Keyframe& frame = frames_.emplace_back();
    player_.mark(frame.mark);
    frame.particles = particles_;
    if (heldBytes() > budget_ && frames_.size() > 2) thin();
}

void ReplaySeek::thin() {
    // Keeps the keyframes at even multiples of the interval, which become the new interval's.
    std::size_t kept = 0;
    for (std::size_t i = 0; i < frames_.size(); i += 2) frames_[kept++] = std::move(frames_[i]);
    frames_.resize(kept);
    interval_ *= 2;
}

std::size_t ReplaySeek::heldBytes() const {
    std::size_t bytes = frames_.capacity() * sizeof(Keyframe);
    for (const Keyframe& f : frames_) bytes += f.mark.game.heldBytes() + f.particles.heldBytes();
    return bytes;
}

std::optional<Desync> ReplaySeek::seek(std::uint64_t tick) {
    last_ = Split{};
    tick = std::min(tick, player_.totalTicks());
    const std::uint64_t now = player_.game().tickCount();
    const std::size_t k = std::min<std::size_t>(tick / interval_, frames_.size() - 1);
    const std::uint64_t frameTick = k * interval_;
    if (now < frameTick || now > tick) {
        auto start = std::chrono::steady_clock::now();
        if (player_.resume(frames_[k].mark)) return std::nullopt;  // our own keyframe: cannot be damaged
        particles_ = frames_[k].particles;
        last_.restored = true;
        last_.restoreMs = msSince(start);
    }
    auto start = std::chrono::steady_clock::now();
    std::optional<Desync> first;
    while (player_.game().tickCount() < tick) {
        std::optional<Desync> found = advance();
        if (found && !first) first = found;
        ++last_.ticks;
    }
    last_.steppingMs = msSince(start);
    return first;
}

}  // namespace polar::game
