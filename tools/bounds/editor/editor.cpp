// The editor's actions: each edit builds the next BoundsSpec and hands it to the model, which
// refuses invalid ones; the generator, the checks, the pair test and the pixel truth are the
// engine's and the authoring library's own.
#include "editor/editor.h"

#include <algorithm>
#include <cmath>

#include "polar/bound_outline.h"
#include "polar/collision.h"
#include "polar/game_object.h"
#include "polar/render/view.h"
#include "polar/world.h"

namespace polar::bounds_tool::editor {
namespace {

// Angles as the editor writes them: tenths of a degree in [0, 360); radii in thousandths of a
// pixel (gen's precision), at least 0.01.
double writtenDegrees(double radians) {
    double d = std::round(reduceDegrees(radians * 180.0 / kPi) * 10.0) / 10.0;
    return d >= 360.0 ? d - 360.0 : d;
}
double writtenRadius(double r) {
    return std::max(0.01, std::round(r * 1000.0) / 1000.0);
}

// The smallest radius in (0, r] for sample `j` of radii `k` whose fit misses by no more than
// `allowed`: the miss only grows as one sample moves in, so bisection finds it.
double tightestRadius(BoundsSpec spec, std::size_t k, std::size_t j, const PixelSet& pixels, bool container,
                      double allowed) {
    auto missAt = [&](double r) {
        spec.radii[k].samples[j][1] = r;
        const BoundSpec& s = spec.radii[k];
        if (Bound::check(s.samples, s.interpolate)) return 1e300;
        return measureFit(pixels, Bound::fromDegrees(s.centre, s.samples, s.interpolate), container)
            .worstMiss;
    };
    double high = spec.radii[k].samples[j][1], low = 0.0;
    if (container) {
        // A container's sample moves out, toward the wall, as far as the free space allows.
        low = high;
        high = 4.0 * (spec.radii[k].samples[j][1] + pixels.width + pixels.height);
        for (int i = 0; i < 40; ++i) {
            const double mid = 0.5 * (low + high);
            (missAt(mid) <= allowed ? low : high) = mid;
        }
        return std::floor(low * 1000.0) / 1000.0;
    }
    for (int i = 0; i < 40; ++i) {
        const double mid = 0.5 * (low + high);
        (missAt(mid) <= allowed ? high : low) = mid;
    }
    return std::ceil(high * 1000.0) / 1000.0;
}

}  // namespace

Editor::Editor(EditorSetup setup) : setup_(std::move(setup)), model_(setup_.start, setup_.onDisk) {
    ownPixels_ = std::make_shared<const OpaquePixels>(setup_.sprite.mask, setup_.sprite.threshold);
    resetView();
    if (!setup_.loadProblem.empty())
        say(setup_.loadProblem + "  (showing gen's fit; the file is kept)", true);
    refresh();
}

void Editor::say(const std::string& message, bool problem) {
    message_ = message;
    messageIsProblem_ = problem;
}

bool Editor::takeScreenshotRequest() {
    const bool asked = screenshotRequested_;
    screenshotRequested_ = false;
    return asked;
}

std::string Editor::title() const {
    return "polarcade-bounds edit: " + setup_.boundsPath + (model_.dirty() ? " (unsaved)" : "");
}

Mat3 Editor::matrix() const {
    const double z = zoom_;
    const Vec2 o = corner_ + z * Vec2(setup_.sprite.mask.width / 2.0, setup_.sprite.mask.height / 2.0);
    Mat3 m;
    m << z, 0, o.x(), 0, -z, o.y(), 0, 0, 1;
    return m;
}

Vec2 Editor::toCanvas(const Vec2& p) const {
    return render::transformPoint(matrix(), p);
}

Vec2 Editor::toBound(const Vec2& canvas) const {
    const double z = zoom_;
    const Vec2 o = corner_ + z * Vec2(setup_.sprite.mask.width / 2.0, setup_.sprite.mask.height / 2.0);
    return Vec2((canvas.x() - o.x()) / z, (o.y() - canvas.y()) / z);
}

void Editor::resetView() {
    const int w = std::max(setup_.sprite.mask.width, 1), h = std::max(setup_.sprite.mask.height, 1);
    const int areaHeight = kHeight - kTop - kBottom;
    // The largest whole zoom that shows the sprite with room around it for the outline and a partner.
    zoom_ = std::clamp(std::min(kDrawingWidth / (2 * w), 2 * areaHeight / (3 * h)), 1, kMaxZoom);
    corner_ = Vec2(std::floor((kDrawingWidth - zoom_ * w) / 2.0),
                   std::floor(kTop + (areaHeight - zoom_ * h) / 2.0));
}

void Editor::zoomAt(int zoom, const Vec2& canvas) {
    zoom = std::clamp(zoom, 1, kMaxZoom);
    if (zoom == zoom_) return;
    // Keep the sprite point under the pointer where it is, to the nearest whole canvas pixel.
    const Vec2 under = toBound(canvas);
    zoom_ = zoom;
    const Vec2 now = toCanvas(under);
    corner_ += Vec2(std::round(canvas.x() - now.x()), std::round(canvas.y() - now.y()));
    say("zoom " + std::to_string(zoom_) + "x");
}

void Editor::edit(const BoundsSpec& next, const std::string& done) {
    if (std::optional<std::string> problem = BoundsModel::problem(next)) {
        say("not done: " + *problem, true);
        return;
    }
    if (model_.commit(next)) say(done);
}

void Editor::selectRadii(std::size_t k) {
    radii_ = k % model_.spec().radii.size();
    sample_.reset();
}

void Editor::moveSampleTo(const Vec2& canvas) {
    if (!sample_) return;
    BoundsSpec next = model_.spec();
    BoundSpec& r = next.radii[radii_];
    const Vec2 d = toBound(canvas) - r.centre;
    if (d.norm() < 1e-9) return;
    r.samples[*sample_] = {writtenDegrees(trig::atan2(d.y(), d.x())), writtenRadius(d.norm())};
    if (!model_.preview(next)) {
        const std::string why = *BoundsModel::problem(next);
        say("that far would break a rule (" + why + "); kept the last valid place", true);
        return;
    }
    const DegreeSample& s = r.samples[*sample_];
    char text[96];
    std::snprintf(text, sizeof text, "sample %zu: %.1f deg, radius %.3f px", *sample_ + 1, s[0], s[1]);
    say(text);
}

void Editor::moveCentreTo(const Vec2& canvas) {
    BoundsSpec next = model_.spec();
    const Vec2 c = toBound(canvas);
    next.radii[radii_].centre = Vec2(std::round(c.x() * 100.0) / 100.0, std::round(c.y() * 100.0) / 100.0);
    if (model_.preview(next)) {
        char text[96];
        std::snprintf(text, sizeof text, "radii %zu: centre (%.2f, %.2f)", radii_ + 1,
                      next.radii[radii_].centre.x(), next.radii[radii_].centre.y());
        say(text);
    }
}

void Editor::addSampleAt(const Vec2& canvas) {
    BoundsSpec next = model_.spec();
    BoundSpec& r = next.radii[radii_];
    const Vec2 d = toBound(canvas) - r.centre;
    const double phi = trig::atan2(d.y(), d.x());
    // The outline's own radius there, so the new handle sits on the outline where it was clicked.
    const DegreeSample added{writtenDegrees(phi), writtenRadius((*model_.bounds())[radii_].radius(phi))};
    // Placed among the file's samples before the first one with a larger angle (ascending files
    // stay ascending).
    std::size_t at = r.samples.size();
    for (std::size_t j = 0; j < r.samples.size(); ++j)
        if (reduceDegrees(r.samples[j][0]) > added[0]) {
            at = j;
            break;
        }
    r.samples.insert(r.samples.begin() + static_cast<std::ptrdiff_t>(at), added);
    const std::size_t before = model_.spec().radii[radii_].samples.size();
    char done[64];
    std::snprintf(done, sizeof done, "added a sample at %.1f deg", added[0]);
    edit(next, done);
    if (model_.spec().radii[radii_].samples.size() > before) sample_ = at;
}

void Editor::deleteSample() {
    if (!sample_) {
        say("no sample selected: click a handle first", true);
        return;
    }
    BoundsSpec next = model_.spec();
    std::vector<DegreeSample>& samples = next.radii[radii_].samples;
    if (samples.size() <= 1) {
        say("not done: a radii keeps at least one sample (X removes the whole radii)", true);
        return;
    }
    samples.erase(samples.begin() + static_cast<std::ptrdiff_t>(*sample_));
    const std::size_t was = *sample_;
    edit(next, "deleted sample " + std::to_string(was + 1));
    if (model_.spec().radii[radii_].samples.size() == samples.size()) sample_.reset();
}

void Editor::addRadii() {
    BoundsSpec next = model_.spec();
    BoundSpec r;
    r.centre = toBound(pointer_);
    if (!inDrawing(pointer_)) r.centre = Vec2::Zero();
    r.centre = Vec2(std::round(r.centre.x() * 100.0) / 100.0, std::round(r.centre.y() * 100.0) / 100.0);
    r.interpolate = true;
    const double radius =
        writtenRadius(std::max(2.0, std::min(setup_.sprite.mask.width, setup_.sprite.mask.height) / 6.0));
    for (int i = 0; i < 8; ++i) r.samples.push_back({45.0 * i, radius});
    next.radii.push_back(r);
    edit(next, "added radii " + std::to_string(next.radii.size()) + " (8 samples; F fits it to its pixels)");
    selectRadii(model_.spec().radii.size() - 1);
}

void Editor::removeRadii() {
    if (model_.spec().radii.size() <= 1) {
        say("not done: the bounds keep at least one radii", true);
        return;
    }
    BoundsSpec next = model_.spec();
    next.radii.erase(next.radii.begin() + static_cast<std::ptrdiff_t>(radii_));
    edit(next, "removed radii " + std::to_string(radii_ + 1));
    selectRadii(std::min(radii_, model_.spec().radii.size() - 1));
}

void Editor::toggleInterpolate() {
    BoundsSpec next = model_.spec();
    next.radii[radii_].interpolate = !next.radii[radii_].interpolate;
    edit(next,
         "radii " + std::to_string(radii_ + 1) + ": interpolate " +
             (next.radii[radii_].interpolate ? "true (straight edges)" : "false (arcs to the bisectors)"));
}

void Editor::fitFromAlpha(bool all) {
    BoundsGenOptions options;
    options.container = setup_.sprite.container;
    options.threshold = setup_.sprite.threshold;
    BoundsSpec next = model_.spec();
    if (all) {
        options.radii = std::max<int>(1, static_cast<int>(next.radii.size()));
        Result<GeneratedBounds> fit = generateBounds(setup_.sprite.mask, options);
        if (!fit) {
            say("fit from alpha: " + fit.error().what, true);
            return;
        }
        next = fit->spec;
        edit(next, "fit from alpha: all " + std::to_string(next.radii.size()) + " radii, as gen makes them");
        sample_.reset();
        return;
    }
    // The selected radii alone, about its own centre, to the pixels it answers for.
    const PixelSet part = pixelsPerBound(setup_.sprite, *model_.bounds())[radii_];
    AlphaMask mask = setup_.sprite.mask;
    if (!setup_.sprite.container)
        for (std::size_t i = 0; i < mask.alpha.size(); ++i) mask.alpha[i] = part.member[i] ? 255 : 0;
    options.threshold = setup_.sprite.container ? setup_.sprite.threshold : 127;
    options.centre = next.radii[radii_].centre;
    Result<GeneratedBounds> fit = generateBounds(mask, options);
    if (!fit) {
        say("fit from alpha: " + fit.error().what, true);
        return;
    }
    next.radii[radii_] = fit->spec.radii[0];
    edit(next, "fit from alpha: radii " + std::to_string(radii_ + 1) + " about its centre");
    sample_.reset();
}

void Editor::tighten(bool wholeRadii) {
    const std::size_t count = model_.spec().radii[radii_].samples.size();
    if (!wholeRadii && !sample_) {
        say("no sample selected: click a handle, or Shift+T for every sample", true);
        return;
    }
    const PixelSet part = pixelsPerBound(setup_.sprite, *model_.bounds())[radii_];
    const double allowed = report_.quality[radii_].worstMiss + 1e-9;
    BoundsSpec next = model_.spec();
    for (std::size_t j = 0; j < count; ++j) {
        if (!wholeRadii && j != *sample_) continue;
        next.radii[radii_].samples[j][1] =
            tightestRadius(next, radii_, j, part, setup_.sprite.container, allowed);
    }
    edit(next, wholeRadii ? "tightened every sample of radii " + std::to_string(radii_ + 1)
                          : "tightened sample " + std::to_string(*sample_ + 1));
}

void Editor::undo() {
    drag_ = Drag::None;
    say(model_.undo() ? "undone" : "nothing to undo");
}

void Editor::redo() {
    drag_ = Drag::None;
    say(model_.redo() ? "redone" : "nothing to redo");
}

void Editor::save() {
    if (std::optional<Error> error = saveBounds(setup_.boundsPath, model_.spec())) {
        say("not saved: " + error->message(), true);
        return;
    }
    model_.markSaved();
    setup_.loadProblem.clear();
    say("saved " + setup_.boundsPath);
}

void Editor::choosePartner(int step) {
    const int n = static_cast<int>(setup_.partners.size()) + 1;
    partner_ = ((partner_ + step) % n + n) % n;
    if (partner_ > 0) {
        // Beside the sprite on its right, two pixels apart, as turned and scaled before.
        const double halfWidth = setup_.partners[partner_ - 1].image.width() / 2.0;
        const double reach = halfWidth * std::fabs(partnerPlace_.scaleFactors().x());
        partnerPlace_.setPosition(Vec2(setup_.sprite.mask.width / 2.0 + reach + 2.0, 0.0));
    }
    say(partner_ == 0 ? "no partner" : "partner: " + setup_.partners[partner_ - 1].name);
}

void Editor::turnPartner(double degrees) {
    partnerPlace_.rotate(degToRad(degrees));
}

void Editor::scalePartner(double factor) {
    const Vec2 s = partnerPlace_.scaleFactors() * factor;
    if (s.x() < 0.05 || s.x() > 20) return;
    partnerPlace_.setScale(s);
}

std::optional<std::pair<std::size_t, std::size_t>> Editor::sampleUnder(const Vec2& canvas) const {
    const BoundsSpec& spec = model_.spec();
    std::optional<std::pair<std::size_t, std::size_t>> best;
    double bestDistance = 5.0;  // canvas pixels
    // The selected radii first, so its handles win where radii overlap.
    for (std::size_t n = 0; n < spec.radii.size(); ++n) {
        const std::size_t k = (radii_ + n) % spec.radii.size();
        const BoundSpec& r = spec.radii[k];
        for (std::size_t j = 0; j < r.samples.size(); ++j) {
            double s = 0, c = 0;
            trig::sincos(degToRad(reduceDegrees(r.samples[j][0])), s, c);
            const double d = (toCanvas(r.centre + r.samples[j][1] * Vec2(c, s)) - canvas).norm();
            if (d < bestDistance) {
                bestDistance = d;
                best = std::pair(k, j);
            }
        }
        if (best) return best;
    }
    return best;
}

std::optional<std::size_t> Editor::centreUnder(const Vec2& canvas) const {
    const BoundsSpec& spec = model_.spec();
    for (std::size_t n = 0; n < spec.radii.size(); ++n) {
        const std::size_t k = (radii_ + n) % spec.radii.size();
        if ((toCanvas(spec.radii[k].centre) - canvas).norm() <= 6.0) return k;
    }
    return std::nullopt;
}

bool Editor::onOutline(const Vec2& canvas) const {
    const std::vector<Vec2> outline = boundOutline((*model_.bounds())[radii_], matrix());
    for (std::size_t i = 0; i < outline.size(); ++i) {
        const Vec2 a = outline[i], b = outline[(i + 1) % outline.size()];
        const Vec2 ab = b - a;
        const double t =
            ab.squaredNorm() > 0 ? std::clamp((canvas - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0) : 0;
        if ((a + t * ab - canvas).norm() <= 4.0) return true;
    }
    return false;
}

bool Editor::onPartner(const Vec2& canvas) const {
    if (partner_ == 0) return false;
    const Partner& p = setup_.partners[partner_ - 1];
    const Mat3 m = matrix() * partnerPlace_.matrix();
    // q = L⁻¹·(canvas − t) for the 2×2 linear part L = [a b; c d] and translation t.
    const double a = m(0, 0), b = m(0, 1), c = m(1, 0), d = m(1, 1), det = a * d - b * c;
    if (det == 0) return false;
    const Vec2 v = canvas - Vec2(m(0, 2), m(1, 2));
    const Vec2 q((d * v.x() - b * v.y()) / det, (a * v.y() - c * v.x()) / det);
    return std::fabs(q.x()) <= p.image.width() / 2.0 && std::fabs(q.y()) <= p.image.height() / 2.0;
}

bool Editor::inDrawing(const Vec2& canvas) const {
    return canvas.x() >= 0 && canvas.x() < kDrawingWidth && canvas.y() >= kTop &&
           canvas.y() < kHeight - kBottom;
}

void Editor::refresh() {
    const std::size_t count = model_.spec().radii.size();
    if (radii_ >= count) selectRadii(count - 1);
    if (sample_ && *sample_ >= model_.spec().radii[radii_].samples.size()) sample_.reset();
    if (report_.quality.empty() || !sameSpec(reportedSpec_, model_.spec())) {
        report_ = reportOn(model_.spec(), *model_.bounds(), setup_.sprite, setup_.boundsPath);
        reportedSpec_ = model_.spec();
    }
    refreshPartner();
}

void Editor::refreshPartner() {
    overlapOwn_.clear();
    overlapPartner_.clear();
    overlapSkipped_ = false;
    ruleHit_ = pixelsHit_ = false;
    if (partner_ == 0) return;
    const Partner& p = setup_.partners[partner_ - 1];
    // The rule: the world's own pair test on the two objects as they stand.
    GameObject own, other;
    own.bounds = model_.bounds();
    own.flags = kCollisions | (setup_.sprite.container ? kContainer : 0u);
    other.bounds = p.bounds ? p.bounds : model_.bounds();
    other.transform = partnerPlace_;
    other.flags = kCollisions;
    ruleHit_ = testObjects(own, other, accuracy_).hit;

    // The pixel truth, and which pixels of each overlap the other's (a one-pixel sprite placed on
    // each pixel in turn, tested against the whole other sprite).
    const OpaquePixels& mine = *ownPixels_;
    const OpaquePixels& theirs = p.pixels ? *p.pixels : *ownPixels_;
    const Mat2 identity = Mat2::Identity(), linear = partnerPlace_.linear();
    const Vec2 position = partnerPlace_.position();
    pixelsHit_ = opaquePixelsOverlap(mine, Vec2::Zero(), identity, theirs, position, linear);
    if (!pixelsHit_) return;
    static const OpaquePixels unit(AlphaMask{1, 1, {255}}, 0);
    const double stretch = linear.norm();  // ≥ the largest stretch of the map
    const double reach = theirs.boundRadius() * stretch + 1.0;
    const double ownReach = mine.boundRadius() + stretch + 1.0;
    std::vector<Vec2> ownCandidates, theirCandidates;
    for (int y = 0; y < mine.mask().height; ++y)
        for (int x = 0; x < mine.mask().width; ++x)
            if (mine.opaque(x, y) && (mine.mask().pixelCentre(x, y) - position).norm() <= reach)
                ownCandidates.push_back(mine.mask().pixelCentre(x, y));
    for (int y = 0; y < theirs.mask().height; ++y)
        for (int x = 0; x < theirs.mask().width; ++x)
            if (theirs.opaque(x, y) &&
                partnerPlace_.apply(theirs.mask().pixelCentre(x, y)).norm() <= ownReach)
                theirCandidates.push_back(theirs.mask().pixelCentre(x, y));
    // Each candidate costs about one look at every boundary pixel of the other sprite: past the
    // budget (a cave against a cave) the verdict stands but the pixels are not marked.
    const double cost = double(ownCandidates.size()) * double(theirs.boundary().size() + 1) +
                        double(theirCandidates.size()) * double(mine.boundary().size() + 1);
    if (cost > kHighlightBudget) {
        overlapSkipped_ = true;
        return;
    }
    for (const Vec2& c : ownCandidates)
        if (opaquePixelsOverlap(unit, c, identity, theirs, position, linear)) overlapOwn_.push_back(c);
    for (const Vec2& q : theirCandidates)
        if (opaquePixelsOverlap(unit, partnerPlace_.apply(q), linear, mine, Vec2::Zero(), identity))
            overlapPartner_.push_back(q);
}

}  // namespace polar::bounds_tool::editor
