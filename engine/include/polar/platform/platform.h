#pragma once
// Polarcade's platform layer on one page: the only part of the engine that talks to the operating
// system (through SDL2, SDL2_image and libpng, which stay inside it: including this needs none of
// their headers).
//
// Window           auto w = Window::open({"Title", canvasW, canvasH, scale});  → Result<unique_ptr>
//                  while (auto e = w->pollEvent()) { if (std::holds_alternative<QuitRequested>(*e)) … }
//                  w->present(canvas);  w->toggleFullscreen();  w->windowToCanvas(x, y)
//                  Window::fit(cw, ch, ww, wh)  (whole-pixel scaling, letterboxed)
//                  Window::displayProblem()  (why a window would not be seen, if it would not)
// Input state      w->keyHeld(Key::Left)  (by position);  w->gamepads();
//                  w->gamepadButton(pad, GamepadButton::A);  w->gamepadAxis(pad, GamepadAxis::LeftX)
// Events           QuitRequested, KeyPressed/KeyReleased {key, position, mods, repeat}, TextEntered,
//                  MouseButtonPressed/Released, MouseMoved, MouseWheelScrolled, GamepadConnected/
//                  Disconnected, GamepadButtonPressed/Released, GamepadAxisMoved, WindowResized
// Key names        keyName(Key::PageUp) → "page-up";  keyFromName("f12") → Key::F12  (for scripts)
// Audio            auto d = AudioDevice::open({44100, 1, 512}, [](float* out, int frames) { … });
//                  d->start();  d->pause();  d->sampleRate()
// Image files      loadRgbaImage(path) → RgbaImage (PNG, GIF, WebP, TGA, BMP, JPEG, TIFF, …)
// PNG files        loadPng(path) → RgbaImage;  savePng(rgbaImage, path);  encodePng(rgbaImage)
//                  loadImage(path) → render::Image;  loadCanvas(path);  savePng(canvas, path)
// Folders          userDataFolder("org", "app") → "/home/me/.local/share/app/"
// Frame loop       runFrames([&] { …one frame…; return FrameResult{exit, idleSeconds}; })
//                  (a loop on the desktop, requestAnimationFrame in a browser)
#include "polar/platform/audio_device.h"
#include "polar/platform/events.h"
#include "polar/platform/image_file.h"
#include "polar/platform/main_loop.h"
#include "polar/platform/png_io.h"
#include "polar/platform/system.h"
#include "polar/platform/window.h"
