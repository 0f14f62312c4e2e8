"""Screenshots of Blender under Xvfb from the X server's own frame buffer
(`Xvfb -fbdir DIR` writes DIR/Xvfb_screen0): Blender 4.x and 5.x under
Xvfb/llvmpipe read a black front buffer, so the screenshot scripts of this
folder crop their pictures out of that file instead."""
import struct

import bpy


def read_xwd(path):
    """(width, height, rows of (r, g, b) bytes top first) of an Xvfb -fbdir
    frame buffer file (XWD, 24-bit TrueColor, 32 bits per pixel)."""
    with open(path, "rb") as f:
        raw = f.read()
    h = struct.unpack(">25I", raw[:100])
    size, width, height, byte_order, bpp, stride, ncolors = h[0], h[4], h[5], h[7], h[11], h[12], h[19]
    if bpp != 32:
        raise SystemExit(f"{path}: {bpp} bits per pixel, expected 32 (Xvfb -screen 0 WxHx24)")
    start = size + 12 * ncolors
    rows = []
    for y in range(height):
        line = raw[start + y * stride:start + y * stride + 4 * width]
        if byte_order == 0:      # LSBFirst: B G R X
            rgb = bytes(b for i in range(0, len(line), 4) for b in (line[i + 2], line[i + 1], line[i]))
        else:
            rgb = bytes(b for i in range(0, len(line), 4) for b in (line[i + 1], line[i + 2], line[i + 3]))
        rows.append(rgb)
    return width, height, rows


def save_rect(fb, x0, top, width, height, path):
    """Writes the width x height rectangle of the frame buffer file fb whose
    top left pixel is (x0, top) (X rows counted from the top) to the PNG
    path, clipped to the screen; returns the (width, height) written."""
    screen_w, screen_h, rows = read_xwd(fb)
    width, height = min(width, screen_w - x0), min(height, screen_h - top)
    img = bpy.data.images.new("xwd_shot", width, height)
    px = []
    for y in range(height - 1, -1, -1):                       # Blender rows from the bottom
        line = rows[top + y]
        for x in range(x0, x0 + width):
            px += [line[3 * x] / 255.0, line[3 * x + 1] / 255.0, line[3 * x + 2] / 255.0, 1.0]
    img.pixels[:] = px
    img.filepath_raw = path
    img.file_format = "PNG"
    img.save()
    return width, height
