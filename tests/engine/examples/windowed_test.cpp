// The windowed example, run headless as a user would: its frame must be the committed screenshot,
// pixel for pixel (assets/docs/example-windowed.png, shown in the docs).
#include <gtest/gtest.h>

#include <filesystem>

#include "polar/platform/image_file.h"
#include "run_command.h"
#include "scratch_folder.h"

namespace polar::render {
namespace {

TEST(WindowedExample, HeadlessFrameIsTheDocsScreenshot) {
    const std::filesystem::path folder = polar::testing::freshTestFolder("polar-example-windowed");
    const std::string shot = (folder / "frame.png").string();
    const polar::testing::CommandOutcome run =
        polar::testing::runShell(polar::testing::shellQuote(POLAR_EXAMPLE_WINDOWED_EXE) +
                                 " --headless --ticks 240 --screenshot " + polar::testing::shellQuote(shot));
    ASSERT_EQ(run.exitCode, 0) << run.err;
    Result<Canvas> frame = loadCanvas(shot);
    ASSERT_TRUE(frame.ok()) << frame.error().message();
    Result<Canvas> committed = loadCanvas(std::string(POLAR_ASSET_DIR) + "/docs/example-windowed.png");
    ASSERT_TRUE(committed.ok()) << committed.error().message();
    ASSERT_EQ(frame->width(), committed->width());
    ASSERT_EQ(frame->height(), committed->height());
    int differing = 0;
    for (int y = 0; y < frame->height(); ++y)
        for (int x = 0; x < frame->width(); ++x) differing += frame->row(y)[x] != committed->row(y)[x];
    EXPECT_EQ(differing, 0) << "pixels differ; the new frame is " << shot;
    if (differing == 0) std::filesystem::remove_all(folder);
}

}  // namespace
}  // namespace polar::render
