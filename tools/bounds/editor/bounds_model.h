#pragma once
// The bounds being edited, with undo and redo, and what gen and check would say about them.
#include <optional>
#include <string>
#include <vector>

#include "polar/authoring/alpha_mask.h"
#include "polar/authoring/bounds_gen.h"
#include "polar/bounds_file.h"

namespace polar::bounds_tool::editor {

// The sprite the bounds belong to, as the generator and the checks see it.
struct SpriteAlpha {
    AlphaMask mask;
    std::uint8_t threshold = AlphaMask::kDefaultThreshold;
    bool container = false;  // bounds that hold objects inside (gen --container)
    PixelSet opaque;         // PixelSet::opaque(mask, threshold)
};

// What gen and check say about one state of the bounds.
struct BoundsReport {
    std::vector<FitQuality> quality;    // per radii, in file order
    std::vector<std::string> lines;     // per radii, as gen prints them (qualityLine)
    std::vector<std::string> warnings;  // as check prints them (warningLine), placed in the saved file
};

// A BoundsSpec under edit: every change is one step that undo takes back.
//
// Why whole snapshots? A bounds file is a few dozen numbers, so keeping each state is cheaper to
// get right than inverse operations, and "unsaved" is simply "differs from the state on disk".
// Every state held here is valid (Bound::check passes for each bound): an edit that
// would break a rule is refused before it reaches the model.
class BoundsModel {
  public:
    // `onDisk`: what the file holds now, or nothing when there is no valid file there.
    BoundsModel(BoundsSpec start, std::optional<BoundsSpec> onDisk);

    const BoundsSpec& spec() const { return spec_; }
    // The runtime radii of spec() (buildBounds).
    const BoundsPtr& bounds() const { return bounds_; }
    // Replaces the spec as one undoable step; false (and nothing changes) when `next` is invalid or
    // equal to the current spec.
    bool commit(const BoundsSpec& next);
    // Shows `preview` without making it a step (a drag in progress); commit or cancelPreview ends it.
    bool preview(const BoundsSpec& next);
    void cancelPreview();
    bool previewing() const { return previewing_; }
    // Back to the state before the last step, or forward again; false when there is none.
    bool undo();
    bool redo();
    // True when the spec differs from what the file holds.
    bool dirty() const;
    // The spec is now what the file holds (after a save).
    void markSaved() { onDisk_ = spec_; }

    // The first rule `spec` breaks, as "radii K: what", or nothing when it is valid.
    static std::optional<std::string> problem(const BoundsSpec& spec);

  private:
    void show(const BoundsSpec& spec);

    BoundsSpec spec_;
    BoundsSpec committed_;  // spec_ unless previewing
    BoundsPtr bounds_;
    bool previewing_ = false;
    std::optional<BoundsSpec> onDisk_;
    std::vector<BoundsSpec> undo_, redo_;
};

// True when the two specs hold the same numbers in the same order.
bool sameSpec(const BoundsSpec& a, const BoundsSpec& b);

// The opaque pixels each bound answers for: all of them for one bound; with several, each pixel
// goes to the bound whose outline holds it most deeply (least |p − c| / r(φ), p its centre).
std::vector<PixelSet> pixelsPerBound(const SpriteAlpha& sprite, const Bounds& bounds);

// gen's fit report and check's warnings for `spec`; warnings name `boundsPath` with the line and
// column they would have in the file as saved.
BoundsReport reportOn(const BoundsSpec& spec, const Bounds& bounds, const SpriteAlpha& sprite,
                      const std::string& boundsPath);

}  // namespace polar::bounds_tool::editor
