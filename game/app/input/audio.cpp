#include "app/input/audio.h"

#include <algorithm>
#include <cmath>

namespace polar::game {
namespace {

constexpr std::size_t kMaxVoices = 24;
constexpr double kMusicLevel = 0.12;  // the loop's peak before its volume: under the effects

double gainOf(int percent) {
    return std::clamp(percent, 0, 100) / 100.0;
}

// 2^(semitones/12) times A2 (110 Hz).
double noteHz(int semitones) {
    return 110.0 * std::exp2(semitones / 12.0);
}

}  // namespace

Audio::Audio(bool enabled) {
    if (!enabled) return;
    Result<std::unique_ptr<platform::AudioDevice>> opened =
        platform::AudioDevice::open({44100, 1, 512}, [this](float* out, int frames) { mix(out, frames); });
    if (!opened) return;
    device_ = std::move(*opened);
    rate_ = device_->sampleRate();
    voices_.reserve(kMaxVoices);
    device_->start();
}

Audio::~Audio() = default;

void Audio::setPaused(bool paused) {
    if (!device_ || paused == paused_) return;
    paused_ = paused;
    if (paused)
        device_->pause();
    else
        device_->start();
}

std::unique_ptr<Audio> Audio::offline(int sampleRate) {
    std::unique_ptr<Audio> audio = std::make_unique<Audio>(false);
    audio->offline_ = true;
    audio->rate_ = sampleRate;
    return audio;
}

void Audio::setMuted(bool muted) {
    std::lock_guard<std::mutex> lock(mutex_);
    volumes_.mute = muted;
}

void Audio::setVolumes(const Volumes& volumes) {
    std::lock_guard<std::mutex> lock(mutex_);
    volumes_ = volumes;
}

void Audio::setMusic(const std::string& scene) {
    Music m;
    m.on = !scene.empty();
    // FNV-1a of the name picks the tune: tempo, the four chord roots, the arpeggio's shape.
    std::uint32_t h = 2166136261u;
    for (char c : scene) h = (h ^ static_cast<unsigned char>(c)) * 16777619u;
    auto next = [&h](std::uint32_t n) {
        h = h * 1664525u + 1013904223u;
        return static_cast<int>((h >> 16) % n);
    };
    m.secondsPerStep = 60.0 / (100 + next(60)) / 4.0;  // sixteenth notes at 100–159 beats a minute
    constexpr int kRoots[] = {0, 3, 5, 7, 8, 10};      // A minor's degrees
    for (int& root : m.bass) root = kRoots[next(6)];
    m.bass[0] = 0;
    constexpr int kShapes[][4] = {{12, 15, 19, 24}, {12, 19, 15, 22}, {24, 19, 15, 12}, {12, 17, 19, 24}};
    const int* shape = kShapes[next(4)];
    std::copy(shape, shape + 4, m.arp);
    std::lock_guard<std::mutex> lock(mutex_);
    music_ = m;
}

void Audio::start(const Voice& voice) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (voices_.size() >= kMaxVoices) voices_.erase(voices_.begin());
    voices_.push_back(voice);
}

