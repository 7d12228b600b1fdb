// polarcade-bounds edit, driven as a modder drives it but from scripts of events (headless): a
// dragged, added and deleted sample, undo, save and a round trip through check; gen's fit when
// there is no file; a broken file that is shown, printed and never overwritten unless saved; the
// unsaved-changes question; golden screenshots after scripted steps.
//
// The goldens live in tests/tools/golden/ and are compared pixel for pixel (every byte of every
// pixel). After an intended change to the editor's picture, rewrite them with
// POLAR_UPDATE_GOLDEN=1 build/bin/polar-tools-tests --gtest_filter='BoundsEdit*' and look at them.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "polar/authoring/bounds_gen.h"
#include "polar/bounds_file.h"
#include "polar/platform/png_io.h"
#include "run_command.h"
#include "scratch_folder.h"

namespace polar {
namespace {

namespace fs = std::filesystem;
using polar::testing::readFile;

const fs::path kSprites = fs::path(POLAR_ASSET_DIR) / "sprites";
const fs::path kGolden = POLAR_TOOLS_GOLDEN_DIR;

// Where the editor puts a w × h sprite when it opens (Editor::resetView): the largest whole zoom
// z ≤ 64 with z·2w ≤ 680 and z·3h ≤ 2·562, the sprite centred in the 680 × 562 drawing that starts
// 14 rows down. canvas(p) = origin + z·(p.x, −p.y).
struct OpenView {
    int zoom = 1;
    double originX = 0, originY = 0;

    OpenView(int w, int h) {
        zoom = std::clamp(std::min(680 / (2 * w), 2 * 562 / (3 * h)), 1, 64);
        originX = std::floor((680 - zoom * w) / 2.0) + zoom * w / 2.0;
        originY = std::floor(14 + (562 - zoom * h) / 2.0) + zoom * h / 2.0;
    }
    // The canvas pixel holding bound-space point (x, y).
    std::pair<int, int> pixel(double x, double y) const {
        return {static_cast<int>(std::floor(originX + zoom * x)),
                static_cast<int>(std::floor(originY - zoom * y))};
    }
    std::pair<int, int> sample(const BoundSpec& r, std::size_t j) const {
        const double a = r.samples[j][0] * 3.14159265358979323846 / 180.0, d = r.samples[j][1];
        return pixel(r.centre.x() + d * std::cos(a), r.centre.y() + d * std::sin(a));
    }
};

BoundsSpec parse(const fs::path& file) {
    Result<BoundsSpec> spec = parseBounds(SourceFile{file.string(), readFile(file)});
    EXPECT_TRUE(spec.ok()) << (spec.ok() ? "" : spec.error().message());
    return spec.ok() ? *spec : BoundsSpec{};
}

std::string at(std::pair<int, int> p) {
    return std::to_string(p.first) + " " + std::to_string(p.second);
}

class BoundsEdit : public ::testing::Test {
  protected:
    void SetUp() override { folder_ = polar::testing::freshTestFolder("polar-bounds-edit"); }
    void TearDown() override { fs::remove_all(folder_); }

