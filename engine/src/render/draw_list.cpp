#include "polar/render/draw_list.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "render/row_clip.h"
#include "render/sprite_span.h"

namespace polar::render {

namespace {
// The most bands per worker, and the most canvas bytes in a band (see draw).
constexpr std::uint32_t kBandsPerWorker = 8;
constexpr std::uint32_t kBandBytes = 512 * 1024;
// Sprites per range of the setup pass: enough that a range outlasts claiming it.
constexpr std::uint32_t kMinPrepareRange = 64;
}  // namespace

// One recorded call. Which fields mean something depends on `kind`; the rest keep their defaults.
struct DrawList::Command {
    enum class Kind : std::uint8_t {
        kClear,
        kSetPixel,
        kBlendPixel,
        kSprite,
        kFillRect,
        kDrawRect,
        kLine,
        kPolyline,
        kPolygon,
        kFillPolygon,
        kFillCircle,
        kDrawCircle,
        kText,
    };
    Kind kind = Kind::kClear;
    Color color;
    SpriteStyle style;
    int x = 0, y = 0, w = 0, h = 0, scale = 0;  // pixels and rectangles; text's corner and scale
    std::uint32_t first = 0, count = 0;         // points_ or text_; a sprite's ordinal (first)
    double radius = 0;
    const Image* image = nullptr;
    Vec2 a = Vec2::Zero(), b = Vec2::Zero();  // line ends; a circle's centre
    Mat3 toCanvas = Mat3::Identity();
};

DrawList::DrawList() = default;
DrawList::~DrawList() = default;
DrawList::DrawList(DrawList&&) noexcept = default;
DrawList& DrawList::operator=(DrawList&&) noexcept = default;

void DrawList::reset() {
    commands_.clear();
    rows_.clear();
    sprites_.clear();
    points_.clear();
    text_.clear();
    largestPolygon_ = 0;
}

std::size_t DrawList::size() const {
    return commands_.size();
}

DrawList::Command& DrawList::add() {
    rows_.push_back(kEveryRow);
    return commands_.emplace_back();
}

void DrawList::clear(Color color) {
    Command& c = add();
    c.kind = Command::Kind::kClear;
    c.color = color;
}

void DrawList::setPixel(int x, int y, Color color) {
    Command& c = add();
    c.kind = Command::Kind::kSetPixel;
    c.x = x;
    c.y = y;
    c.color = color;
}

void DrawList::blendPixel(int x, int y, Color color) {
    Command& c = add();
    c.kind = Command::Kind::kBlendPixel;
    c.x = x;
    c.y = y;
    c.color = color;
}

void DrawList::drawSprite(const Image& image, const Mat3& toCanvas, const SpriteStyle& style) {
    Command& c = add();
    c.kind = Command::Kind::kSprite;
    c.image = &image;
    c.toCanvas = toCanvas;
    c.style = style;
    c.first = std::uint32_t(sprites_.size());
    sprites_.push_back(std::uint32_t(commands_.size() - 1));
}

void DrawList::drawSprite(const Image& image, const View& view, const Transform& transform,
                          const SpriteStyle& style) {
    drawSprite(image, Mat3(view.matrix() * transform.matrix()), style);
}

void DrawList::drawSprite(const Image& image, const Vec2& centre, const SpriteStyle& style) {
    // The same matrix as render::drawSprite(canvas, image, centre): flip y, translate.
    Mat3 m = Mat3::Identity();
    m(1, 1) = -1.0;
    m(0, 2) = centre.x();
    m(1, 2) = centre.y();
    drawSprite(image, m, style);
}

void DrawList::fillRect(int x0, int y0, int w, int h, Color color) {
    Command& c = add();
    c.kind = Command::Kind::kFillRect;
    c.x = x0;
    c.y = y0;
    c.w = w;
    c.h = h;
    c.color = color;
}

void DrawList::drawRect(int x0, int y0, int w, int h, Color color) {
    fillRect(x0, y0, w, h, color);
    commands_.back().kind = Command::Kind::kDrawRect;
}

void DrawList::drawLine(const Vec2& a, const Vec2& b, Color color) {
    Command& c = add();
    c.kind = Command::Kind::kLine;
    c.a = a;
    c.b = b;
    c.color = color;
}

void DrawList::drawPolyline(std::span<const Vec2> points, Color color) {
    Command& c = add();
    c.kind = Command::Kind::kPolyline;
    c.first = std::uint32_t(points_.size());
    c.count = std::uint32_t(points.size());
    c.color = color;
    points_.insert(points_.end(), points.begin(), points.end());
}

void DrawList::drawPolygon(std::span<const Vec2> points, Color color) {
    drawPolyline(points, color);
    commands_.back().kind = Command::Kind::kPolygon;
}

void DrawList::fillPolygon(std::span<const Vec2> points, Color color) {
    drawPolyline(points, color);
    commands_.back().kind = Command::Kind::kFillPolygon;
    largestPolygon_ = std::max(largestPolygon_, std::uint32_t(points.size()));
}

void DrawList::fillCircle(const Vec2& centre, double radius, Color color) {
    Command& c = add();
    c.kind = Command::Kind::kFillCircle;
    c.a = centre;
    c.radius = radius;
    c.color = color;
}

void DrawList::drawCircle(const Vec2& centre, double radius, Color color) {
    fillCircle(centre, radius, color);
    commands_.back().kind = Command::Kind::kDrawCircle;
}

void DrawList::drawText(std::string_view text, int x, int y, int scale, Color color) {
    Command& c = add();
    c.kind = Command::Kind::kText;
    c.first = std::uint32_t(text_.size());
    c.count = std::uint32_t(text.size());
    c.x = x;
    c.y = y;
    c.scale = scale;
    c.color = color;
    text_.append(text);
}

void DrawList::drawRows(Canvas& canvas, int rowBegin, int rowEnd, std::vector<double>& crossings) const {
    using Kind = Command::Kind;
    const detail::RowClip rows{rowBegin, rowEnd};
    const detail::SpanKernel kernel = detail::activeSpanKernel().kernel;
    // The rows each command may touch are read from their own array, so a band passes over the
    // commands it does not cross without reading them.
    for (std::size_t k = 0; k < commands_.size(); ++k) {
        if (rows_[k].begin >= rowEnd || rows_[k].end <= rowBegin) continue;
        const Command& c = commands_[k];
        const std::span<const Vec2> points(points_.data() + c.first, c.count);
        switch (c.kind) {
            case Kind::kClear:
                detail::clear(canvas, rows, c.color);
                break;
            case Kind::kSetPixel:
                detail::setPixel(canvas, rows, c.x, c.y, c.color);
                break;
            case Kind::kBlendPixel:
                detail::blendPixel(canvas, rows, c.x, c.y, c.color);
                break;
            case Kind::kSprite:
                detail::drawPrepared(canvas, rows, prepared_[c.first], kernel);
                break;
            case Kind::kFillRect:
                detail::fillRect(canvas, rows, c.x, c.y, c.w, c.h, c.color);
                break;
            case Kind::kDrawRect:
                detail::drawRect(canvas, rows, c.x, c.y, c.w, c.h, c.color);
                break;
            case Kind::kLine:
                detail::drawLine(canvas, rows, c.a, c.b, c.color);
                break;
            case Kind::kPolyline:
                detail::drawPolyline(canvas, rows, points, c.color);
                break;
            case Kind::kPolygon:
                detail::drawPolygon(canvas, rows, points, c.color);
                break;
            case Kind::kFillPolygon:
                detail::fillPolygon(canvas, rows, points, c.color, crossings);
                break;
            case Kind::kFillCircle:
                detail::fillCircle(canvas, rows, c.a, c.radius, c.color);
                break;
            case Kind::kDrawCircle:
                detail::drawCircle(canvas, rows, c.a, c.radius, c.color);
                break;
            case Kind::kText:
                detail::drawText(canvas, rows, std::string_view(text_).substr(c.first, c.count), c.x, c.y,
                                 c.scale, c.color);
                break;
        }
    }
}

void DrawList::prepareSprites(const Canvas& canvas, TaskSystem* tasks) const {
    prepared_.resize(sprites_.size());
    struct Job {
        const DrawList* list;
        const Canvas* canvas;
    } job{this, &canvas};
    auto prepare = [](std::uint32_t begin, std::uint32_t end, std::uint32_t, void* context) {
        const Job& j = *static_cast<const Job*>(context);
        const DrawList& list = *j.list;
        for (std::uint32_t s = begin; s < end; ++s) {
            const std::uint32_t k = list.sprites_[s];
            const Command& c = list.commands_[k];
            detail::PreparedSprite& sprite = list.prepared_[s];
            // A sprite that draws nothing crosses no band.
            if (detail::prepareSprite(*j.canvas, *c.image, c.toCanvas, c.style, sprite))
                list.rows_[k] = {sprite.rowBegin, sprite.rowEnd};
            else
                list.rows_[k] = {0, 0};
        }
    };
    const auto count = std::uint32_t(sprites_.size());
    if (tasks && tasks->workerCount() > 1)
        runTask(*tasks, prepare, count, kMinPrepareRange, &job);
    else
        prepare(0, count, 0, &job);
}

void DrawList::draw(Canvas& canvas, TaskSystem* tasks) const {
    const std::uint32_t workers = tasks ? tasks->workerCount() : 1;
    if (crossings_.size() < workers) crossings_.resize(workers);
    for (std::vector<double>& buffer : crossings_) buffer.reserve(largestPolygon_);
    // Bands: a sprite is set up once (prepareSprites), but every band it crosses walks the command
    // list and clips it again, so bands are as tall as they can be, but no taller than
    // kBandsPerWorker per worker (for balance; the thread pool alone would cut 16 per worker) and
    // than kBandBytes of canvas,
    // so that a band's pixels stay in a core's L2 cache while its sprites are drawn (one band of a
    // whole 1280×720 frame is 3.7 MB: its rows leave the cache between sprites).
    const std::uint32_t rows = std::uint32_t(canvas.height());
    const std::uint32_t rowBytes = std::uint32_t(std::max(1, canvas.width())) * 4;
    const std::uint32_t bandRows =
        std::max({kMinBandRows, std::min(kBandBytes / rowBytes, rows / (workers * kBandsPerWorker))});
    using Clock = std::chrono::steady_clock;
    const Clock::time_point start = timing_ ? Clock::now() : Clock::time_point{};
    prepareSprites(canvas, tasks);
    const Clock::time_point prepared = timing_ ? Clock::now() : Clock::time_point{};
    drawBands(canvas, tasks, rows, bandRows);
    if (timing_) {
        auto nanoseconds = [](Clock::duration d) {
            return std::uint64_t(std::chrono::duration_cast<std::chrono::nanoseconds>(d).count());
        };
        times_.setupNanoseconds = nanoseconds(prepared - start);
        times_.bandsNanoseconds = nanoseconds(Clock::now() - prepared);
    }
}

void DrawList::drawBands(Canvas& canvas, TaskSystem* tasks, std::uint32_t rows,
                         std::uint32_t bandRows) const {
    if (!tasks || tasks->workerCount() == 1) {
        for (std::uint32_t begin = 0; begin < rows; begin += bandRows)
            drawRows(canvas, int(begin), int(std::min(rows, begin + bandRows)), crossings_[0]);
        return;
    }
    struct Job {
        const DrawList* list;
        Canvas* canvas;
    } job{this, &canvas};
    runTask(
        *tasks,
        [](std::uint32_t begin, std::uint32_t end, std::uint32_t worker, void* context) {
            const Job& j = *static_cast<const Job*>(context);
            j.list->drawRows(*j.canvas, int(begin), int(end), j.list->crossings_[worker]);
        },
        rows, bandRows, &job);
}

}  // namespace polar::render
