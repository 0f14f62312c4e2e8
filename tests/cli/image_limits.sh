#!/usr/bin/env bash
# Image inputs bounded before work (issue 21, items 2 and 4): a PNG whose
# header claims 16000 x 16000 from ~250 KB of deflate (a decompression bomb,
# 42 s and 5.4 GB before) is refused from its header by the compression-ratio
# rule of soak/image.h; a folder or a FIFO given as an image is refused by
# what it is, before it is opened (a FIFO used to block); a uniform mask far
# below the rule's floor is still read.
set -u
. "$(dirname "$0")/lib.bash"
D="$SOAK_TMP/image_limits"
rm -rf "$D" && mkdir -p "$D"
python3 - "$D" <<'PY'
import struct, sys, zlib
def png(path, w, h):
    def chunk(t, d):
        return struct.pack(">I", len(d)) + t + d + struct.pack(">I", zlib.crc32(t + d) & 0xffffffff)
    c = zlib.compressobj(9)
    row = b"\0" * (w + 1)  # filter byte + w grey samples
    data = b"".join(c.compress(row) for _ in range(h)) + c.flush()
    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 0, 0, 0, 0)) +
                chunk(b"IDAT", data) + chunk(b"IEND", b""))
png(sys.argv[1] + "/bomb.png", 16000, 16000)
png(sys.argv[1] + "/mask.png", 512, 512)
PY
size=$(stat -c %s "$D/bomb.png")
expect_exit 1 "16000x16000 PNG of $size bytes as a mask" -- "$SOAK" bake drying "$D/bomb.png" --time 0.5 -o "$D/o.png"
expect_stderr "bomb\.png: the PNG header claims 16000x16000x1 pixels \(976 MiB as float\) from [0-9]+ bytes of pixel data \(IDAT\)" \
  "the bomb is refused from its header with the numbers"
expect_exit 0 "a uniform 512x512 mask is read" -- "$SOAK" bake drying "$D/mask.png" --time 0.5 -o "$D/o.png"
mkdir -p "$D/folder.png"
expect_exit 1 "a folder as a mask" -- "$SOAK" bake drying "$D/folder.png" --time 0.5 -o "$D/o2.png"
expect_stderr "folder\.png: cannot read this image: it is a folder, not a regular file" "a folder is called a folder"
rm -f "$D/fifo.png" && mkfifo "$D/fifo.png"
expect_exit 1 "a FIFO as a mask (no blocking open)" -- timeout 120 "$SOAK" bake drying "$D/fifo.png" --time 0.5 -o "$D/o2.png"
expect_stderr "fifo\.png: cannot read this image: it is a FIFO \(pipe\), not a regular file" "a FIFO is refused as not a regular file"
finish
