"""Frames of `soak bake rain --frames` on the bas-relief as a strip
(docs/images/rain_frames_relief.png): the film thickness and the wetness at
the given times, from DIR/film_T.tif and DIR/wet_T.tif (32-bit float TIFF,
written by bench_rain_frames.sh). Usage: plot_rain_frames.py DIR T..."""
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from PIL import Image  # noqa: E402

folder, times = sys.argv[1], [int(t) for t in sys.argv[2:]]
fig, axes = plt.subplots(2, len(times), figsize=(2.6 * len(times), 3.3), constrained_layout=True)
for col, t in enumerate(times):
    film = np.array(Image.open(f"{folder}/film_{t}.tif")) * 1e6
    wet = np.array(Image.open(f"{folder}/wet_{t}.tif"))
    phase = "rain" if t <= 600 else f"{t - 600} s after"
    fi = axes[0, col].imshow(film, cmap="viridis", vmin=0, vmax=60, extent=(0, 2.6, 0, 1.3))
    wi = axes[1, col].imshow(wet, cmap="gray", vmin=0, vmax=1, extent=(0, 2.6, 0, 1.3))
    axes[0, col].set_title(f"t = {t} s ({phase})", fontsize=9)
    for r in range(2):
        axes[r, col].set_xticks([])
        axes[r, col].set_yticks([])
axes[0, 0].set_ylabel("film, um", fontsize=9)
axes[1, 0].set_ylabel("wetness", fontsize=9)
fig.colorbar(fi, ax=axes[0, :], shrink=0.8, label="um")
fig.colorbar(wi, ax=axes[1, :], shrink=0.8)
fig.suptitle("soak bake rain --frames: the bas-relief in 10 min of 6 mm/h from the front, then draining", fontsize=10)
fig.savefig(f"{folder}/rain_frames_relief.png", dpi=80)
