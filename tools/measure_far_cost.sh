#!/usr/bin/env bash
# What far plants cost against the Godot-native way (docs/performance.md, "Far plants against the
# native way"): the demo's recording mode from 40 m outside and from 25 m up at 45° over the large
# field (113 000 plants), calm, no draw distance, the sun's shadows off (the pixels' work alone), at
# 480 × 270 under Xvfb (Vulkan lavapipe, which shades on the CPU), drawn by the addon and by the
# native baseline (demo_project/scripts/native_baseline.gd: whole plants near, one Y-billboard quad
# with the front view far), and by the native baseline with its far quads' alpha test hashed
# (--baseline native-hashed: the far field keeps its cover). Prints primitives, draw calls and the
# software frame time (medians of the last 5 of 9 frames) of each, the ratios, and the share of each
# picture that is plant (green over blue: 0 % with no impostor drawn), the pixels the far plants'
# shaders shade.
#   tools/measure_far_cost.sh [MAP]     (default res://fields/large.field)
set -euo pipefail
repo=$(cd "$(dirname "$0")/.." && pwd)
"$repo/tools/build.sh" >/dev/null
out="$repo/build/bench/far_cost"
mkdir -p "$out"
map=${1:-res://fields/large.field}
frames=9
for view in outside40 above45; do
  for way in ours native native-hashed; do
    baseline=()
    [[ $way != ours ]] && baseline=(--baseline "$way")
    RESOLUTION=480x270 "$repo/tools/demo_recording.sh" "$out/${view}_$way.log" "$out/${view}_$way.json" --map "$map" \
      --view "$view" --wind 0 --no-hud --frames "$frames" --draw-distance 0 --shadows off \
      --screenshot "$out/${view}_$way.png" "${baseline[@]}" ||
      { echo "measure_far_cost: the run $view/$way failed; see $out/${view}_$way.log" >&2; exit 1; }
    printf '.' >&2
  done
done
echo >&2
"$repo/.cache/venv/bin/python" - "$out" "$map" <<'PY'
import json, statistics, sys
import numpy
from PIL import Image
out, map_path = sys.argv[1], sys.argv[2]
print(f"{map_path}, calm, no draw distance, no shadows, 480 × 270; medians of the last 5 frames")
print()
def plant_share(path):
    rgb = numpy.asarray(Image.open(path).convert("RGB")).astype(int)
    return ((rgb[..., 1] > 1.25 * rgb[..., 2]) & (rgb[..., 1] > 60)).mean()
print("| view | primitives ours / native | draw calls ours / native | software frame ours / native / native hashed "
      "| ratio to native / to hashed | plant in the picture ours / native / native hashed |")
print("|---|---|---|---|---|---|")
ways = ("ours", "native", "native-hashed")
for view, name in (("outside40", "40 m outside"), ("above45", "45° from 25 m")):
    runs = [json.load(open(f"{out}/{view}_{way}.json")) for way in ways]
    p = [s["primitives"]["median"] for s in runs]
    d = [s["draw_calls"]["median"] for s in runs]
    t = [statistics.median(s["frame_times_ms"][-5:]) for s in runs]
    c = [plant_share(f"{out}/{view}_{way}.png") for way in ways]
    print(f"| {name} | {p[0] / 1e3:.0f} k / {p[1] / 1e3:.0f} k | {d[0]:.0f} / {d[1]:.0f} "
          f"| {t[0]:.0f} / {t[1]:.0f} / {t[2]:.0f} ms | {t[0] / t[1]:.2f}× / {t[0] / t[2]:.2f}× "
          f"| {100 * c[0]:.0f} / {100 * c[1]:.0f} / {100 * c[2]:.0f} % |")
PY
