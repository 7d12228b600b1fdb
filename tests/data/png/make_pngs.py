#!/usr/bin/env python3
"""Writes the PNG test set in this folder: one small image for every colour type and bit depth the
PNG specification allows, plain and Adam7-interlaced, each with transparent pixels; two sprites for
`polarcade-bounds gen`; and broken files. tests/engine/platform/png_flavours_test.cpp states, pixel
by pixel, what each must decode to, from the same rules as below (written out there again, so the
test checks the decoder against the rules, not against another decoder).

Every flavour image is 11 x 7 pixels. Pixel (x, y) has index i = 11 * y + x. A sample of n bits is
(i * P[c] + Q[c]) mod (2^n - 1) for channel c (R, G, B, A; grey is channel 0), so it is never the
largest value, 2^n - 1; the border pixels (x or y on the edge) are the transparent ones:
  - grey, RGB: border samples are 2^n - 1 (white), and tRNS names white as transparent;
  - grey+alpha, RGBA: border alpha is 0 (colour from the formula);
  - palette: 2^n entries (181 at 8 bits), entry k coloured (53k + 11, 101k + 23, 197k + 5) mod 256;
    border index 0, others 1 + (i * P[0]) mod (entries - 1); tRNS gives entry 0 alpha 0 and
    entry 1 alpha 128 (2 bits and more), the others none (opaque: tRNS is shorter than PLTE).
At 16 bits two pixels are set apart: (1, 1) has colour samples 0xFFFF except the last, which is
0xFFFE (it differs from the tRNS colour only in the low byte, so it is opaque), and (2, 1) has
colour samples 0x01FF (round(511 * 255 / 65535) = 2, where taking the high byte would give 1).

Rows use filter types 0 to 4 in turn (row r of each pass has type r mod 5), so every filter is
decoded. Run from anywhere: python3 tests/data/png/make_pngs.py
"""
import os
import struct
import zlib

HERE = os.path.dirname(os.path.abspath(__file__))
WIDTH, HEIGHT = 11, 7
P = [4099, 9973, 30011, 1237]
Q = [0, 7, 13, 3]
# (colour type, name, channels, bit depths the specification allows)
FLAVOURS = [
    (0, "grey", 1, [1, 2, 4, 8, 16]),
    (2, "rgb", 3, [8, 16]),
    (3, "palette", 1, [1, 2, 4, 8]),
    (4, "grey-alpha", 2, [8, 16]),
    (6, "rgba", 4, [8, 16]),
]
# Adam7: (first column, first row, column step, row step) of each pass.
ADAM7 = [(0, 0, 8, 8), (4, 0, 8, 8), (0, 4, 4, 8), (2, 0, 4, 4), (0, 2, 2, 4), (1, 0, 2, 2), (0, 1, 1, 2)]


def chunk(kind, data):
    body = kind + data
    return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body) & 0xFFFFFFFF)


def border(x, y, width=WIDTH, height=HEIGHT):
    return x == 0 or y == 0 or x == width - 1 or y == height - 1


def sample(x, y, c, depth):
    i = y * WIDTH + x
    return (i * P[c] + Q[c]) % ((1 << depth) - 1)


def palette_entries(depth):
    return 181 if depth == 8 else 1 << depth


def palette_colour(k):
    return ((k * 53 + 11) % 256, (k * 101 + 23) % 256, (k * 197 + 5) % 256)


def flavour_pixel(colour_type, depth, x, y):
    """The stored samples of pixel (x, y), as a list (a palette index is one sample)."""
    if colour_type == 3:
        if border(x, y):
            return [0]
        return [1 + (y * WIDTH + x) * P[0] % (palette_entries(depth) - 1)]
    colours = 1 if colour_type in (0, 4) else 3
    values = [sample(x, y, c, depth) for c in range(colours)]
    if colour_type in (4, 6):
        values.append(0 if border(x, y) else sample(x, y, 3, depth))
    elif border(x, y):
        values = [(1 << depth) - 1] * colours
    if depth == 16 and (x, y) == (1, 1):
        values[:colours] = [0xFFFF] * (colours - 1) + [0xFFFE]
    if depth == 16 and (x, y) == (2, 1):
        values[:colours] = [0x01FF] * colours
    return values


def pack_row(samples, depth):
    """Samples of one row, packed at `depth` bits (high bits first, 16-bit big-endian)."""
    if depth == 16:
        return b"".join(struct.pack(">H", s) for s in samples)
    if depth == 8:
        return bytes(samples)
    out, bits, used = bytearray(), 0, 0
    for s in samples:
        bits = (bits << depth) | s
        used += depth
        if used == 8:
            out.append(bits)
            bits, used = 0, 0
    if used:
        out.append(bits << (8 - used))
    return bytes(out)


def paeth(a, b, c):
    p = a + b - c
    pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
    if pa <= pb and pa <= pc:
        return a
    return b if pb <= pc else c


