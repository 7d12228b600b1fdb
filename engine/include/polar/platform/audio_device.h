#pragma once
#include <cstdint>
#include <functional>
#include <memory>

#include "polar/error.h"

namespace polar::platform {

// How to open an AudioDevice.
struct AudioSettings {
    int sampleRate = 44100;    // frames per second
    int channels = 1;          // 1 mono, 2 stereo (samples of a frame are interleaved)
    int framesPerBlock = 512;  // how many frames each call of the mixer fills
};

// Fills `frames` frames of interleaved float samples in [−1, 1] at `out`. Called on the audio
// thread, so it must guard what it shares with the game (a mutex) and never block for long.
using AudioMixer = std::function<void(float* out, int frames)>;

// The sound output: a device that pulls samples from the game's mixer while it plays.
//
// Why pull? The device asks for the next block when it needs one, at its own pace; a mixer that
// synthesizes or mixes on demand never falls behind or runs ahead of the speaker. The device
// opens paused, so the mixer can read sampleRate() before the first call; start() begins playing.
// Destroying it stops the calls (waiting for one in progress) before it returns.
class AudioDevice {
  public:
    // Opens the default output device (starting the audio subsystem). An Error when there is
    // none, e.g. headless or a machine without sound.
    static Result<std::unique_ptr<AudioDevice>> open(const AudioSettings& settings, AudioMixer mixer);
    ~AudioDevice();
    AudioDevice(const AudioDevice&) = delete;
    AudioDevice& operator=(const AudioDevice&) = delete;

    // The device's rate in frames per second (the one asked for: other rates are converted).
    int sampleRate() const { return sampleRate_; }
    int channels() const { return channels_; }
    // Starts or resumes calling the mixer.
    void start();
    // Stops calling the mixer (the speaker plays silence) until start().
    void pause();

  private:
    AudioDevice() = default;
    static void callback(void* self, unsigned char* stream, int bytes);

    std::uint32_t device_ = 0;
    int sampleRate_ = 0;
    int channels_ = 1;
    AudioMixer mixer_;
};

}  // namespace polar::platform
