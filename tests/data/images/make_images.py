#!/usr/bin/python3
# Writes the sprite of tests/engine/platform/image_formats_test.cpp in every format the platform
# layer reads, into this folder: Debian's python3-pil for most, ImageMagick's `convert` for XPM,
# and a few lines here for QOI, SVG and GIMP's XCF, which neither writes. The files are committed;
# run this again (from anywhere) only to change them. Each format's rule, which the test applies to
# sprite.png's pixels to get what the decoded file must hold, is in the comment beside it.
import os
import struct
import subprocess

from PIL import Image

HERE = os.path.dirname(os.path.abspath(__file__))
SIZE = 16

# Four 8×8 quarters: opaque red, transparent, half-transparent green, opaque blue; and one white
# pixel in the red quarter, so a shift or a flip shows.
RED, CLEAR, GREEN, BLUE, WHITE = (200, 40, 30, 255), (0, 0, 0, 0), (30, 180, 60, 128), (20, 60, 220, 255), (255, 255, 255, 255)


def sprite():
    image = Image.new("RGBA", (SIZE, SIZE))
    for y in range(SIZE):
        for x in range(SIZE):
            image.putpixel((x, y), [[RED, CLEAR], [GREEN, BLUE]][y // 8][x // 8])
    image.putpixel((2, 3), WHITE)
    return image


def path(name):
    return os.path.join(HERE, name)


def keyed(image):
    """The sprite with one-bit alpha: transparent where it was, every other pixel opaque."""
    out = image.copy()
    out.putdata([(r, g, b, 0 if a == 0 else 255) for r, g, b, a in image.getdata()])
    return out


def qoi(image):
    """QOI (qoiformat.org): the header, then every pixel as a QOI_OP_RGBA chunk, then the end."""
    data = b"qoif" + struct.pack(">IIBB", image.width, image.height, 4, 0)
    for r, g, b, a in image.getdata():
        data += bytes([0xFF, r, g, b, a])
    return data + bytes(7) + b"\x01"


def svg(image):
    """An SVG of 1×1 squares at whole pixels, so rasterising them covers each pixel whole."""
    rects = []
    for y in range(image.height):
        for x in range(image.width):
            r, g, b, a = image.getpixel((x, y))
            if a:
                rects.append(f'<rect x="{x}" y="{y}" width="1" height="1" fill="#{r:02x}{g:02x}{b:02x}"'
                             + (f' fill-opacity="{a / 255:.6f}"' if a != 255 else "") + "/>")
    return (f'<svg xmlns="http://www.w3.org/2000/svg" width="{image.width}" height="{image.height}">\n'
            + "\n".join(rects) + "\n</svg>\n").encode()


def rle_channel(data):
    """One channel of an XCF tile in GIMP's run-length code: a byte n up to 126 then a value
    repeats it n + 1 times; a byte n from 129 then 256 - n values copies them."""
    out, at = b"", 0
    while at < len(data):
        run = 1
        while at + run < len(data) and data[at + run] == data[at] and run < 127:
            run += 1
        if run >= 2:
            out += bytes([run - 1, data[at]])
            at += run
            continue
        end = at + 1  # a literal, up to the next pair of equal values
        while end < len(data) and end - at < 127 and not (end + 1 < len(data) and data[end] == data[end + 1]):
            end += 1
        out += bytes([256 - (end - at)]) + data[at:end]
        at = end
    return out


def xcf(image):
    """GIMP's XCF, version 0 (32-bit offsets, as GIMP 2.8 writes): an RGB image holding one
    visible, opaque RGBA layer at 0,0 of the image's size, RLE-compressed in one 64×64 tile (the
    sprite fits). Each property is an id, a length and its data; a list ends with PROP_END."""
    PROP_END, PROP_OPACITY, PROP_VISIBLE, PROP_OFFSETS, PROP_COMPRESSION = 0, 6, 8, 15, 17
    RGB_IMAGE, RGBA_LAYER, RLE = 0, 1, 1

    def prop(kind, payload=b""):
        return struct.pack(">II", kind, len(payload)) + payload

    w, h = image.size
    name = b"sprite\0"
    header = (b"gimp xcf file\0" + struct.pack(">III", w, h, RGB_IMAGE)
              + prop(PROP_COMPRESSION, bytes([RLE])) + prop(PROP_END))
    layer_at = len(header) + 12  # after the layer list (one offset, then 0) and the channel list (0)
    layer = (struct.pack(">III", w, h, RGBA_LAYER) + struct.pack(">I", len(name)) + name
             + prop(PROP_OPACITY, struct.pack(">I", 255)) + prop(PROP_VISIBLE, struct.pack(">I", 1))
             + prop(PROP_OFFSETS, struct.pack(">ii", 0, 0)) + prop(PROP_END))
    hierarchy_at = layer_at + len(layer) + 8  # after the hierarchy and mask offsets
    hierarchy = struct.pack(">III", w, h, 4)  # 4 bytes a pixel
    level_at = hierarchy_at + len(hierarchy) + 8  # after one level offset and its ending 0
    level = struct.pack(">II", w, h)
    tile_at = level_at + len(level) + 8  # after one tile offset and its ending 0
    pixels = image.tobytes()  # R, G, B, A for each pixel, row by row
    tile = b"".join(rle_channel(pixels[c::4]) for c in range(4))  # each channel whole, in turn
    return (header + struct.pack(">II", layer_at, 0) + struct.pack(">I", 0)
            + layer + struct.pack(">II", hierarchy_at, 0)
            + hierarchy + struct.pack(">II", level_at, 0)
            + level + struct.pack(">II", tile_at, 0)
            + tile)


def main():
    s = sprite()
    s.save(path("sprite.png"))                                   # the truth
    s.save(path("sprite.tga"))                                   # exact (32-bit, raw)
    s.save(path("sprite-rle.tga"), compression="tga_rle")        # exact (32-bit, run-length)
    s.save(path("sprite.tif"))                                   # exact (RGBA, unassociated alpha)
    s.save(path("sprite.webp"), lossless=True, exact=True)       # exact (lossless)
    open(path("sprite.qoi"), "wb").write(qoi(s))                 # exact
    open(path("sprite.xcf"), "wb").write(xcf(s))                 # exact once premultiplied
    s.save(path("sprite-32.bmp"))                                # exact (32-bit with alpha)
    open(path("sprite.svg"), "wb").write(svg(s))                 # exact (whole-pixel squares)
    rgb = s.convert("RGB")                                       # no alpha: opaque, colours kept
    rgb.save(path("sprite.bmp"))
    rgb.save(path("sprite.pcx"))
    rgb.save(path("sprite.ppm"))
    rgb.save(path("sprite.jpg"), quality=100, subsampling=0)     # no alpha, and lossy: near
    k = keyed(s)                                                 # colour key: 0 or opaque
    k.save(path("sprite.gif"), transparency=0, optimize=False)
    k.save(path("keyed.png"))
    subprocess.run(["convert", path("keyed.png"), "xpm:" + path("sprite.xpm")], check=True)
    os.remove(path("keyed.png"))
    # A GIF whose name says PNG: read as the GIF it is.
    k.save(path("gif-named.png"), format="GIF", transparency=0, optimize=False)


if __name__ == "__main__":
    main()