def filter_row(kind, row, prior, bpp):
    out = bytearray([kind])
    for j, value in enumerate(row):
        a = row[j - bpp] if j >= bpp else 0
        b = prior[j] if prior else 0
        c = prior[j - bpp] if prior and j >= bpp else 0
        predictor = [0, a, b, (a + b) // 2, paeth(a, b, c)][kind]
        out.append((value - predictor) % 256)
    return bytes(out)


def image_data(pixel, width, height, channels, depth, interlaced):
    """The filtered scanlines of every pass, before compression."""
    bpp = max(1, channels * depth // 8)
    passes = ADAM7 if interlaced else [(0, 0, 1, 1)]
    raw = bytearray()
    for x0, y0, dx, dy in passes:
        columns, rows = range(x0, width, dx), range(y0, height, dy)
        if not columns or not rows:
            continue
        prior = None
        for r, y in enumerate(rows):
            row = pack_row([s for x in columns for s in pixel(x, y)], depth)
            raw += filter_row(r % 5, row, prior, bpp)
            prior = row
    return bytes(raw)


def png(width, height, colour_type, depth, interlaced, pixel, extra_chunks):
    channels = {0: 1, 2: 3, 3: 1, 4: 2, 6: 4}[colour_type]
    header = struct.pack(">IIBBBBB", width, height, depth, colour_type, 0, 0, 1 if interlaced else 0)
    data = zlib.compress(image_data(pixel, width, height, channels, depth, interlaced), 9)
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) + b"".join(extra_chunks) + chunk(b"IDAT", data)
            + chunk(b"IEND", b""))


def flavour_png(colour_type, depth, interlaced):
    extra = []
    if colour_type == 3:
        entries = palette_entries(depth)
        extra.append(chunk(b"PLTE", b"".join(bytes(palette_colour(k)) for k in range(entries))))
        extra.append(chunk(b"tRNS", bytes([0]) if depth == 1 else bytes([0, 128])))
    elif colour_type == 0:
        extra.append(chunk(b"tRNS", struct.pack(">H", (1 << depth) - 1)))
    elif colour_type == 2:
        extra.append(chunk(b"tRNS", struct.pack(">HHH", *[(1 << depth) - 1] * 3)))
    return png(WIDTH, HEIGHT, colour_type, depth, interlaced,
               lambda x, y: flavour_pixel(colour_type, depth, x, y), extra)


# The sprites: a disc of radius 8 about (12, 12) in a 24 x 24 image, grey 60 on white, once as 8-bit
# grey with tRNS making white transparent, and once as 8-bit RGBA with the white's alpha 0.
SPRITE_SIDE = 24


def in_disc(x, y):
    return (x + 0.5 - 12) ** 2 + (y + 0.5 - 12) ** 2 <= 8 * 8


def write(name, data):
    with open(os.path.join(HERE, name), "wb") as f:
        f.write(data)


def main():
    for colour_type, name, _, depths in FLAVOURS:
        for depth in depths:
            for interlaced in (False, True):
                suffix = "-adam7" if interlaced else ""
                write(f"{name}-{depth}{suffix}.png", flavour_png(colour_type, depth, interlaced))

    grey = png(SPRITE_SIDE, SPRITE_SIDE, 0, 8, False, lambda x, y: [60 if in_disc(x, y) else 255],
               [chunk(b"tRNS", struct.pack(">H", 255))])
    write("sprite-grey-trns.png", grey)
    write("sprite-rgba.png", png(SPRITE_SIDE, SPRITE_SIDE, 6, 8, False,
                                 lambda x, y: [60, 60, 60, 255] if in_disc(x, y) else [255, 255, 255, 0], []))

    # Broken files, each from the 8-bit grey flavour.
    good = flavour_png(0, 8, False)
    idat = good.index(b"IDAT")
    length = struct.unpack(">I", good[idat - 4:idat])[0]
    data_end = idat + 4 + length
    os.makedirs(os.path.join(HERE, "broken"), exist_ok=True)
    # A byte of the compressed data changed, the chunk's CRC left as it was.
    bad_crc = bytearray(good)
    bad_crc[idat + 10] ^= 0x01
    write("broken/bad-crc.png", bytes(bad_crc))
    # zlib's Adler-32 (the last 4 bytes of the IDAT data) wrong, the chunk's CRC made right again.
    data = bytearray(good[idat + 4:data_end])
    data[-1] ^= 0xFF
    write("broken/bad-adler.png", good[:idat - 4] + chunk(b"IDAT", bytes(data)) + good[data_end + 4:])
    # The same, with the Adler-32 alone in a second IDAT chunk, as encoders that split IDAT may leave
    # it: libpng then finds the fault only after the last row (and calls it a warning).
    write("broken/bad-adler-split.png", good[:idat - 4] + chunk(b"IDAT", bytes(data[:-4]))
          + chunk(b"IDAT", bytes(data[-4:])) + good[data_end + 4:])
    write("broken/truncated.png", good[:data_end - 20])
    write("broken/not-a-png.png", b"GIF89a\x0b\x00\x07\x00")
    write("broken/empty.png", b"")
    # Sound, but wider than the renderer takes (32767 pixels a side).
    write("broken/too-wide.png", png(40000, 1, 0, 1, False, lambda x, y: [x % 2], []))


if __name__ == "__main__":
    main()
