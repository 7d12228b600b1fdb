#include "app/input/audio.h"

#include <gtest/gtest.h>

#include <cmath>

namespace polar::game {
namespace {

constexpr int kRate = 44100;

// The root mean square of `seconds` of mixed output.
double rms(Audio& audio, double seconds) {
    std::vector<float> samples(static_cast<std::size_t>(seconds * kRate));
    for (std::size_t at = 0; at < samples.size(); at += 512)
        audio.mix(samples.data() + at, static_cast<int>(std::min<std::size_t>(512, samples.size() - at)));
    double sum = 0;
    for (float s : samples) sum += static_cast<double>(s) * s;
    return std::sqrt(sum / static_cast<double>(samples.size()));
}

double effectsLevel(const Audio::Volumes& volumes) {
    std::unique_ptr<Audio> audio = Audio::offline(kRate);
    audio->setVolumes(volumes);
    GameEvent event{};
    event.type = GameEvent::GameOver;  // a 1.2 s square sweep
    audio->play({event});
    return rms(*audio, 0.5);
}

double musicLevel(const Audio::Volumes& volumes, const std::string& scene = "cave") {
    std::unique_ptr<Audio> audio = Audio::offline(kRate);
    audio->setVolumes(volumes);
    audio->setMusic(scene);
    return rms(*audio, 2.0);
}

TEST(Audio, EffectsFollowMasterAndEffectsVolume) {
    const double full = effectsLevel({100, 100, 0, false});
    ASSERT_GT(full, 0.01);
    EXPECT_NEAR(effectsLevel({50, 100, 0, false}) / full, 0.5, 1e-4);
    EXPECT_NEAR(effectsLevel({100, 25, 0, false}) / full, 0.25, 1e-4);
    EXPECT_NEAR(effectsLevel({50, 50, 100, false}) / full, 0.25, 1e-4);  // music volume: no effect
    EXPECT_EQ(effectsLevel({100, 0, 100, false}), 0.0);
    EXPECT_EQ(effectsLevel({100, 100, 100, true}), 0.0);
}

// Every event the game reports has a sound: each alone, in a fresh mixer, is heard.
TEST(Audio, EveryEventIsHeard) {
    for (int type = 0; type <= GameEvent::kLastType; ++type) {
        std::unique_ptr<Audio> audio = Audio::offline(kRate);
        audio->setVolumes({100, 100, 0, false});
        GameEvent event{};
        event.type = static_cast<GameEvent::Type>(type);
        event.size = 2;
        audio->play({event});
        EXPECT_GT(rms(*audio, 0.05), 0.001) << "event type " << type << " is silent";
    }
}

// The thruster hums while Thrust events keep coming, one a tick, and dies away without them.
TEST(Audio, TheThrusterHumsWhileThrusting) {
    std::unique_ptr<Audio> audio = Audio::offline(kRate);
    audio->setVolumes({100, 100, 0, false});
    GameEvent thrust{};
    thrust.type = GameEvent::Thrust;
    for (int tick = 0; tick < 30; ++tick) {
        audio->play({thrust});
        rms(*audio, 1.0 / 60);
    }
    EXPECT_GT(rms(*audio, 0.02), 0.01);
    for (int tick = 0; tick < 30; ++tick) {
        audio->play({});
        rms(*audio, 1.0 / 60);
    }
    EXPECT_LT(rms(*audio, 0.02), 1e-4);
}

TEST(Audio, MusicFollowsMasterAndMusicVolume) {
    const double full = musicLevel({100, 0, 100, false});
    ASSERT_GT(full, 0.01);
    EXPECT_NEAR(musicLevel({100, 100, 40, false}) / full, 0.4, 1e-4);
    EXPECT_NEAR(musicLevel({20, 100, 100, false}) / full, 0.2, 1e-4);
    EXPECT_EQ(musicLevel({100, 100, 0, false}), 0.0);
    EXPECT_EQ(musicLevel({100, 100, 100, true}), 0.0);
    EXPECT_EQ(musicLevel({100, 100, 100, false}, ""), 0.0);  // no scene: no music
}

TEST(Audio, EachSceneHasItsOwnLoop) {
    auto firstSecond = [](const std::string& scene) {
        std::unique_ptr<Audio> audio = Audio::offline(kRate);
        audio->setVolumes({100, 100, 100, false});
        audio->setMusic(scene);
        std::vector<float> samples(kRate);
        audio->mix(samples.data(), kRate);
        return samples;
    };
    EXPECT_EQ(firstSecond("cave"), firstSecond("cave"));
    EXPECT_NE(firstSecond("cave"), firstSecond("field"));
    for (float s : firstSecond("cave")) ASSERT_LE(std::fabs(s), 1.0f);
}

}  // namespace
}  // namespace polar::game
