#pragma once
#include <cstdint>
#include <memory>
#include <mutex>
#include <vector>

#include "polar/platform/audio_device.h"
#include "rules/game.h"

namespace polar::game {

// Short synthesized sound effects: no sound files, no new dependency.
//
// Why synthesized? The game's sounds are chirps, thumps and noise bursts, a few lines of arithmetic
// each. The Audio object turns the game's events into voices and mixes them when the platform's
// audio device asks for samples; if no device can be opened (headless, or a machine without
// sound), it stays silent and everything else carries on.
class Audio {
  public:
    // Opens the default device when `enabled`; silent if it cannot (or when not enabled).
    explicit Audio(bool enabled);
    ~Audio();
    Audio(const Audio&) = delete;
    Audio& operator=(const Audio&) = delete;

    bool active() const { return device_ != nullptr; }
    // Starts the sounds for one tick's events.
    void play(const std::vector<GameEvent>& events);
    void setMuted(bool muted) { muted_ = muted; }
    // Stops the device while `paused` (the voices wait where they are), starts it again after.
    void setPaused(bool paused);

  private:
    struct Voice {
        enum Shape : std::uint8_t { Square, Noise, Triangle } shape = Square;
        double time = 0, duration = 0.1;
        double freqStart = 440, freqEnd = 440;
        double volume = 0.2;
        double phase = 0;
        std::uint32_t noise = 0x12345678u;
    };
    // Fills `frames` mono samples with the sum of the playing voices, clamped to [−1, 1] (on the
    // audio thread).
    void mix(float* out, int frames);
    void start(const Voice& voice);

    int rate_ = 44100;
    std::mutex mutex_;
    std::vector<Voice> voices_;
    bool muted_ = false;
    bool paused_ = false;
    // Last, so it is closed first: no mix() runs once the voices and the mutex are gone.
    std::unique_ptr<platform::AudioDevice> device_;
};

}  // namespace polar::game