    // The sprite NAME.png copied into the folder, with its bounds file unless told otherwise.
    void copySprite(const std::string& name, bool withBounds = true) const {
        fs::copy_file(kSprites / (name + ".png"), folder_ / (name + ".png"));
        if (withBounds) fs::copy_file(kSprites / (name + ".bounds.json"), folder_ / (name + ".bounds.json"));
    }
    void write(const std::string& name, const std::string& text) const {
        std::ofstream(folder_ / name, std::ios::binary) << text;
    }
    polar::testing::CommandOutcome bounds(const std::vector<std::string>& args) const {
        return polar::testing::run(POLAR_BOUNDS_EXE, args, folder_);
    }
    // Runs the editor headless on NAME.png with `script`, ending with a screenshot end.png.
    polar::testing::CommandOutcome edit(const std::string& name, const std::string& script,
                                        std::vector<std::string> extra = {}) const {
        write("script.txt", script);
        std::vector<std::string> args = {"edit", name + ".png"};
        args.insert(args.end(), extra.begin(), extra.end());
        args.insert(args.end(), {"--script", "script.txt", "--screenshot", "end.png"});
        return bounds(args);
    }
    // Compares the screenshot `file` with golden/NAME.png pixel for pixel, or rewrites the golden.
    void expectGolden(const std::string& file, const std::string& name) const {
        const fs::path golden = kGolden / (name + ".png");
        if (const char* update = std::getenv("POLAR_UPDATE_GOLDEN"); update && std::string(update) == "1") {
            fs::create_directories(kGolden);
            fs::copy_file(folder_ / file, golden, fs::copy_options::overwrite_existing);
            return;
        }
        Result<RgbaImage> actual = loadPng((folder_ / file).string());
        Result<RgbaImage> expected = loadPng(golden.string());
        ASSERT_TRUE(actual.ok()) << actual.error().message();
        ASSERT_TRUE(expected.ok()) << expected.error().message() << " (POLAR_UPDATE_GOLDEN=1 writes it)";
        ASSERT_EQ(actual->width, expected->width);
        ASSERT_EQ(actual->height, expected->height);
        std::size_t differing = 0, first = 0;
        for (std::size_t i = 0; i < actual->pixels.size(); ++i)
            if (actual->pixels[i] != expected->pixels[i] && differing++ == 0) first = i;
        if (differing)
            fs::copy_file(folder_ / file, fs::temp_directory_path() / ("failed-" + name + ".png"),
                          fs::copy_options::overwrite_existing);
        EXPECT_EQ(differing, 0u) << name << ": first at (" << first % actual->width << ", "
                                 << first / actual->width << "); the picture is in "
                                 << (fs::temp_directory_path() / ("failed-" + name + ".png"));
    }

