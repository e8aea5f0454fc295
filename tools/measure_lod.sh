#!/usr/bin/env bash
# The far levels against the full-mesh picture: renders five views of a 60 × 60 m field three times
# each (automatic LOD; every plant as mesh 1; the impostors alone, as a mask) with the demo's
# recording mode under Xvfb (Forward+ on Vulkan lavapipe), in calm air, and prints per view the SSIM
# to the full-mesh picture, the mean difference and the impostor region's brightness relative to it
# (tools/measure_lod.py). Pictures go to build/measure/ (look at them side by side).
set -euo pipefail
repo=$(cd "$(dirname "$0")/.." && pwd)
"$repo/tools/build.sh" >/dev/null
godot=$("$repo/tools/find_godot.sh")
out="$repo/build/measure"
mkdir -p "$out"
"$repo/tools/make_field.py" 120 120 "$out/field60.field" >/dev/null
# eye x y z, target x y z: head height inside, 5 m outside, 40 m outside, 25 m up at 45°, 60 m straight down
declare -A views=(
  [inside]="30 1.7 45 30 1.4 20"
  [outside5]="30 1.7 65 30 1.0 30"
  [outside40]="30 1.7 100 30 1.0 30"
  [above45]="30 25 55 30 0 30"
  [down60]="30 60 30.01 30 0 30"
)
names=(inside outside5 outside40 above45 down60)
for view in "${names[@]}"; do
  printf '%s\n%s\n' "${views[$view]}" "${views[$view]}" >"$out/$view.path"
  for mode in auto mesh1 mask; do
    extra=()
    [[ $mode == mesh1 ]] && extra=(--force-lod 0)
    [[ $mode == mask ]] && extra=(--impostor-mask)
    timeout 900 xvfb-run -a -s "-screen 0 1280x720x24" "$godot" --audio-driver Dummy --resolution 640x360 \
      --path "$repo/demo_project" -- --map "$out/field60.field" --frames 6 --path "$out/$view.path" --wind 0 --no-hud \
      --screenshot "$out/$view.$mode.png" "${extra[@]}" >"$out/$view.$mode.log" 2>&1 ||
      { echo "measure: $view/$mode failed; see $out/$view.$mode.log" >&2; exit 1; }
    printf '.' >&2
  done
done
echo >&2
"$repo/.cache/venv/bin/python" "$repo/tools/measure_lod.py" "$out" "${names[@]}"
