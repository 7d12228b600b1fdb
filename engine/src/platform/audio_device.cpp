#include "polar/platform/audio_device.h"

#include <SDL.h>

#include <algorithm>

namespace polar::platform {

Result<std::unique_ptr<AudioDevice>> AudioDevice::open(const AudioSettings& settings, AudioMixer mixer) {
    auto failure = [](const char* what) {
        return Error{"", 0, 0, std::string(what) + " (" + SDL_GetError() + ")", "a sound output device"};
    };
    if (SDL_InitSubSystem(SDL_INIT_AUDIO) != 0) return failure("cannot start SDL audio");
    std::unique_ptr<AudioDevice> device(new AudioDevice());
    device->mixer_ = std::move(mixer);
    SDL_AudioSpec want{}, have{};
    want.freq = settings.sampleRate;
    want.format = AUDIO_F32SYS;
    want.channels = Uint8(std::clamp(settings.channels, 1, 8));
    want.samples = Uint16(std::clamp(settings.framesPerBlock, 16, 8192));
    want.callback = &AudioDevice::callback;
    want.userdata = device.get();
    // No changes allowed: SDL converts to whatever the hardware takes, so `have` is `want`.
    device->device_ = SDL_OpenAudioDevice(nullptr, 0, &want, &have, 0);
    if (device->device_ == 0) {
        Error error = failure("cannot open an audio device");
        SDL_QuitSubSystem(SDL_INIT_AUDIO);
        return error;
    }
    device->sampleRate_ = have.freq;
    device->channels_ = have.channels;
    return device;
}

AudioDevice::~AudioDevice() {
    SDL_CloseAudioDevice(device_);  // waits for a callback in progress
    SDL_QuitSubSystem(SDL_INIT_AUDIO);
}

void AudioDevice::start() {
    SDL_PauseAudioDevice(device_, 0);
}

void AudioDevice::pause() {
    SDL_PauseAudioDevice(device_, 1);
}

void AudioDevice::callback(void* self, unsigned char* stream, int bytes) {
    auto* device = static_cast<AudioDevice*>(self);
    const int frames = bytes / int(sizeof(float)) / device->channels_;
    device->mixer_(reinterpret_cast<float*>(stream), frames);
}

}  // namespace polar::platform