void Audio::play(const std::vector<GameEvent>& events) {
    if (!device_ && !offline_) return;
    {
        std::lock_guard<std::mutex> lock(mutex_);
        if (engineTicks_ > 0) --engineTicks_;
    }
    for (const GameEvent& e : events) {
        Voice v;
        switch (e.type) {
            case GameEvent::Thrust: {
                std::lock_guard<std::mutex> lock(mutex_);
                engineTicks_ = 2;
                continue;
            }
            case GameEvent::WaveCleared:
                // A rising major arpeggio, a note every tenth of a second.
                for (int i = 0; i < 3; ++i) {
                    const double hz = noteHz(24 + (i == 0 ? 0 : i == 1 ? 4 : 7));
                    start({Voice::Triangle, -0.1 * i, 0.35, hz, hz, 0.2});
                }
                continue;
            case GameEvent::Shot:
                v = {Voice::Square, 0, 0.07, 1250, 500, 0.08};
                break;
            case GameEvent::RockSplit:
            case GameEvent::RockDestroyed:
                // A big rock's split lands with a thump under its crunch, as its hit-stop does.
                if (e.size >= 3) start({Voice::Triangle, 0, 0.3, 90, 35, 0.35});
                v = {Voice::Noise, 0, 0.18 + 0.12 * e.size, 900.0 / (e.size + 1), 120, 0.25};
                break;
            case GameEvent::ShipHit:
                start({Voice::Triangle, 0, 0.5, 70, 28, 0.45});
                v = {Voice::Noise, 0, 0.9, 500, 40, 0.4};
                break;
            case GameEvent::CometIn:
                v = {Voice::Noise, 0, 0.7, 2200, 600, 0.08};
                break;
            case GameEvent::CometShot:
                start({Voice::Triangle, 0, 0.25, 1200, 2400, 0.12});
                v = {Voice::Noise, 0, 0.6, 1500, 80, 0.3};
                break;
            case GameEvent::PickupTaken:
                // Each pickup a chime of its own: a shield and a life the old one, a power-up higher.
                v = {Voice::Triangle,
                     0,
                     0.25,
                     520.0 * (1 + 0.25 * std::max(0, e.size - 1)),
                     1560.0 * (1 + 0.25 * std::max(0, e.size - 1)),
                     0.25};
                break;
            case GameEvent::ExtraLife:
                v = {Voice::Triangle, 0, 0.5, 660, 1320, 0.25};
                break;
            case GameEvent::WaveStart:
                v = {Voice::Triangle, 0, 0.45, 330, 660, 0.2};
                break;
            case GameEvent::ShipRespawn:
                v = {Voice::Triangle, 0, 0.3, 880, 440, 0.15};
                break;
            case GameEvent::GameOver:
                v = {Voice::Square, 0, 1.2, 440, 110, 0.12};
                break;
            case GameEvent::Bounce:
                v = {Voice::Triangle, 0, 0.06, 160, 90, 0.2};
                break;
            case GameEvent::WallHit:
                v = {Voice::Noise, 0, 0.04, 3000, 2000, 0.05};
                break;
            // Rules 3's foes, each with its own voice (e.size: the FoeKind).
            case GameEvent::FoeIn:
                switch (static_cast<FoeKind>(e.size)) {
                    case FoeKind::Saucer:  // the siren: a square wobbling down and up
                        for (int i = 0; i < 4; ++i) start({Voice::Square, -0.12 * i, 0.12, 520, 380, 0.06});
                        continue;
                    case FoeKind::SmallSaucer:  // the same, higher and faster
                        for (int i = 0; i < 6; ++i) start({Voice::Square, -0.08 * i, 0.08, 980, 720, 0.06});
                        continue;
                    case FoeKind::Mine:  // a low sonar ping
                        v = {Voice::Triangle, 0, 0.6, 240, 230, 0.22};
                        break;
                    case FoeKind::Shard:
                        continue;
                    case FoeKind::Hunter:  // a grinding growl
                        v = {Voice::Square, 0, 0.5, 70, 110, 0.08};
                        break;
                }
                break;
            case GameEvent::FoeFired:
                if (static_cast<FoeKind>(e.size) == FoeKind::Hunter)
                    v = {Voice::Square, 0, 0.12, 300, 160, 0.07};
                else
                    v = {Voice::Triangle, 0, 0.1, 1500, 700, 0.12};
                break;
            case GameEvent::FoeHit:
                v = {Voice::Square, 0, 0.05, 200, 180, 0.1};
                break;
            case GameEvent::FoeDestroyed:
                switch (static_cast<FoeKind>(e.size)) {
                    case FoeKind::Mine:  // the burst: a crack, then the shards' rising whine
                        start({Voice::Noise, 0, 0.3, 2600, 300, 0.3});
                        v = {Voice::Square, 0.05, 0.3, 300, 900, 0.06};
                        break;
                    case FoeKind::Shard:
                        v = {Voice::Noise, 0, 0.1, 3000, 1200, 0.12};
                        break;
                    case FoeKind::Hunter:
                        start({Voice::Triangle, 0, 0.4, 110, 40, 0.35});
                        v = {Voice::Noise, 0, 0.5, 700, 60, 0.3};
                        break;
                    default:  // a saucer: a falling warble into a crunch
                        start({Voice::Square, 0, 0.25, 900, 200, 0.07});
                        v = {Voice::Noise, 0, 0.35, 1200, 100, 0.25};
                        break;
                }
                break;
            case GameEvent::PowerUpEnd:
                v = {Voice::Triangle, 0, 0.2, 660, 330, 0.15};
                break;
            case GameEvent::ChainUp:  // a blip that climbs with the multiplier
                v = {Voice::Triangle, 0, 0.08, noteHz(24 + 2 * e.points), noteHz(26 + 2 * e.points), 0.12};
                break;
        }
        start(v);
    }
}

