#include "golden.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <sstream>

#include "polar/platform/image_file.h"
#include "polar/render/image.h"
#include "polar/tasks.h"

namespace polar::render::testing {

namespace {

std::string hex(std::uint32_t v) {
    std::ostringstream out;
    out << "0x" << std::hex << v;
    return out.str();
}

bool updating() {
    const char* flag = std::getenv("POLAR_UPDATE_GOLDEN");
    return flag && std::string(flag) == "1";
}

// A task system that ignores minRange: ranges of a fixed number of items, run last first, all on
// this thread. It reports two workers so that a DrawList splits its rows at all.
class FixedBands final : public TaskSystem {
  public:
    explicit FixedBands(std::uint32_t size) : size_(size) {}
    std::uint32_t workerCount() const override { return 2; }
    TaskHandle enqueue(TaskFunction function, std::uint32_t count, std::uint32_t, void* context) override {
        for (std::uint32_t r = (count + size_ - 1) / size_; r-- > 0;)
            function(r * size_, std::min(count, (r + 1) * size_), 0, context);
        return nullptr;
    }
    void finish(TaskHandle) override {}

  private:
    std::uint32_t size_;
};

}  // namespace

void expectListMatchesGolden(const Canvas& background, const DrawList& list, const std::string& name) {
    if (updating()) return;  // the immediate drawing wrote the golden
    auto check = [&](TaskSystem* tasks, const std::string& how) {
        SCOPED_TRACE(name + " through a DrawList, " + how);
        Canvas canvas = background.clone();
        list.draw(canvas, tasks);
        expectMatchesGolden(canvas, name);
    };
    check(nullptr, "no task system");
    for (std::uint32_t workers : {1u, 2u, 3u, 8u}) {
        ThreadPool pool(workers);
        check(&pool, std::to_string(workers) + " threads");
    }
    for (std::uint32_t rows : {1u, 5u, 16u}) {
        FixedBands bands(rows);
        check(&bands, "bands of " + std::to_string(rows) + " rows, last first");
    }
}

void expectMatchesGolden(const Canvas& actual, const std::string& name) {
    const std::string goldenPath = std::string(POLAR_GOLDEN_DIR) + "/" + name + ".png";
    if (updating()) {
        auto error = savePng(actual, goldenPath);
        ASSERT_FALSE(error) << error->message();
        std::printf("updated golden %s\n", goldenPath.c_str());
        return;
    }
    Result<Canvas> golden = loadCanvas(goldenPath);
    ASSERT_TRUE(golden.ok())
        << golden.error().message()
        << "\n(run with POLAR_UPDATE_GOLDEN=1 to create it, then look at it before committing)";
    ASSERT_EQ(golden->width(), actual.width()) << name;
    ASSERT_EQ(golden->height(), actual.height()) << name;

    int differing = 0, firstX = -1, firstY = -1;
    Canvas diff(actual.width(), actual.height());
    for (int y = 0; y < actual.height(); ++y)
        for (int x = 0; x < actual.width(); ++x) {
            const std::uint32_t want = golden->row(y)[x], got = actual.row(y)[x];
            if (want == got) {
                // The golden at a third of its brightness, so the differences stand out.
                diff.row(y)[x] = 0xFF000000u | ((want >> 2) & 0x3F3F3Fu);
                continue;
            }
            diff.row(y)[x] = 0xFFFF00FFu;
            if (differing++ == 0) {
                firstX = x;
                firstY = y;
            }
        }
    if (differing == 0) return;

    const std::filesystem::path dir(POLAR_RENDER_FAILURE_DIR);
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    const std::string actualPath = (dir / (name + ".actual.png")).string();
    const std::string diffPath = (dir / (name + ".diff.png")).string();
    savePng(actual, actualPath);
    savePng(diff, diffPath);
    ADD_FAILURE() << name << ": " << differing << " pixels differ from " << goldenPath << "; the first at ("
                  << firstX << ", " << firstY << "): golden " << hex(golden->row(firstY)[firstX])
                  << ", actual " << hex(actual.row(firstY)[firstX]) << "\nactual: " << actualPath
                  << "\ndiff:   " << diffPath;
}

void drawCheckerboard(Canvas& canvas) {
    for (int y = 0; y < canvas.height(); ++y)
        for (int x = 0; x < canvas.width(); ++x)
            canvas.setPixel(x, y, ((x / 8 + y / 8) % 2) ? Color{70, 70, 80, 255} : Color{40, 40, 48, 255});
}

Image makeArrowSprite() {
    auto inArrow = [](int x, int y) {
        const bool shaft = x >= 3 && x < 13 && y >= 4 && y < 10;
        const bool head = x >= 13 && x < 20 && std::abs(2 * y - 13) <= 2 * (19 - x) + 1;  // tip at x = 19
        return shaft || head;
    };
    Image image(20, 14);
    for (int y = 0; y < 14; ++y)
        for (int x = 0; x < 20; ++x) {
            if (inArrow(x, y)) {
                const bool upperEdge = !inArrow(x, y - 1);
                image.setPixel(x, y,
                               upperEdge
                                   ? Color{255, 230, 0, 255}
                                   : Color{std::uint8_t(60 + 9 * x), std::uint8_t(40 + 12 * y), 200, 255});
            } else if (x < 3 && y >= 5 && y < 9) {
                image.setPixel(x, y, Color{255, 120, 40, std::uint8_t(60 + 50 * x)});  // exhaust, translucent
            }
        }
    return image;
}

}  // namespace polar::render::testing
