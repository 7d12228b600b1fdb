#include "editor/bounds_model.h"

#include <cmath>
#include <limits>

#include "bounds_tool.h"
#include "polar/authoring/bounds_check.h"
#include "polar/json_doc.h"

namespace polar::bounds_tool::editor {

bool sameSpec(const BoundsSpec& a, const BoundsSpec& b) {
    if (a.radii.size() != b.radii.size()) return false;
    for (std::size_t k = 0; k < a.radii.size(); ++k) {
        const BoundSpec &x = a.radii[k], &y = b.radii[k];
        if (x.centre != y.centre || x.interpolate != y.interpolate || x.samples != y.samples) return false;
    }
    return true;
}

BoundsModel::BoundsModel(BoundsSpec start, std::optional<BoundsSpec> onDisk) : onDisk_(std::move(onDisk)) {
    assert(!problem(start));
    committed_ = start;
    show(start);
}

std::optional<std::string> BoundsModel::problem(const BoundsSpec& spec) {
    if (spec.radii.empty()) return "no radii; expected at least one";
    for (std::size_t k = 0; k < spec.radii.size(); ++k) {
        const BoundSpec& r = spec.radii[k];
        if (!std::isfinite(r.centre.x()) || !std::isfinite(r.centre.y()))
            return "radii " + std::to_string(k + 1) + ": the centre is not finite";
        if (std::optional<SampleProblem> p = Bound::check(r.samples, r.interpolate))
            return "radii " + std::to_string(k + 1) + ": " + p->what;
    }
    return std::nullopt;
}

void BoundsModel::show(const BoundsSpec& spec) {
    spec_ = spec;
    bounds_ = std::make_shared<const Bounds>(buildBounds(spec_));
}

bool BoundsModel::commit(const BoundsSpec& next) {
    if (problem(next)) return false;
    const bool wasPreviewing = previewing_;
    previewing_ = false;
    if (sameSpec(next, committed_)) {
        if (wasPreviewing) show(committed_);
        return false;
    }
    undo_.push_back(committed_);
    redo_.clear();
    committed_ = next;
    show(next);
    return true;
}

bool BoundsModel::preview(const BoundsSpec& next) {
    if (problem(next)) return false;
    previewing_ = true;
    show(next);
    return true;
}

void BoundsModel::cancelPreview() {
    if (!previewing_) return;
    previewing_ = false;
    show(committed_);
}

bool BoundsModel::undo() {
    cancelPreview();
    if (undo_.empty()) return false;
    redo_.push_back(committed_);
    committed_ = undo_.back();
    undo_.pop_back();
    show(committed_);
    return true;
}

bool BoundsModel::redo() {
    cancelPreview();
    if (redo_.empty()) return false;
    undo_.push_back(committed_);
    committed_ = redo_.back();
    redo_.pop_back();
    show(committed_);
    return true;
}

bool BoundsModel::dirty() const {
    return !onDisk_ || !sameSpec(*onDisk_, spec_);
}

std::vector<PixelSet> pixelsPerBound(const SpriteAlpha& sprite, const Bounds& bounds) {
    if (bounds.size() == 1) return {sprite.opaque};
    std::vector<PixelSet> parts(bounds.size());
    for (PixelSet& part : parts) {
        part.width = sprite.opaque.width;
        part.height = sprite.opaque.height;
        part.member.assign(sprite.opaque.member.size(), 0);
    }
    for (int y = 0; y < sprite.opaque.height; ++y)
        for (int x = 0; x < sprite.opaque.width; ++x) {
            if (!sprite.opaque.has(x, y)) continue;
            const Vec2 p = sprite.mask.pixelCentre(x, y);
            std::size_t best = 0;
            double bestDepth = std::numeric_limits<double>::infinity();
            for (std::size_t k = 0; k < bounds.size(); ++k) {
                const Vec2 d = p - bounds[k].centre();
                const double depth = d.norm() / bounds[k].radius(trig::atan2(d.y(), d.x()));
                if (depth < bestDepth) {
                    bestDepth = depth;
                    best = k;
                }
            }
            parts[best].member[static_cast<std::size_t>(y) * sprite.opaque.width + x] = 1;
        }
    return parts;
}

BoundsReport reportOn(const BoundsSpec& spec, const Bounds& bounds, const SpriteAlpha& sprite,
                      const std::string& boundsPath) {
    BoundsReport report;
    std::vector<PixelSet> parts = pixelsPerBound(sprite, bounds);
    for (std::size_t k = 0; k < bounds.size(); ++k) {
        report.quality.push_back(measureFit(parts[k], bounds[k], sprite.container));
        report.lines.push_back(qualityLine(k, spec.radii[k], report.quality.back(), sprite.container,
                                           sprite.mask.width * sprite.mask.height));
    }
    Result<JsonDoc> doc = JsonDoc::parse(SourceFile{boundsPath, boundsToJson(spec)});
    for (const BoundsWarning& w : suspiciousBounds(spec, sprite.mask, sprite.threshold))
        report.warnings.push_back(warningLine(doc ? doc->errorAt(w.pointer, w.what, w.expected)
                                                  : Error{boundsPath, 0, 0, w.what, w.expected}));
    return report;
}

}  // namespace polar::bounds_tool::editor