void Audio::mixMusic(float* out, int frames, double gain) {
    Music& m = music_;
    if (!m.on) return;
    const double dt = 1.0 / rate_;
    for (int i = 0; i < frames; ++i) {
        const int chord = m.step / 16;
        const double bass = noteHz(m.bass[chord] - 12);
        const double arp = noteHz(m.bass[chord] + m.arp[m.step % 4]);
        // Each step's note fades out over the step (a pluck); the bass holds for two steps.
        const double pluck = 1.0 - m.time / m.secondsPerStep;
        const double hold = 1.0 - 0.5 * ((m.step % 2) + m.time / m.secondsPerStep) / 2.0;
        m.bassPhase += bass * dt;
        m.bassPhase -= std::floor(m.bassPhase);
        m.arpPhase += arp * dt;
        m.arpPhase -= std::floor(m.arpPhase);
        const double bassSample = 4.0 * std::fabs(m.bassPhase - 0.5) - 1.0;
        const double arpSample = m.arpPhase < 0.25 ? 1.0 : -1.0 / 3.0;
        const double attack = std::min(1.0, m.time * 400.0);
        out[i] += static_cast<float>(kMusicLevel * gain * attack *
                                     (0.6 * bassSample * hold + 0.4 * arpSample * pluck * pluck));
        m.time += dt;
        if (m.time >= m.secondsPerStep) {
            m.time -= m.secondsPerStep;
            m.step = (m.step + 1) % 64;
        }
    }
}

void Audio::mixEngine(float* out, int frames, double gain) {
    // Low noise that swells while the ship thrusts and dies away after, never clicking on or off.
    const double target = engineTicks_ > 0 ? 1.0 : 0.0;
    const double dt = 1.0 / rate_;
    for (int i = 0; i < frames; ++i) {
        engineLevel_ += (target - engineLevel_) * std::min(1.0, dt * 25.0);
        if (engineLevel_ < 1e-4) continue;
        enginePhase_ += 140.0 * dt;
        if (enginePhase_ >= 1.0) {
            enginePhase_ -= std::floor(enginePhase_);
            engineNoise_ = engineNoise_ * 1664525u + 1013904223u;
        }
        const double sample = static_cast<double>(engineNoise_ >> 8) / 8388608.0 - 1.0;
        out[i] += static_cast<float>(sample * engineLevel_ * 0.07 * gain);
    }
}

void Audio::mix(float* out, int frames) {
    std::fill(out, out + frames, 0.0f);
    std::lock_guard<std::mutex> lock(mutex_);
    const double master = volumes_.mute ? 0.0 : gainOf(volumes_.master);
    const double effects = master * gainOf(volumes_.effects);
    mixMusic(out, frames, master * gainOf(volumes_.music));
    mixEngine(out, frames, effects);
    double dt = 1.0 / rate_;
    for (Voice& v : voices_) {
        for (int i = 0; i < frames && v.time < v.duration; ++i) {
            if (v.time < 0) {  // not started yet
                v.time += dt;
                continue;
            }
            double progress = v.time / v.duration;
            double freq = v.freqStart + (v.freqEnd - v.freqStart) * progress;
            double envelope = (1.0 - progress) * (1.0 - progress) * std::min(1.0, v.time * 400.0);
            double sample = 0;
            v.phase += freq * dt;
            v.phase -= std::floor(v.phase);
            switch (v.shape) {
                case Voice::Square:
                    sample = v.phase < 0.5 ? 1.0 : -1.0;
                    break;
                case Voice::Triangle:
                    sample = 4.0 * std::fabs(v.phase - 0.5) - 1.0;
                    break;
                case Voice::Noise:
                    // A new random level each cycle of `freq`: noise whose pitch falls with freq.
                    if (v.phase < freq * dt) v.noise = v.noise * 1664525u + 1013904223u;
                    sample = static_cast<double>(v.noise >> 8) / 8388608.0 - 1.0;
                    break;
            }
            out[i] += static_cast<float>(sample * envelope * v.volume * effects);
            v.time += dt;
        }
    }
    voices_.erase(
        std::remove_if(voices_.begin(), voices_.end(), [](const Voice& v) { return v.time >= v.duration; }),
        voices_.end());
    for (int i = 0; i < frames; ++i) out[i] = std::clamp(out[i], -1.0f, 1.0f);
}

}  // namespace polar::game
