#!/usr/bin/env bash
# soak render --denoise (pictures only): the flag reaches the filter and says so,
# and the filter keeps a furnace's identity: a Lambertian sphere of albedo 0.5
# under a uniform sky of radiance 1 sends back exactly 0.5 from every point
# (one bounce, then the sky), so its pixels stay 0.5 and the sky's 1 through
# the filter, to what the silhouette leaks. Without the flag nothing is filtered.
. "$(dirname "$0")/lib.bash"

dir=$SOAK_TMP/render_denoise
rm -rf "$dir" && mkdir -p "$dir"
cat > "$dir/furnace.json" <<'EOF'
{"render": {"width": 64, "height": 64, "spp": 4},
 "camera": {"position": [0, -4, 0], "look_at": [0, 0, 0], "fov": 60},
 "environment": {"type": "constant", "radiance": 1},
 "materials": {"m": {"type": "lambert", "albedo": 0.5}},
 "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "m"}]}
EOF
expect_exit 0 "render --denoise" -- "$SOAK" render "$dir/furnace.json" -o "$dir/d.exr" --denoise --threads 2
grep -q "denoised (a picture, not numbers): 0 fireflies removed" "$SOAK_TMP/last.out" \
  && ok "--denoise reports itself (no firefly in a furnace)" || bad "--denoise line missing: $(cat "$SOAK_TMP/last.out")"
expect_exit 0 "render without --denoise" -- "$SOAK" render "$dir/furnace.json" -o "$dir/r.exr" --threads 2
grep -q "denoised" "$SOAK_TMP/last.out" && bad "a plain render says it was denoised" || ok "a plain render is not denoised"
if ! command -v oiiotool > /dev/null; then skip "oiiotool not on PATH" "pixel values"; finish; fi
# pixel X Y FILE: mean of its RGB
pixel() { oiiotool --dumpdata "$3" 2>/dev/null | awk -v p="Pixel ($1, $2):" 'index($0, p) { print ($(NF-2) + $(NF-1) + $NF) / 3; exit }'; }
close "$(pixel 32 32 "$dir/d.exr")" 0.5 1e-5 "sphere's centre pixel, denoised = albedo x sky"
close "$(pixel 27 37 "$dir/d.exr")" 0.5 1e-5 "a pixel inside the silhouette, denoised"
# The sky 24 px from the silhouette: 1e-4, since the silhouette's pixels (part
# sphere, part sky, labelled sky by their centre ray) pass a little of their
# colour on through the filter's later, wider passes (measured 9e-6).
close "$(pixel 0 0 "$dir/d.exr")" 1 1e-4 "the sky's corner pixel, denoised"
finish
