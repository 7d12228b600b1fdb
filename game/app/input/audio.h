#pragma once
#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
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
//
// Music is a loop synthesized the same way: a bass line and an arpeggio over four chords, its
// notes and tempo drawn from the scene's name, so each scene has its own tune. It lives on the
// audio thread only and never reads or writes the game.
class Audio {
  public:
    // The gains a player sets, as whole percents 0–100.
    struct Volumes {
        int master = 80, effects = 100, music = 60;
        bool mute = false;
    };

    // Opens the default device when `enabled`; silent if it cannot (or when not enabled).
    explicit Audio(bool enabled);
    // No device: mix() is called by hand (tests, and what a headless run would hear).
    static std::unique_ptr<Audio> offline(int sampleRate);
    ~Audio();
    Audio(const Audio&) = delete;
    Audio& operator=(const Audio&) = delete;

    bool active() const { return device_ != nullptr; }
    // Starts the sounds for one tick's events (call it once a tick: the engine's hum lasts while
    // Thrust events keep coming).
    void play(const std::vector<GameEvent>& events);
    void setMuted(bool muted);
    // Stops the device while `paused` (the voices wait where they are), starts it again after.
    void setPaused(bool paused);
    void setVolumes(const Volumes& volumes);
    // Starts the loop chosen by `scene` (a scene's name); an empty name stops the music.
    void setMusic(const std::string& scene);

    // Fills `frames` mono samples with the sum of the playing voices and the music, each times its
    // gain, clamped to [−1, 1] (on the audio thread; by hand when offline).
    void mix(float* out, int frames);

  private:
    struct Music {
        bool on = false;
        double secondsPerStep = 0.125;
        int bass[4] = {};  // the chords' roots, semitones from A2
        int arp[4] = {};   // the arpeggio's steps, semitones above the root
        double time = 0;   // into the current step
        int step = 0;      // 0…63: 4 chords of 16 steps
        double bassPhase = 0, arpPhase = 0;
    };
    struct Voice {
        enum Shape : std::uint8_t { Square, Noise, Triangle } shape = Square;
        double time = 0, duration = 0.1;  // a negative time: it starts that many seconds later
        double freqStart = 440, freqEnd = 440;
        double volume = 0.2;
        double phase = 0;
        std::uint32_t noise = 0x12345678u;
    };
    void start(const Voice& voice);
    void mixMusic(float* out, int frames, double gain);
    void mixEngine(float* out, int frames, double gain);

    int rate_ = 44100;
    std::mutex mutex_;
    std::vector<Voice> voices_;
    Volumes volumes_;
    Music music_;
    int engineTicks_ = 0;  // ticks the thruster's hum goes on for (a Thrust event renews it)
    double engineLevel_ = 0, enginePhase_ = 0;
    std::uint32_t engineNoise_ = 0x2545F491u;
    bool offline_ = false;
    bool paused_ = false;
    // Last, so it is closed first: no mix() runs once the voices and the mutex are gone.
    std::unique_ptr<platform::AudioDevice> device_;
};

}  // namespace polar::game