    fs::path folder_;
};

TEST_F(BoundsEdit, DragAddDeleteUndoSaveAndCheck) {
    copySprite("rock-large-1");
    const BoundsSpec before = parse(folder_ / "rock-large-1.bounds.json");
    ASSERT_EQ(before.radii.size(), 1u);
    const BoundSpec& r = before.radii[0];
    const OpenView view(56, 56);
    ASSERT_EQ(view.zoom, 6);
    // Sample 1 dragged to bound-space (30, 5) from the centre: 9.46 deg, radius 30.414.
    const auto from = view.sample(r, 0);
    const auto to = view.pixel(r.centre.x() + 30, r.centre.y() + 5);
    // A click on the outline halfway along the edge between the samples with the widest gap
    // (the file is in ascending order, the first sample not among them) adds a sample there;
    // Delete removes it, undo brings it back.
    std::size_t gap = 1;
    for (std::size_t j = 1; j + 1 < r.samples.size(); ++j)
        if (r.samples[j + 1][0] - r.samples[j][0] > r.samples[gap + 1][0] - r.samples[gap][0]) gap = j;
    auto tip = [&](std::size_t j) {
        const double a = r.samples[j][0] * 3.14159265358979323846 / 180.0;
        return Vec2(r.centre.x() + r.samples[j][1] * std::cos(a),
                    r.centre.y() + r.samples[j][1] * std::sin(a));
    };
    const Vec2 middle = (tip(gap) + tip(gap + 1)) / 2;
    const auto onEdge = view.pixel(middle.x(), middle.y());
    const std::string script = "drag left " + at(from) + " " + at(to) + "\n" + "click left " + at(onEdge) +
                               "\n"
                               "key delete\n"
                               "key ctrl+z\n"
                               "key ctrl+s\n";
    const polar::testing::CommandOutcome run = edit("rock-large-1", script);
    ASSERT_EQ(run.exitCode, 0) << run.err;

    const BoundsSpec after = parse(folder_ / "rock-large-1.bounds.json");
    ASSERT_EQ(after.radii.size(), 1u);
    const std::vector<DegreeSample>& s = after.radii[0].samples;
    ASSERT_EQ(s.size(), r.samples.size() + 1);
    // The dragged sample, to the tenth of a degree and the thousandth of a pixel the editor writes
    // (the pointer lands on a pixel's centre, so within half a canvas pixel of the target).
    EXPECT_NEAR(s[0][0], 9.46, 0.6);
    EXPECT_NEAR(s[0][1], std::hypot(30.0, 5.0), 0.1);
    EXPECT_EQ(s[0][0], std::round(s[0][0] * 10) / 10);
    EXPECT_EQ(s[0][1], std::round(s[0][1] * 1000) / 1000);
    EXPECT_NE(s[0], r.samples[0]);
    // The added sample came back with undo, in ascending place.
    const std::size_t added = gap + 1;
    EXPECT_GT(s[added][0], r.samples[gap][0]);
    EXPECT_LT(s[added][0], r.samples[gap + 1][0]);
    EXPECT_EQ(std::find(r.samples.begin(), r.samples.end(), s[added]), r.samples.end());
    // On the outline where it was clicked: within the canvas pixel (1/6 px) of the edge's middle.
    const double a = s[added][0] * 3.14159265358979323846 / 180.0;
    const Vec2 newTip = r.centre + s[added][1] * Vec2(std::cos(a), std::sin(a));
    EXPECT_LT((newTip - middle).norm(), 0.15);
    // Every other sample unchanged, in its order.
    for (std::size_t j = 1; j < r.samples.size(); ++j) EXPECT_EQ(s[j < added ? j : j + 1], r.samples[j]) << j;

    // The saved file is what check (the game's loader) accepts, and it reads back the same.
    const polar::testing::CommandOutcome check = bounds({"check", "rock-large-1.bounds.json"});
    EXPECT_EQ(check.exitCode, 0) << check.err;
    EXPECT_NE(check.out.find("ok (1 radii, " + std::to_string(s.size()) + " samples"), std::string::npos)
        << check.out;
    EXPECT_EQ(readFile(folder_ / "rock-large-1.bounds.json"), boundsToJson(after));
}

TEST_F(BoundsEdit, TightenAndFitFromAlpha) {
    copySprite("rock-large-1");
    const BoundsSpec spec = parse(folder_ / "rock-large-1.bounds.json");
    const BoundSpec& r = spec.radii[0];
    const OpenView view(56, 56);
    // Sample 1 dragged 6 px further out, then tightened: it comes back in as far as the opaque
    // pixels allow, and the outline still encloses every one of them.
    const double a = r.samples[0][0] * 3.14159265358979323846 / 180.0, out = r.samples[0][1] + 6;
    const std::string script =
        "drag left " + at(view.sample(r, 0)) + " " +
        at(view.pixel(r.centre.x() + out * std::cos(a), r.centre.y() + out * std::sin(a))) +
        "\nkey t\nkey ctrl+s\n";
    polar::testing::CommandOutcome run = edit("rock-large-1", script);
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const BoundsSpec tightened = parse(folder_ / "rock-large-1.bounds.json");
    const BoundSpec& t = tightened.radii[0];
    EXPECT_LT(t.samples[0][1], r.samples[0][1] + 1.0);
    Result<RgbaImage> sprite = loadPng((folder_ / "rock-large-1.png").string());
    ASSERT_TRUE(sprite.ok());
    const PixelSet opaque = PixelSet::opaque(alphaMaskOf(*sprite));
    const Bound radii = Bound::fromDegrees(t.centre, t.samples, t.interpolate);
    EXPECT_EQ(measureFit(opaque, radii, false).worstMiss, 0.0);
    // 0.01 px further in, it would miss: tighter is not possible.
    std::vector<DegreeSample> closer = t.samples;
    closer[0][1] -= 0.01;
    EXPECT_GT(measureFit(opaque, Bound::fromDegrees(t.centre, closer, t.interpolate), false).worstMiss, 0.0);

    // Fit from alpha on all radii is gen's fit, exactly.
    run = edit("rock-large-1", "key shift+f\nkey ctrl+s\n");
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const polar::testing::CommandOutcome gen =
        bounds({"gen", "rock-large-1.png", "-o", "gen.bounds.json", "-q"});
    ASSERT_EQ(gen.exitCode, 0) << gen.err;
    EXPECT_EQ(readFile(folder_ / "rock-large-1.bounds.json"), readFile(folder_ / "gen.bounds.json"));
}

TEST_F(BoundsEdit, PanAndZoomMoveTheViewNotTheBounds) {
    copySprite("rock-medium-3");
    const BoundsSpec spec = parse(folder_ / "rock-medium-3.bounds.json");
    const BoundSpec& r = spec.radii[0];
    const OpenView view(32, 32);
    // Space + drag pans by (40, 30), the middle button by (−10, 10), the wheel zooms in one step
    // about the pointer; none of these is an edit, and the handles go where the view puts them.
    const auto [x, y] = view.sample(r, 2);
    std::string script = "down space\ndrag left 300 300 340 330\nup space\ndrag middle 340 330 330 340\n";
    script += "move " + std::to_string(x + 50) + " " + std::to_string(y + 50) + "\nwheel 1\n";
    // The handle of sample 3 is now where pan and zoom put it: zoom z + 1 about the pointer p, so
    // q' = p + (q − p)·(z + 1)/z, to within a canvas pixel. Dragging it 2 canvas pixels right and
    // saving changes that one sample.
    const int z = view.zoom;
    const double px = x + 50.5, py = y + 50.5;
    const int hx = static_cast<int>(std::floor(px + (x + 30.5 - px) * (z + 1) / z));
    const int hy = static_cast<int>(std::floor(py + (y + 40.5 - py) * (z + 1) / z));
    script += "drag left " + std::to_string(hx) + " " + std::to_string(hy) + " " + std::to_string(hx) + " " +
              std::to_string(hy - 3 * (z + 1)) + "\n";
    script += "screenshot moved.png\nkey ctrl+s\n";
    const polar::testing::CommandOutcome run = edit("rock-medium-3", script);
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const BoundsSpec after = parse(folder_ / "rock-medium-3.bounds.json");
    ASSERT_EQ(after.radii[0].samples.size(), r.samples.size());
    for (std::size_t j = 0; j < r.samples.size(); ++j)
        if (j == 2)
            EXPECT_NE(after.radii[0].samples[j], r.samples[j]);
        else
            EXPECT_EQ(after.radii[0].samples[j], r.samples[j]) << j;
    // The sample moved up by 3 sprite pixels (3·(z + 1) canvas pixels at the new zoom).
    const double a = after.radii[0].samples[2][0] * 3.14159265358979323846 / 180.0;
    const double b = r.samples[2][0] * 3.14159265358979323846 / 180.0;
    const Vec2 moved = after.radii[0].samples[2][1] * Vec2(std::cos(a), std::sin(a)) -
                       r.samples[2][1] * Vec2(std::cos(b), std::sin(b));
    EXPECT_NEAR(moved.x(), 0.0, 0.3);
    EXPECT_NEAR(moved.y(), 3.0, 0.3);
}

TEST_F(BoundsEdit, RadiiAddedMovedToggledRemovedUndoneAndRedone) {
    copySprite("comet", false);
    const OpenView view(24, 24);
    // gen's two radii; N adds a third at the pointer (bound space (−4, 6)); dragging its centre
    // moves it by 2 sprite pixels right; I makes it arcs (interpolate false).
    const auto [x, y] = view.pixel(-4, 6);
    const int z = view.zoom;
    std::string script = "move " + at(view.pixel(-4, 6)) + "\nkey n\n";
    script += "drag left " + at(view.pixel(-4, 6)) + " " + std::to_string(x + 2 * z) + " " +
              std::to_string(y) + "\n";
    script += "key i\nkey ctrl+s\n";
    polar::testing::CommandOutcome run = edit("comet", script, {"--radii", "2"});
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const BoundsSpec three = parse(folder_ / "comet.bounds.json");
    ASSERT_EQ(three.radii.size(), 3u);
    const BoundSpec& added = three.radii[2];
    EXPECT_FALSE(added.interpolate);
    EXPECT_EQ(added.samples.size(), 8u);
    // The pointer lands on a canvas pixel's centre: within half a canvas pixel of the target.
    EXPECT_NEAR(added.centre.x(), -2.0, 0.5 / z + 0.01);
    EXPECT_NEAR(added.centre.y(), 6.0, 0.5 / z + 0.01);

    // The editor opens with radii 1 selected: Tab selects radii 2, X removes it; undo, then Ctrl+Y redoes it;
    // undo and Ctrl+Shift+Z again. The file keeps radii 1 and 3.
    run = edit("comet", "key tab\nkey x\nkey ctrl+z\nkey ctrl+y\nkey ctrl+z\nkey ctrl+shift+z\nkey ctrl+s\n");
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const BoundsSpec two = parse(folder_ / "comet.bounds.json");
    ASSERT_EQ(two.radii.size(), 2u);
    EXPECT_EQ(two.radii[0].samples, three.radii[0].samples);
    EXPECT_EQ(two.radii[1].samples, three.radii[2].samples);
    EXPECT_EQ(two.radii[1].centre, three.radii[2].centre);
    // Undo as far as it goes is the file as opened.
    run = edit("comet", "key i\nkey tab\nkey x\nkey ctrl+z\nkey ctrl+z\nkey ctrl+z\nkey ctrl+s\n");
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_EQ(readFile(folder_ / "comet.bounds.json"), boundsToJson(two));
}

TEST_F(BoundsEdit, WithoutAFileStartsFromGensFitAndSavesItAsGenWrites) {
    copySprite("rock-medium-2", false);
    polar::testing::CommandOutcome run = edit("rock-medium-2", "key f12\n");
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_FALSE(fs::exists(folder_ / "rock-medium-2.bounds.json")) << "written without Ctrl+S";

    run = edit("rock-medium-2", "key ctrl+s\n");
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const polar::testing::CommandOutcome gen =
        bounds({"gen", "rock-medium-2.png", "-o", "gen.bounds.json", "-q"});
    ASSERT_EQ(gen.exitCode, 0) << gen.err;
    EXPECT_EQ(readFile(folder_ / "rock-medium-2.bounds.json"), readFile(folder_ / "gen.bounds.json"));
}

TEST_F(BoundsEdit, ABrokenFileIsShownPrintedAndKeptUnlessSaved) {
    copySprite("rock-medium-1", false);
    const std::string broken = "{\n  \"format\": 1,\n  \"radii\": [{\"samples\": [[0, 5], [90, -2]]}]\n}\n";
    write("rock-medium-1.bounds.json", broken);
    polar::testing::CommandOutcome run = edit("rock-medium-1", "key p\n");
    ASSERT_EQ(run.exitCode, 0) << run.err;
    // The loader's own message, file:line:column first, on stderr.
    EXPECT_EQ(run.err.rfind("rock-medium-1.bounds.json:3:", 0), 0u) << run.err;
    EXPECT_NE(run.err.find("starting from gen's fit"), std::string::npos) << run.err;
    EXPECT_EQ(readFile(folder_ / "rock-medium-1.bounds.json"), broken);
    expectGolden("end.png", "edit-broken-file");

    // Answering "discard" to the close question leaves it too; "save" writes gen's fit over it.
    run = edit("rock-medium-1", "quit\nkey d\n");
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_EQ(readFile(folder_ / "rock-medium-1.bounds.json"), broken);
    run = edit("rock-medium-1", "quit\nkey s\n");
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const polar::testing::CommandOutcome check = bounds({"check", "rock-medium-1.bounds.json"});
    EXPECT_EQ(check.exitCode, 0) << check.err;
}

TEST_F(BoundsEdit, ClosingWithUnsavedChangesAsksFirst) {
    copySprite("rock-small-1");
    const std::string original = readFile(folder_ / "rock-small-1.bounds.json");
    // An edit, then the close button: the question is up, and Esc keeps editing.
    polar::testing::CommandOutcome run =
        edit("rock-small-1", "key i\nquit\nscreenshot asked.png\nkey escape\n");
    ASSERT_EQ(run.exitCode, 0) << run.err;
    expectGolden("asked.png", "edit-unsaved-question");
    EXPECT_EQ(readFile(folder_ / "rock-small-1.bounds.json"), original);
    // Unchanged bounds close at once: the rest of the script is not run (no screenshot after it).
    run = edit("rock-small-1", "quit\nscreenshot after.png\n");
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_FALSE(fs::exists(folder_ / "after.png"));
}

TEST_F(BoundsEdit, GoldenAfterADragAPartnerAndAnAccuracyLevel) {
    copySprite("rock-large-1");
    const BoundsSpec spec = parse(folder_ / "rock-large-1.bounds.json");
    const OpenView view(56, 56);
    const BoundSpec& r = spec.radii[0];
    // Sample 4 pulled in; the same sprite as partner, moved into the rock, turned and at exact.
    const std::string script = "drag left " + at(view.sample(r, 3)) + " " + at(view.pixel(8, 10)) + "\n" +
                               "key p\n"
                               "drag left " +
                               at(view.pixel(40, 0)) + " " + at(view.pixel(22, -4)) + "\n" +
                               "key comma\nkey comma\nkey 6\n";
    const polar::testing::CommandOutcome run = edit("rock-large-1", script);
    ASSERT_EQ(run.exitCode, 0) << run.err;
    expectGolden("end.png", "edit-drag-partner-exact");
}

TEST_F(BoundsEdit, GoldenOfTwoRadiiTightenedAndTheKeyList) {
    copySprite("comet", false);
    const polar::testing::CommandOutcome run =
        edit("comet", "key tab\nkey shift+t\nkey 2\nwheel 1\nkey h\n", {"--radii", "2"});
    ASSERT_EQ(run.exitCode, 0) << run.err;
    expectGolden("end.png", "edit-two-radii-keys");
}

TEST_F(BoundsEdit, ABadScriptIsOneMessageWithItsLineAndColumn) {
    copySprite("bullet");
    polar::testing::CommandOutcome run = edit("bullet", "move 1 2\n  key ctrl+nokey\n");
    EXPECT_EQ(run.exitCode, 2);
    EXPECT_EQ(run.err,
              "script.txt:2:7: \"nokey\" is not a key name; expected a key as platform::keyName writes it, "
              "e.g. z, delete, tab, space, f12\n");
    run = edit("bullet", "hover 1 2\n");
    EXPECT_EQ(run.exitCode, 2);
    EXPECT_EQ(run.err.rfind("script.txt:1:1: unknown command \"hover\"", 0), 0u) << run.err;
}

TEST_F(BoundsEdit, HelpListsTheKeys) {
    const polar::testing::CommandOutcome run = bounds({"edit", "--help"});
    EXPECT_EQ(run.exitCode, 0);
    for (const char* key : {"Ctrl+Z", "Ctrl+Shift+Z or Ctrl+Y", "Ctrl+S", "Tab", "Delete", "fit from alpha",
                            "tighten", "accuracy", "--script"})
        EXPECT_NE(run.out.find(key), std::string::npos) << key;
}

}  // namespace
}  // namespace polar
