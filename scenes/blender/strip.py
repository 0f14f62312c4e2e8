"""Frames of one size side by side in a PNG, 4-pixel white gaps between
them (rain_frames.py, rain_runnels.py)."""
import bpy


def save_strip(paths, out, w, h, gap=4):
    img = bpy.data.images.new("strip", len(paths) * w + (len(paths) - 1) * gap, h)
    px = [1.0] * (img.size[0] * h * 4)
    for k, path in enumerate(paths):
        src = list(bpy.data.images.load(path).pixels)
        x0 = k * (w + gap)
        for y in range(h):
            row = 4 * (y * img.size[0] + x0)
            px[row:row + 4 * w] = src[4 * y * w:4 * (y + 1) * w]
    img.pixels[:] = px
    img.filepath_raw = out
    img.file_format = "PNG"
    img.save()
