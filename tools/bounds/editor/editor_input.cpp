// The input mapping: which key or gesture does which action. Events come from a Window or from a
// script alike, and this is the only place that reads them.
#include <cmath>

#include "editor/editor.h"

namespace polar::bounds_tool::editor {

using namespace platform;

const std::vector<std::string>& editorKeys() {
    static const std::vector<std::string> keys = {
        "wheel               zoom in or out (whole pixels), about the pointer",
        "middle drag         pan (or Space + drag); Home fits the sprite in view",
        "drag a handle       move a sample: its angle and radius",
        "click the outline   add a sample there (on the selected radii)",
        "Delete, Backspace   remove the selected sample",
        "drag a centre       move that radii's centre",
        "Tab, Shift+Tab      select the next or previous radii",
        "N, X                add a radii at the pointer, remove the selected radii",
        "I                   toggle interpolate for the selected radii",
        "F, Shift+F          fit from alpha: the selected radii, or all (as gen)",
        "T, Shift+T          tighten the selected sample, or every sample of the radii",
        "P, Shift+P          the next or previous partner sprite (or none)",
        "drag the partner    move it; right drag turns it; Shift+wheel scales it",
        ", .  - =  arrows    turn the partner 5 deg (Shift: 1), scale it, nudge it",
        "1 ... 6             accuracy: bounds circle nearest chord all-radii exact",
        "Ctrl+Z              undo; Ctrl+Shift+Z or Ctrl+Y redo",
        "Ctrl+S              save (atomically, as gen writes)",
        "F12                 screenshot; H or F1 this list; Esc quit",
    };
    return keys;
}

void Editor::handle(const Event& event) {
    if (const auto* key = std::get_if<KeyPressed>(&event)) {
        keyPressed(*key);
    } else if (const auto* key = std::get_if<KeyReleased>(&event)) {
        if (key->position == Key::Space) spaceHeld_ = false;
        if (key->position == Key::LeftShift || key->position == Key::RightShift) shiftHeld_ = false;
    } else if (const auto* press = std::get_if<MouseButtonPressed>(&event)) {
        moved(press->canvas);
        buttonPressed(*press);
    } else if (const auto* release = std::get_if<MouseButtonReleased>(&event)) {
        moved(release->canvas);
        buttonReleased(*release);
    } else if (const auto* motion = std::get_if<MouseMoved>(&event)) {
        moved(motion->canvas);
    } else if (const auto* scroll = std::get_if<MouseWheelScrolled>(&event)) {
        wheel(scroll->dy);
    } else if (std::holds_alternative<QuitRequested>(event)) {
        closeRequested();
    }
    refresh();
}

void Editor::closeRequested() {
    if (!model_.dirty()) {
        finished_ = true;
        return;
    }
    asking_ = true;
    say("unsaved changes: S save and quit, D discard them and quit, Esc keep editing", true);
}

void Editor::keyPressed(const KeyPressed& press) {
    const Key key = press.key;
    const bool ctrl = (press.mods & kModCtrl) != 0, shift = (press.mods & kModShift) != 0;
    if (press.position == Key::Space) spaceHeld_ = true;
    if (press.position == Key::LeftShift || press.position == Key::RightShift) shiftHeld_ = true;
    if (asking_) {
        if (key == Key::S) {
            save();
            if (!model_.dirty()) finished_ = true;
        } else if (key == Key::D) {
            finished_ = true;
        } else if (key == Key::Escape) {
            say("kept editing");
        } else {
            return;
        }
        asking_ = false;
        return;
    }
    if (ctrl) {
        if (key == Key::Z && shift)
            redo();
        else if (key == Key::Z)
            undo();
        else if (key == Key::Y)
            redo();
        else if (key == Key::S)
            save();
        return;
    }
    if (drag_ != Drag::None && drag_ != Drag::Pan) return;  // no edits while a handle is held
    switch (key) {
        case Key::Delete:
        case Key::Backspace:
            deleteSample();
            break;
        case Key::Tab:
            selectRadii(radii_ + (shift ? model_.spec().radii.size() - 1 : 1));
            say("radii " + std::to_string(radii_ + 1) + " of " + std::to_string(model_.spec().radii.size()));
            break;
        case Key::N:
            addRadii();
            break;
        case Key::X:
            removeRadii();
            break;
        case Key::I:
            toggleInterpolate();
            break;
        case Key::F:
            fitFromAlpha(shift);
            break;
        case Key::T:
            tighten(shift);
            break;
        case Key::P:
            choosePartner(shift ? -1 : 1);
            break;
        case Key::Comma:
            turnPartner(shift ? 1 : 5);
            break;
        case Key::Period:
            turnPartner(shift ? -1 : -5);
            break;
        case Key::Minus:
            scalePartner(1 / 1.1);
            break;
        case Key::Equals:
            scalePartner(1.1);
            break;
        case Key::Left:
        case Key::Right:
        case Key::Up:
        case Key::Down: {
            const double step = shift ? 0.25 : 1.0;
            const Vec2 d = key == Key::Left    ? Vec2(-step, 0)
                           : key == Key::Right ? Vec2(step, 0)
                           : key == Key::Up    ? Vec2(0, step)
                                               : Vec2(0, -step);
            partnerPlace_.translate(d);
            break;
        }
        case Key::Num1:
        case Key::Num2:
        case Key::Num3:
        case Key::Num4:
        case Key::Num5:
        case Key::Num6:
            accuracy_ = kAllAccuracies[static_cast<int>(key) - static_cast<int>(Key::Num1)];
            say(std::string("accuracy: ") + accuracyName(accuracy_));
            break;
        case Key::Home:
            resetView();
            break;
        case Key::H:
        case Key::F1:
            showKeys_ = !showKeys_;
            break;
        case Key::F12:
            screenshotRequested_ = true;
            break;
        case Key::Escape:
            if (showKeys_)
                showKeys_ = false;
            else
                closeRequested();
            break;
        default:
            break;
    }
}

void Editor::buttonPressed(const MouseButtonPressed& press) {
    if (drag_ != Drag::None || asking_) return;
    const Vec2 at = press.canvas;
    if (!inDrawing(at)) return;
    dragFrom_ = at;
    cornerAtDragStart_ = corner_;
    if (press.button == MouseButton::Middle || (press.button == MouseButton::Left && spaceHeld_)) {
        drag_ = Drag::Pan;
        return;
    }
    if (press.button == MouseButton::Right) {
        if (onPartner(at)) {
            drag_ = Drag::PartnerTurn;
            const Vec2 c = toCanvas(partnerPlace_.position());
            turnFrom_ = trig::atan2(-(at.y() - c.y()), at.x() - c.x());
        }
        return;
    }
    if (press.button != MouseButton::Left) return;
    if (auto hit = sampleUnder(at)) {
        if (hit->first != radii_) selectRadii(hit->first);
        sample_ = hit->second;
        drag_ = Drag::Sample;
        return;
    }
    if (auto centre = centreUnder(at)) {
        if (*centre != radii_) selectRadii(*centre);
        drag_ = Drag::Centre;
        return;
    }
    if (onOutline(at)) {
        addSampleAt(at);
        return;
    }
    if (onPartner(at)) {
        drag_ = Drag::PartnerMove;
        return;
    }
    sample_.reset();
}

void Editor::buttonReleased(const MouseButtonReleased& release) {
    const bool ends = (drag_ == Drag::Pan &&
                       (release.button == MouseButton::Middle || release.button == MouseButton::Left)) ||
                      (drag_ == Drag::PartnerTurn && release.button == MouseButton::Right) ||
                      ((drag_ == Drag::Sample || drag_ == Drag::Centre || drag_ == Drag::PartnerMove) &&
                       release.button == MouseButton::Left);
    if (!ends) return;
    if (drag_ == Drag::Sample || drag_ == Drag::Centre) {
        if (model_.previewing()) {
            const BoundsSpec dragged = model_.spec();
            model_.commit(dragged);  // the whole drag is one undo step
        }
    }
    drag_ = Drag::None;
}

void Editor::moved(const Vec2& at) {
    const Vec2 before = pointer_;
    pointer_ = at;
    switch (drag_) {
        case Drag::Pan:
            corner_ = cornerAtDragStart_ +
                      Vec2(std::round(at.x() - dragFrom_.x()), std::round(at.y() - dragFrom_.y()));
            break;
        case Drag::Sample:
            moveSampleTo(at);
            break;
        case Drag::Centre:
            moveCentreTo(at);
            break;
        case Drag::PartnerMove:
            partnerPlace_.translate((at - before).cwiseProduct(Vec2(1, -1)) / zoom_);
            break;
        case Drag::PartnerTurn: {
            const Vec2 c = toCanvas(partnerPlace_.position());
            const double now = trig::atan2(-(at.y() - c.y()), at.x() - c.x());
            partnerPlace_.rotate(now - turnFrom_);
            turnFrom_ = now;
            break;
        }
        case Drag::None:
            break;
    }
}

void Editor::wheel(double notches) {
    if (notches == 0 || !inDrawing(pointer_)) return;
    if (shiftHeld_ && partner_ > 0) {
        scalePartner(notches > 0 ? 1.1 : 1 / 1.1);
        return;
    }
    zoomAt(zoom_ + (notches > 0 ? 1 : -1) * std::max(1, zoom_ / 8), pointer_);
}

}  // namespace polar::bounds_tool::editor
