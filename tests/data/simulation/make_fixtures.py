#!/usr/bin/env python3
"""Writes the map-loader fixtures of the simulation tests (run once; the
outputs are committed). Only the standard library: zlib, struct."""
import struct, zlib

def chunk(kind, data):
    c = kind + data
    return struct.pack(">I", len(data)) + c + struct.pack(">I", zlib.crc32(c) & 0xffffffff)

def paeth(a, b, c):
    p = a + b - c
    pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
    return a if pa <= pb and pa <= pc else (b if pb <= pc else c)

def png(path, rows, ctype, depth, bpp, palette=None, corrupt_crc=False, truncate=None):
    """rows: list of raw (unfiltered) byte rows; filters cycle 0..4."""
    raw = b""
    prev = bytes(len(rows[0]))
    for y, row in enumerate(rows):
        f = y % 5
        out = bytearray()
        for i, x in enumerate(row):
            a = row[i - bpp] if i >= bpp else 0
            b = prev[i]
            c = prev[i - bpp] if i >= bpp else 0
            pred = [0, a, b, (a + b) // 2, paeth(a, b, c)][f]
            out.append((x - pred) % 256)
        raw += bytes([f]) + bytes(out)
        prev = row
    width = {0: 8 * len(rows[0]) // depth, 3: 8 * len(rows[0]) // depth,
             2: len(rows[0]) // 3}[ctype]
    data = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, len(rows), depth, ctype, 0, 0, 0))
    if palette:
        data += chunk(b"PLTE", b"".join(bytes(p) for p in palette))
    z = zlib.compress(raw, 9)
    data += chunk(b"IDAT", z[:len(z) // 2]) + chunk(b"IDAT", z[len(z) // 2:]) + chunk(b"IEND", b"")
    if corrupt_crc:
        data = bytearray(data); data[40] ^= 0xff; data = bytes(data)
    if truncate:
        data = data[:truncate]
    open(path, "wb").write(data)

# A 20 x 10 room at 0.1 m: walls on the border (black), free inside (white),
# one unknown (gray 205) cell at column 5, row 2 from the top, and an
# obstacle (black) block at columns 12..13, rows 4..5 from the top.
W, H = 20, 10
def gray(x, y):
    if x in (0, W - 1) or y in (0, H - 1): return 0
    if (x, y) == (5, 2): return 205
    if 12 <= x <= 13 and 4 <= y <= 5: return 0
    return 254
pix = [[gray(x, y) for x in range(W)] for y in range(H)]
open("room.pgm", "wb").write(b"P5\n# room\n%d %d\n255\n" % (W, H) + bytes(v for r in pix for v in r))
open("room_p2.pgm", "w").write("P2\n# room, ASCII\n%d %d\n255\n" % (W, H) +
                                "\n".join(" ".join(str(v) for v in r) for r in pix) + "\n")
png("room.png", [bytes(r) for r in pix], 0, 8, 1)
png("room_rgb.png", [bytes(c for v in r for c in (v, v, v)) for r in pix], 2, 8, 3)
# 1-bit palette: index 0 = black (wall), 1 = white (free); no unknown cell.
def bits(r):
    out = bytearray((len(r) + 7) // 8)
    for i, v in enumerate(r):
        if v: out[i // 8] |= 0x80 >> (i % 8)
    return bytes(out)
png("room_palette.png", [bits([1 if gray(x, y) >= 205 else 0 for x in range(W)]) for y in range(H)],
    3, 1, 1, palette=[(0, 0, 0), (255, 255, 255)])
for name, image in (("room.yaml", "room.pgm"), ("room_png.yaml", "room.png")):
    open(name, "w").write("image: %s\nresolution: 0.1\norigin: [-1.0, -0.5, 0.0]\n"
                          "negate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n" % image)
# Bad files.
png("bad_crc.png", [bytes(r) for r in pix], 0, 8, 1, corrupt_crc=True)
png("truncated.png", [bytes(r) for r in pix], 0, 8, 1, truncate=60)
open("truncated.pgm", "wb").write(b"P5\n20 10\n255\n" + bytes(50))
open("bad_header.pgm", "wb").write(b"P5\n20 x10\n255\n")
open("bad_resolution.yaml", "w").write("image: room.pgm\n# comment\nresolution: fine\n"
                                       "origin: [0.0, 0.0, 0.0]\n")
open("missing_origin.yaml", "w").write("image: room.pgm\nresolution: 0.1\n")
open("bad.walls", "w").write("# walls\nresolution 0.05\nwall 0 0 10 0\nwall 0 0 ten 10\n")
open("room.walls", "w").write("# a 4 x 3 room with a pillar\nresolution 0.05\nthickness 0.1\n"
                              "box 0 0 4 3\nwall 2 1 2 2 0.2\n")
# Known zlib streams for the zlib binding test (as Ada aggregates).
text = b"SANCTA SANCTA SANCTA robots robots robots " * 3
for label, data in (("fixed", zlib.compress(b"hello hello hello hello", 9)),
                    ("dynamic", zlib.compress(text, 9)),
                    ("stored", zlib.compress(b"abc", 0))):
    print(label, len(data), "[" + ", ".join(str(b) for b in data) + "]")
print(len(text))
# A dynamic-Huffman stream (checked below) and its plain text.
plain = b"".join(b"robot %d goes to (%d, %d) at %s speed\n" % (i, i * 7 % 13, i * 11 % 17,
                 [b"low", b"high", b"cruise"][i % 3]) for i in range(200))
packed = zlib.compress(plain, 9)
assert (packed[2] >> 1) & 3 == 2, "expected a dynamic Huffman block"
open("dynamic.txt", "wb").write(plain)
open("dynamic.zz", "wb").write(packed)
for name in ("room.png", "room_rgb.png"):
    d = open(name, "rb").read()
    print(name, "first IDAT block type", (d[8 + 25 + 8 + 2] >> 1) & 3)
