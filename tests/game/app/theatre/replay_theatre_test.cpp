// The replay theatre's parts: the markers found while a replay is read (each checked against straight
// play at its tick), the score a high-score marker measures against, the list's summary of a replay
// and its verdict on playing it here, the list's order, export, and the seek bar's geometry.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>

#include "app/screens/replay_list_screen.h"
#include "app/screens/widgets/seek_bar.h"
#include "app/theatre/replay_playback.h"
#include "app/theatre/replay_summary.h"
#include "golden_replays.h"
#include "polar/platform/image_file.h"
#include "run_command.h"
#include "scratch_folder.h"

namespace polar::game {
namespace {

namespace fs = std::filesystem;

int rocksIn(const Game& game) {
    int rocks = 0;
    for (const GameObject& object : game.world().objects()) rocks += game.kindOf(object.id) == Kind::Rock;
    return rocks;
}

int cometsIn(const Game& game) {
    int comets = 0;
    for (const GameObject& object : game.world().objects()) comets += game.kindOf(object.id) == Kind::Comet;
    return comets;
}

std::unique_ptr<Playback> openPlayback(const std::string& path, const AssetFs& assets, TaskSystem& tasks) {
    Result<std::unique_ptr<Playback>> play = Playback::open(path, assets, tasks);
    EXPECT_TRUE(play.ok()) << (play.ok() ? "" : play.error().message());
    return play.ok() ? std::move(*play) : nullptr;
}

// Every marker of every golden replay is where straight play says: a life fewer, the last rock
// gone, a comet fewer, the first points (no table here). A second pass over the same ticks, after a
// seek back, adds none.
TEST(ReplayTheatre, MarkersSitWhereStraightPlayChanges) {
    const AssetFs assets(POLAR_ASSET_DIR);
    ThreadPool tasks(1);
    std::set<ReplayMarker::Kind> kinds;
    for (const std::string& path : polar::testing::goldenReplays()) {
        SCOPED_TRACE(path);
        std::unique_ptr<Playback> play = openPlayback(path, assets, tasks);
        ASSERT_TRUE(play);
        while (!play->player().done()) ASSERT_TRUE(play->tick(true));
        const std::vector<ReplayMarker> markers = play->markers().all();
        EXPECT_EQ(play->markers().seen(), play->player().totalTicks());
        ASSERT_TRUE(play->seekTo(0, true));
        while (!play->player().done()) ASSERT_TRUE(play->tick(true));
        ASSERT_EQ(play->markers().all().size(), markers.size()) << "a tick played twice marks once";

        std::unique_ptr<Playback> straight = openPlayback(path, assets, tasks);
        ASSERT_TRUE(straight);
        for (std::size_t i = 0; i < markers.size(); ++i) {
            const ReplayMarker& m = markers[i];
            if (i > 0) {
                EXPECT_LE(markers[i - 1].tick, m.tick) << "in tick order";
            }
            ASSERT_GT(m.tick, 0u);
            ASSERT_TRUE(straight->seekTo(m.tick - 1, true));
            const Game& before = straight->player().game();
            const int lives = before.lives(), rocks = rocksIn(before), comets = cometsIn(before);
            const int score = before.score();
            ASSERT_TRUE(straight->seekTo(m.tick, true));
            const Game& after = straight->player().game();
            kinds.insert(m.kind);
            switch (m.kind) {
                case ReplayMarker::Kind::LifeLost:
                    EXPECT_EQ(after.lives(), lives - 1) << "life lost at tick " << m.tick;
                    break;
                case ReplayMarker::Kind::WaveCleared:
                    EXPECT_GT(rocks, 0) << "wave cleared at tick " << m.tick;
                    EXPECT_EQ(rocksIn(after), 0) << "wave cleared at tick " << m.tick;
                    EXPECT_EQ(m.value, after.wave());
                    break;
                case ReplayMarker::Kind::CometShot:
                    EXPECT_LT(cometsIn(after), comets) << "comet shot at tick " << m.tick;
                    EXPECT_GT(after.score(), score);
                    break;
                case ReplayMarker::Kind::HighScore:
                    EXPECT_EQ(score, 0) << "first points at tick " << m.tick;
                    EXPECT_GT(after.score(), 0);
                    break;
            }
        }
    }
    EXPECT_EQ(kinds.size(), 4u) << "the golden replays show every kind of marker";
}

TEST(ReplayTheatre, TheHighScoreMarkerMeasuresAgainstTheRecordBefore) {
    const fs::path folder = polar::testing::freshTestFolder("polar-theatre-scores");
    Result<Replay> replay = readReplay(std::string(POLAR_REPLAY_DIR) + "/short.replay");
    ASSERT_TRUE(replay.ok());
    const int final = replay->checkpoints.back().score;
    ASSERT_GT(final, 0);
    HighScores scores = HighScores::load((folder / "highscores.json").string());
    EXPECT_EQ(scoreToBeat(scores, *replay), 0) << "an empty table: the first points";
    scores.select(replay->header.scene);
    scores.insert({"AAA", final + 500, 3});
    scores.insert({"BBB", final - 10, 1});
    EXPECT_EQ(scoreToBeat(scores, *replay), final + 500);
    scores.insert({"CCC", final + 900, 2});
    EXPECT_EQ(scoreToBeat(scores, *replay), final + 900);
    HighScores own = HighScores::load((folder / "own.json").string());
    own.select(replay->header.scene);
    own.insert({"ME", final, 1});
    own.insert({"YOU", final - 10, 1});
    EXPECT_EQ(scoreToBeat(own, *replay), final - 10)
        << "the replay that set the record passes the one before";
    HighScores otherScene = HighScores::load((folder / "other.json").string());
    otherScene.select("scenes/field.json");
    otherScene.insert({"FLD", 99999, 9});
    EXPECT_EQ(scoreToBeat(otherScene, *replay), 0) << "another scene's table does not count";
    fs::remove_all(folder);
}

// What the list says of a replay, and why one cannot play: each case made from a golden replay
// with one line changed.
TEST(ReplayTheatre, TheListSaysWhetherAReplayPlaysHereAndWhyNot) {
    const fs::path folder = polar::testing::freshTestFolder("polar-theatre-summary");
    const AssetFs assets(POLAR_ASSET_DIR);
    const std::string text = polar::testing::readFile(std::string(POLAR_REPLAY_DIR) + "/short.replay");
    auto variant = [&](const std::string& name, const std::string& from, const std::string& to) {
        std::string changed = text;
        const std::size_t at = changed.find(from);
        EXPECT_NE(at, std::string::npos) << from;
        if (at != std::string::npos) changed.replace(at, from.size(), to);
        std::ofstream(folder / name, std::ios::binary) << changed;
        return summariseReplay((folder / name).string(), assets);
    };
    const ReplaySummary good = variant("2026-01-02_12-30-00.replay", "", "");
    EXPECT_EQ(good.playable, ReplaySummary::Playable::Yes) << good.detail;
    EXPECT_EQ(good.when, "2026-01-02 12:30");
    EXPECT_EQ(recorderTimeOf("r/2026-01-02_12-30-05_02.replay"), "2026-01-02 12:30")
        << "a second game that second";
    EXPECT_EQ(recorderTimeOf("r/2026-01-02_12-30-05x.replay"), std::nullopt);
    EXPECT_EQ(recorderTimeOf("r/2026-01-02_12-30.replay"), std::nullopt);
    EXPECT_EQ(recorderTimeOf("r/mine.replay"), std::nullopt);
    EXPECT_EQ(good.scene, "CAVE");
    EXPECT_EQ(good.ticks, 600u);
    Result<Replay> replay = readReplay(std::string(POLAR_REPLAY_DIR) + "/short.replay");
    ASSERT_TRUE(replay.ok());
    EXPECT_EQ(good.score, replay->checkpoints.back().score);
    EXPECT_EQ(good.wave, replay->checkpoints.back().wave);

    const std::size_t ship = text.find(" sprites/ship.bounds.json");
    ASSERT_NE(ship, std::string::npos);
    const std::string hash = text.substr(ship - 16, 16);
    const ReplaySummary changed =
        variant("changed.replay", hash + " sprites/ship", "0000000000000001 sprites/ship");
    EXPECT_EQ(changed.playable, ReplaySummary::Playable::No);
    EXPECT_EQ(changed.reason, "FILES CHANGED");
    EXPECT_NE(changed.detail.find("sprites/ship.bounds.json is not the file"), std::string::npos)
        << changed.detail;

    const ReplaySummary older = variant("older.replay", "game 0.1.0", "game 0.0.9");
    EXPECT_EQ(older.playable, ReplaySummary::Playable::Caution);
    EXPECT_EQ(older.reason, "FROM VERSION 0.0.9");

    const ReplaySummary modded = variant("modded.replay", "\nasset ", "\nmod mods/gold\nasset ");
    EXPECT_EQ(modded.playable, ReplaySummary::Playable::No);
    EXPECT_EQ(modded.reason, "NEEDS MOD GOLD");
    EXPECT_EQ(modded.mods, std::vector<std::string>{"gold"});

    const ReplaySummary missing =
        variant("missing.replay", "scene scenes/cave.json", "scene scenes/gone.json");
    EXPECT_EQ(missing.playable, ReplaySummary::Playable::No);
    EXPECT_EQ(missing.reason, "SCENE MISSING");

    const ReplaySummary broken = variant("broken.replay", "polarcade-replay 1", "not a replay");
    EXPECT_EQ(broken.playable, ReplaySummary::Playable::No);
    EXPECT_EQ(broken.reason, "CANNOT BE READ");
    EXPECT_NE(broken.detail.find("broken.replay:1:"), std::string::npos) << broken.detail;
    fs::remove_all(folder);
}

// An interrupted recording (short.replay cut after its checkpoint at tick 240, no end line) plays
// to its last tick; under --verify it fails unless incomplete replays are allowed. In the theatre
// it is watchable to its end, where the picture says it is incomplete: it differs from the picture
// of the same replay with its end line only by that.
TEST(ReplayTheatre, AnInterruptedRecordingPlaysAndSaysItIsIncomplete) {
    const fs::path folder = polar::testing::freshTestFolder("polar-theatre-incomplete");
    const std::string text = polar::testing::readFile(std::string(POLAR_REPLAY_DIR) + "/short.replay");
    const std::size_t cut = text.find("\nin ", text.find("\ncheck 240 ")) + 1;
    ASSERT_NE(cut, std::string::npos + 1);
    fs::create_directories(folder / "cut");
    fs::create_directories(folder / "ended");
    polar::testing::writeFile(folder / "cut/game.replay", text.substr(0, cut));
    polar::testing::writeFile(folder / "ended/game.replay", text.substr(0, cut) + "end 240 quit\n");

    const AssetFs assets(POLAR_ASSET_DIR);
    ThreadPool tasks(1);
    std::unique_ptr<Playback> play = openPlayback((folder / "cut/game.replay").string(), assets, tasks);
    ASSERT_TRUE(play);
    EXPECT_TRUE(play->incomplete());
    while (!play->player().done()) ASSERT_TRUE(play->tick(true));
    EXPECT_EQ(play->tickNow(), 240u);
    EXPECT_FALSE(play->desync());
    EXPECT_EQ(play->finish(/*verify=*/true, /*allowIncomplete=*/false), 1);
    EXPECT_EQ(play->finish(true, true), 0);
    EXPECT_EQ(play->finish(false, false), 0) << "watching is not verifying";

    auto endPicture = [&](const std::string& sub) {
        polar::testing::writeFile(folder / "script.txt",
                                  "expect replays\nwait 2\nkey enter\nexpect replay\nwait 5\nkey end\n"
                                  "expect-tick 240\nscreenshot " +
                                      sub +
                                      ".png\nkey escape\nexpect replays\n"
                                      "key escape\n");
        const auto run = polar::testing::run(
            POLARCADE_EXE, {"--script", "script.txt", "--data", "data", "--replay", sub}, folder);
        EXPECT_EQ(run.exitCode, 0) << run.err;
        return render::loadCanvas((folder / (sub + ".png")).string());
    };
    Result<render::Canvas> cutEnd = endPicture("cut");
    Result<render::Canvas> endedEnd = endPicture("ended");
    ASSERT_TRUE(cutEnd.ok() && endedEnd.ok());
    int differing = 0, top = cutEnd->height();
    for (int y = 0; y < cutEnd->height(); ++y)
        for (int x = 0; x < cutEnd->width(); ++x)
            if (cutEnd->row(y)[x] != endedEnd->row(y)[x]) ++differing, top = std::min(top, y);
    EXPECT_GT(differing, 0) << "the theatre says the recording is incomplete";
    EXPECT_GE(top, 150) << "the game itself is drawn the same: only the words under END OF REPLAY and in the "
                           "bar differ";
    fs::remove_all(folder);
}

TEST(ReplayTheatre, TheListIsNewestFirstAndExportNeverOverwrites) {
    const fs::path folder = polar::testing::freshTestFolder("polar-theatre-list");
    fs::create_directories(folder / "in");
    for (const char* name : {"2026-01-01_10-00-00", "2026-03-01_10-00-00", "2026-02-01_10-00-00", "mine"})
        std::ofstream(folder / "in" / (std::string(name) + ".replay")) << name;
    std::ofstream(folder / "in" / "notes.txt") << "not a replay";
    std::vector<std::string> names;
    for (const std::string& path : listReplays((folder / "in").string()))
        names.push_back(fs::path(path).stem().string());
    EXPECT_EQ(names, (std::vector<std::string>{"2026-03-01_10-00-00", "2026-02-01_10-00-00",
                                               "2026-01-01_10-00-00", "mine"}));

    // Export goes through platform::offerFile: into $XDG_DOWNLOAD_DIR here, never over a file.
    fs::create_directories(folder / "out");
    ::setenv("XDG_DOWNLOAD_DIR", (folder / "out").c_str(), 1);
    const std::string from = (folder / "in" / "mine.replay").string();
    Result<std::string> first = exportReplay(from), second = exportReplay(from);
    ::unsetenv("XDG_DOWNLOAD_DIR");
    ASSERT_TRUE(first.ok()) << first.error().message();
    ASSERT_TRUE(second.ok()) << second.error().message();
    EXPECT_EQ(fs::path(*first).filename(), "polarcade-mine.replay");
    EXPECT_EQ(fs::path(*second).filename(), "polarcade-mine-2.replay");
    EXPECT_EQ(polar::testing::readFile(*first), "mine");
    EXPECT_EQ(polar::testing::readFile(*second), "mine");
    const char* home = std::getenv("HOME");
    const std::string keptHome = home ? home : "";
    ::setenv("HOME", "", 1);
    Result<std::string> nowhere = exportReplay(from);
    if (home) ::setenv("HOME", keptHome.c_str(), 1);
    ASSERT_FALSE(nowhere.ok());
    EXPECT_NE(nowhere.error().message().find("no folder to export to"), std::string::npos);
    fs::remove_all(folder);
}

TEST(ReplayTheatre, TheSeekBarMapsColumnsToTicksAndPicksMarkers) {
    SeekBar bar;
    bar.layOut({10, 300, 601, SeekBar::kHeight}, 36000);
    EXPECT_EQ(bar.tickAt(10), 0u);
    EXPECT_EQ(bar.tickAt(610), 36000u);
    EXPECT_EQ(bar.tickAt(310), 18000u);
    EXPECT_EQ(bar.tickAt(-50), 0u) << "clamped";
    EXPECT_EQ(bar.columnOf(18000), 310);
    const std::vector<ReplayMarker> markers = {{6000, ReplayMarker::Kind::LifeLost, 0},
                                               {6120, ReplayMarker::Kind::CometShot, 0}};
    // Column 110 is tick 6000, 112 is tick 6120: a press picks the nearer marker within 3 columns.
    ASSERT_TRUE(bar.markerAt(Vec2(109.5, 305), markers));
    EXPECT_EQ(bar.markerAt(Vec2(109.5, 305), markers)->tick, 6000u);
    EXPECT_EQ(bar.markerAt(Vec2(112.5, 305), markers)->tick, 6120u);
    EXPECT_FALSE(bar.markerAt(Vec2(120.5, 305), markers));
    EXPECT_FALSE(bar.markerAt(Vec2(110.5, 290), markers)) << "above the bar";
    // A drag: the press seeks, each move while held scrubs, the release ends it.
    EXPECT_EQ(bar.update(Vec2(109.5, 305), Vec2(109.5, 305), false, markers),
              std::optional<std::uint64_t>(6000));
    EXPECT_TRUE(bar.dragging());
    EXPECT_EQ(bar.update(Vec2(310, 250), std::nullopt, false, markers), std::optional<std::uint64_t>(18000));
    EXPECT_EQ(bar.update(Vec2(410, 250), std::nullopt, true, markers), std::optional<std::uint64_t>(24000));
    EXPECT_FALSE(bar.dragging());
    EXPECT_EQ(bar.update(Vec2(500.5, 250), std::nullopt, false, markers), std::nullopt) << "released";
    EXPECT_EQ(bar.update(Vec2(300.5, 100), Vec2(300.5, 100), false, markers), std::nullopt)
        << "a press elsewhere";
}

}  // namespace
}  // namespace polar::game
