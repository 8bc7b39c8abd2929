"""Reads an 8-bit PNG (no external packages: zlib and the PNG filters) and prints its size and how many
pixels are dark (max channel < 128) and how many distinct colours it has; or compares two images.
usage: python3 png_pixels.py FILE.png  ->  "WIDTH HEIGHT DARK COLOURS"
       python3 png_pixels.py --diff A.png B.png  ->  "LARGEST_CHANNEL_DIFFERENCE PIXELS_THAT_DIFFER" """
import struct
import sys
import zlib


def read_png(path):
    data = open(path, "rb").read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        raise SystemExit("not a PNG: " + path)
    pos, idat, palette = 8, b"", None
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            width, height, depth, ctype, _, _, interlace = struct.unpack(">IIBBBBB", body)
        elif kind == b"PLTE":
            palette = [tuple(body[i:i + 3]) for i in range(0, len(body), 3)]
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    if depth != 8 or interlace:
        raise SystemExit("only 8-bit non-interlaced PNGs: " + path)
    channels = {0: 1, 2: 3, 3: 1, 4: 2, 6: 4}[ctype]
    raw = zlib.decompress(idat)
    stride = width * channels
    rows, prev, pos = [], bytearray(stride), 0
    for _ in range(height):
        ftype, line = raw[pos], bytearray(raw[pos + 1:pos + 1 + stride])
        pos += 1 + stride
        for i in range(stride):
            a = line[i - channels] if i >= channels else 0
            b = prev[i]
            c = prev[i - channels] if i >= channels else 0
            if ftype == 1:
                line[i] = (line[i] + a) & 255
            elif ftype == 2:
                line[i] = (line[i] + b) & 255
            elif ftype == 3:
                line[i] = (line[i] + (a + b) // 2) & 255
            elif ftype == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(line)
        prev = line
    pixels = []
    for line in rows:
        for x in range(width):
            px = line[x * channels:(x + 1) * channels]
            if ctype == 3:
                pixels.append(palette[px[0]])
            elif ctype in (0, 4):
                pixels.append((px[0],) * 3)
            else:
                pixels.append(tuple(px[:3]))
    return width, height, pixels


if __name__ == "__main__":
    if sys.argv[1] == "--diff":
        (wa, ha, a), (wb, hb, b) = read_png(sys.argv[2]), read_png(sys.argv[3])
        if (wa, ha) != (wb, hb):
            raise SystemExit("sizes differ: %dx%d and %dx%d" % (wa, ha, wb, hb))
        d = [max(abs(x - y) for x, y in zip(p, q)) for p, q in zip(a, b)]
        print(max(d), sum(1 for v in d if v))
    else:
        w, h, px = read_png(sys.argv[1])
        print(w, h, sum(1 for p in px if max(p) < 128), len(set(px)))
