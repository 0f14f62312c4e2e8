#!/usr/bin/env bash
# soak bake ripples -o r.%04d.png stores what it claims: RGB = (n + 1) / 2 and
# alpha = the height, unassociated (straight) as PNG defines its alpha. The
# PNG is decoded here by its specification (zlib + scanline filters, in
# Python), independently of OpenImageIO, and compared with the 32-bit EXR of
# the same frame: every channel within half a 16-bit step (+1e-6), and the
# decoded normals unit length within the 16-bit quantisation (4e-4). Before
# the fix OIIO divided RGB by alpha on writing (normals up to 0.73 too long).
. "$(dirname "$0")/lib.bash"

D="$SOAK_TMP/ripples_png"
rm -rf "$D"
mkdir -p "$D"
command -v python3 >/dev/null || { skip "python3 not on PATH" "decoding the PNG"; finish; }
command -v oiiotool >/dev/null || { skip "oiiotool not on PATH" "reading the EXR"; finish; }

R=(bake ripples --width 48 --tile 0.2 --loop-frames 4 --period 0.4 --rate 40 --frames 2-2)
expect_exit 0 "ripples as PNG" -- "$SOAK" "${R[@]}" -o "$D/r.%04d.png"
expect_exit 0 "ripples as float EXR" -- "$SOAK" "${R[@]}" --float -o "$D/r.%04d.exr"
oiiotool --dumpdata "$D/r.0002.exr" >"$D/exr.txt" || bad "oiiotool cannot read the EXR"

python3 - "$D/r.0002.png" "$D/exr.txt" >"$D/report" <<'PY'
import re, struct, sys, zlib

def decode_png(path):
    data = open(path, "rb").read()
    assert data[:8] == b"\x89PNG\r\n\x1a\n", "not a PNG"
    pos, idat, ihdr = 8, b"", None
    while pos < len(data):
        n, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + n]
        if kind == b"IHDR":
            ihdr = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            idat += body
        pos += 12 + n
    w, h, depth, colour = ihdr[:4]
    assert depth == 16 and colour == 6, "want 16-bit RGBA, got depth %d colour type %d" % (depth, colour)
    raw, bpp, stride = zlib.decompress(idat), 8, w * 8
    rows, prev = [], bytearray(stride)
    for y in range(h):
        f, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - bpp] if i >= bpp else 0
            b, c = prev[i], prev[i - bpp] if i >= bpp else 0
            if f == 1: line[i] = (line[i] + a) & 255
            elif f == 2: line[i] = (line[i] + b) & 255
            elif f == 3: line[i] = (line[i] + (a + b) // 2) & 255
            elif f == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append([v / 65535.0 for v in struct.unpack(">%dH" % (w * 4), bytes(line))])
        prev = line
    return w, h, rows

w, h, rows = decode_png(sys.argv[1])
exr = {}
for line in open(sys.argv[2]):
    m = re.match(r"\s*Pixel \((\d+), (\d+)\):\s*(.*)", line)
    if m:
        exr[(int(m.group(1)), int(m.group(2)))] = [float(v) for v in m.group(3).split()]
worst_ch, worst_len = 0.0, 0.0
for y in range(h):
    for x in range(w):
        p, e = rows[y][4 * x:4 * x + 4], exr[(x, y)]
        worst_ch = max(worst_ch, max(abs(p[k] - min(max(e[k], 0.0), 1.0)) for k in range(4)))
        n = [2 * p[k] - 1 for k in range(3)]
        worst_len = max(worst_len, abs(sum(v * v for v in n) ** 0.5 - 1))
print(len(exr) == w * h, worst_ch, worst_len)
PY
read -r all_read worst_ch worst_len <"$D/report"
[ "$all_read" = True ] && ok "the EXR has every texel of the PNG" || bad "EXR and PNG sizes differ: $(cat "$D/report")"
close "$worst_ch" 0 "$(awk 'BEGIN { printf "%.9g", 0.5 / 65535 + 1e-6 }')" "PNG channels = EXR channels (straight alpha), worst"
close "$worst_len" 0 4e-4 "PNG normals (2 RGB - 1) unit length, worst | |n| - 1 |"
finish
