#pragma once
// Polarcade's software renderer on one page. Include this and you have all of it.
//
// Spaces (every function says which one it takes):
//   world   y up, the game's units; objects are placed by their Transform, M = T·R·S.
//   bound   a sprite's own space: origin at the image centre, one unit per image pixel, y up.
//   canvas  y down, pixels; pixel (x, y) is [x, x+1) × [y, y+1), its centre (x + ½, y + ½).
// Compose like SFML's render states: view.matrix() * transform.matrix() maps bound → canvas, and
// a parent's matrix goes in between (view · parent · child).
//
// Canvas           Canvas canvas(w, h);  canvas.clear(color);  canvas.pixel(x, y);
//                  canvas.setPixel(x, y, c);  canvas.blendPixel(x, y, c);
//                  Canvas::wrap(pixels, w, h, pitchBytes)  (memory someone else owns)
// Colours          Color{r, g, b, a} (straight alpha), kBlack, kWhite, kRed, …, c.withAlpha(a)
// Images           Result<Image> loadImage("ship.png");  Image::fromCanvas(canvas);
//                  Image img(w, h); img.setPixel(x, y, c)
// Files            savePng(canvas, "out.png") → optional<Error> (atomic);  loadCanvas("a.png")
//                  (polar/platform/image_file.h: PNG files go through the platform layer)
// Camera           View view(w, h); view.setCentre(p); view.setZoom(z);
//                  view.matrix(), view.toCanvas(world), view.toWorld(canvasPoint);
//                  transformPoint(m, p)
// Sprites          drawSprite(canvas, img, canvasCentre)                   upright, unscaled
//                  drawSprite(canvas, img, view, transform)                 a world object
//                  drawSprite(canvas, img, toCanvas)                        any bound → canvas matrix
//                  drawSprite(canvas, img, toCanvas, {tint, opacity})       modulated
// Shapes (canvas)  fillRect(canvas, x, y, w, h, c);  drawRect(…)
//                  drawLine(canvas, a, b, c);  drawPolyline(canvas, pts, c)
//                  drawPolygon(canvas, pts, c);  fillPolygon(canvas, pts, c)
//                  drawCircle(canvas, centre, r, c);  fillCircle(canvas, centre, r, c)
// Text (canvas)    drawText(canvas, "SCORE 100", x, y, scale, c);  measureText(text, scale)
// Draw lists       DrawList list;  list.reset();  list.drawSprite(img, view, transform);  list.drawText(…)
//                  (every call above as a member, without the canvas), then list.draw(canvas, tasks):
//                  bands of rows on a TaskSystem (null: this thread), the same bytes at any count
//
// Everything clips exactly at the canvas edges and blends premultiplied "over" with integer
// arithmetic, so a picture is the same bytes on every compiler and machine.
#include "polar/render/canvas.h"
#include "polar/render/color.h"
#include "polar/render/draw_list.h"
#include "polar/render/image.h"
#include "polar/render/shapes.h"
#include "polar/render/sprite.h"
#include "polar/render/text.h"
#include "polar/render/view.h"
