#pragma once
// polarcade-bounds edit: the editor's state, its actions, and the one input pipeline into them.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "editor/bounds_model.h"
#include "polar/accuracy.h"
#include "polar/authoring/pixel_truth.h"
#include "polar/platform/events.h"
#include "polar/render/canvas.h"
#include "polar/render/image.h"
#include "polar/transform.h"

namespace polar::bounds_tool::editor {

// A sprite the edited bounds can be tested against.
struct Partner {
    std::string name;  // as shown: "same sprite" or the logical path "sprites/rock-large-1.png"
    render::Image image;
    std::shared_ptr<const OpaquePixels> pixels;
    BoundsPtr bounds;  // null: the bounds being edited (the same sprite)
};

// Everything the editor starts from.
struct EditorSetup {
    std::string boundsPath;  // where Ctrl+S writes
    render::Image image;
    SpriteAlpha sprite;
    BoundsSpec start;                  // the file's bounds, or gen's fit
    std::optional<BoundsSpec> onDisk;  // the file's bounds when it held valid ones
    std::string loadProblem;           // why the file was not used (its file:line:column message)
    std::vector<Partner> partners;     // in the order P cycles through them
};

// The bounds editor, without a window: events in (handle), a picture out (draw).
//
// Why no window here? Everything the modder does arrives as a platform::Event, from a Window or
// from a script, and goes through handle(); so a test that replays events exercises exactly the
// code a person does, and draw() gives the picture a person sees. The main loop (edit.cpp) only
// moves events and pictures between this class and a Window or files.
class Editor {
  public:
    static constexpr int kWidth = 960;  // the canvas
    static constexpr int kHeight = 600;
    static constexpr int kDrawingWidth = 680;  // the sprite's area; the panel is right of it
    static constexpr int kTop = 14;            // the message line above the drawing
    static constexpr int kBottom = 24;         // the help lines below it
    static constexpr int kMaxZoom = 64;

    explicit Editor(EditorSetup setup);

    // The one input pipeline: a key, mouse or window event, from a person or a script.
    void handle(const platform::Event& event);
    // The editor as it looks now, on a kWidth × kHeight canvas.
    void draw(render::Canvas& canvas) const;
    // True once the modder has closed the editor (after answering the unsaved-changes question).
    bool finished() const { return finished_; }
    // True (once) when the modder asked for a screenshot (F12); the caller writes it.
    bool takeScreenshotRequest();
    // Shows a line in the message bar (the main loop reports saved screenshots with it).
    void say(const std::string& message, bool problem = false);

    // The window's title: the file, and whether it has unsaved changes.
    std::string title() const;

  private:
    enum class Drag { None, Pan, Sample, Centre, PartnerMove, PartnerTurn };

    // Input (editor_input.cpp).
    void keyPressed(const platform::KeyPressed& key);
    void buttonPressed(const platform::MouseButtonPressed& press);
    void buttonReleased(const platform::MouseButtonReleased& release);
    void moved(const Vec2& at);
    void wheel(double notches);
    void closeRequested();

    // Actions (editor.cpp): each one undoable edit, or a change of what is shown.
    void selectRadii(std::size_t k);
    void moveSampleTo(const Vec2& canvas);
    void moveCentreTo(const Vec2& canvas);
    void addSampleAt(const Vec2& canvas);
    void deleteSample();
    void addRadii();
    void removeRadii();
    void toggleInterpolate();
    void fitFromAlpha(bool all);
    void tighten(bool wholeRadii);
    void undo();
    void redo();
    void save();
    void zoomAt(int zoom, const Vec2& canvas);
    void resetView();
    void choosePartner(int step);
    void turnPartner(double degrees);
    void scalePartner(double factor);
    void edit(const BoundsSpec& next, const std::string& done);

    // What the pointer is over.
    std::optional<std::pair<std::size_t, std::size_t>> sampleUnder(const Vec2& canvas) const;
    std::optional<std::size_t> centreUnder(const Vec2& canvas) const;
    bool onOutline(const Vec2& canvas) const;
    bool onPartner(const Vec2& canvas) const;
    bool inDrawing(const Vec2& canvas) const;

    // The canvas point of bound-space point p, and back; bound space → canvas, homogeneous.
    Vec2 toCanvas(const Vec2& p) const;
    Vec2 toBound(const Vec2& canvas) const;
    Mat3 matrix() const;

    // Keeps the selection, the report and the partner verdicts in step with the model.
    void refresh();
    void refreshPartner();

    // Drawing (editor_draw.cpp).
    void drawScene(render::Canvas& scene) const;
    void drawPanel(render::Canvas& canvas) const;

    EditorSetup setup_;
    BoundsModel model_;
    BoundsReport report_;
    BoundsSpec reportedSpec_;  // the spec report_ was made for

    // The view: sprite pixel edges on canvas pixel edges, `corner_` the canvas pixel of the
    // sprite's top-left corner, zoom_ whole canvas pixels per sprite pixel.
    int zoom_ = 1;
    Vec2 corner_ = Vec2::Zero();

    std::size_t radii_ = 0;              // the selected radii (file order)
    std::optional<std::size_t> sample_;  // its selected sample (file order)

    Drag drag_ = Drag::None;
    Vec2 pointer_ = Vec2::Zero();
    Vec2 dragFrom_ = Vec2::Zero();
    Vec2 cornerAtDragStart_ = Vec2::Zero();
    double turnFrom_ = 0.0;
    bool spaceHeld_ = false;
    bool shiftHeld_ = false;

    int partner_ = 0;  // 0: none; k: setup_.partners[k − 1]
    Transform partnerPlace_;
    Accuracy accuracy_ = Accuracy::Bounds;
    bool ruleHit_ = false;
    bool pixelsHit_ = false;
    std::vector<Vec2> overlapOwn_;      // bound-space centres of own pixels overlapping the partner's
    std::vector<Vec2> overlapPartner_;  // partner-space centres of the partner's pixels overlapping
    bool overlapSkipped_ = false;       // too many pixels to mark within kHighlightBudget
    static constexpr double kHighlightBudget = 4e7;  // pixel-pair looks per refresh
    std::shared_ptr<const OpaquePixels> ownPixels_;

    std::string message_;
    bool messageIsProblem_ = false;
    bool asking_ = false;  // the unsaved-changes question is up
    bool showKeys_ = false;
    bool finished_ = false;
    bool screenshotRequested_ = false;
};

// Every key and mouse gesture, one per line, as the help overlay and --help show them.
const std::vector<std::string>& editorKeys();

}  // namespace polar::bounds_tool::editor
