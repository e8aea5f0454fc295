#!/usr/bin/env bash
# What the near plants' shadows cost and look like (docs/performance.md, "Shadows"): the demo's
# recording mode at head height in the million-plant field, calm, 4 frames at 480 × 270 under Xvfb
# (Vulkan lavapipe), once per way of casting: every mesh level from its own mesh, from mesh 3
# (cheap_shadows), and from the impostors from mesh 3 (the default) and from mesh 2 on
# (impostor_shadows_from).
# Prints the renderer's primitives and draw calls for the whole frame (medians) and each picture's
# SSIM and brightness against the full-shadow one.
#   tools/measure_shadows.sh            the table above (about 15 minutes)
#   tools/measure_shadows.sh --views    instead: full shadows against the default's, primitives and
#                                       draw calls, on the demo, large, million and 4-million-plant
#                                       fields from the four still views, 3 frames each (about 35 minutes)
set -euo pipefail
repo=$(cd "$(dirname "$0")/.." && pwd)
"$repo/tools/build.sh" >/dev/null
godot=$("$repo/tools/find_godot.sh")
out="$repo/build/bench/shadows"
mkdir -p "$out" "$repo/build/bench/fields"
field="$repo/build/bench/fields/million.field"
[[ -s "$field" ]] || "$repo/tools/make_field.py" 1000 1000 "$field" >/dev/null
# Every mesh level casting from its own mesh: the full-detail shadows both tables compare with.
full_shadows=(--cheap-shadows off --impostor-shadows never)
if [[ ${1:-} == --views ]]; then
  four="$repo/build/bench/fields/4m.field"
  [[ -s "$four" ]] || "$repo/tools/make_field.py" 2000 2000 "$four" >/dev/null
  fields=("demo|res://fields/demo.field" "large|res://fields/large.field" "million|$field" "4 million|$four")
  echo "Shadows per view: full (every mesh level from its own mesh) against the default (impostors from"
  echo "mesh 3), calm, 3 frames at 480 × 270 (medians; the renderer's counts for the whole frame)"
  echo
  echo "| field | view | primitives full / default | against full | draw calls full / default |"
  echo "|---|---|---|---|---|"
  for entry in "${fields[@]}"; do
    for view in inside outside40 above45 down60; do
      for way in full default; do
        flags=()
        [[ $way == full ]] && flags=("${full_shadows[@]}")
        RESOLUTION=480x270 "$repo/tools/demo_recording.sh" "$out/view_$way.log" "$out/view_$way.json" \
          --map "${entry#*|}" --view "$view" --wind 0 --no-hud --frames 3 "${flags[@]}" ||
          { echo "measure_shadows: the run ${entry%%|*} $view $way failed; see $out/view_$way.log" >&2; exit 1; }
      done
      python3 - "${entry%%|*}" "$view" "$out/view_full.json" "$out/view_default.json" <<'PY'
import json, sys
name, view, full, default = sys.argv[1], sys.argv[2], json.load(open(sys.argv[3])), json.load(open(sys.argv[4]))
p = [s["primitives"]["median"] for s in (full, default)]
d = [s["draw_calls"]["median"] for s in (full, default)]
print(f"| {name} | {view} | {p[0] / 1e6:.2f} M / {p[1] / 1e6:.2f} M | {p[1] / max(p[0], 1):.2f}× | {d[0]:.0f} / {d[1]:.0f} |")
PY
    done
  done
  exit 0
fi
ways=("full|${full_shadows[*]}" "mesh 3 (cheap_shadows)|--impostor-shadows never"
  "impostors from mesh 3 (the default)|" "impostors from mesh 2|--impostor-shadows mesh2")
for i in "${!ways[@]}"; do
  read -r -a flags <<<"${ways[$i]#*|}"
  RESOLUTION=480x270 "$repo/tools/demo_recording.sh" "$out/way_$i.log" "$out/way_$i.json" --map "$field" \
    --view inside --wind 0 --no-hud --frames 4 --screenshot "$out/way_$i.png" "${flags[@]}" ||
    { echo "measure_shadows: the run '${ways[$i]%%|*}' failed; see $out/way_$i.log" >&2; exit 1; }
  printf '.' >&2
done
echo >&2
echo "Million-plant field, head height inside, calm, 4 frames at 480 × 270 (medians)"
echo
echo "| shadows cast | primitives | against full | draw calls | picture against full |"
echo "|---|---|---|---|---|"
full=$(python3 -c "import json,sys; print(json.load(open(sys.argv[1]))['primitives']['median'])" "$out/way_0.json")
for i in "${!ways[@]}"; do
  read -r primitives calls < <(python3 -c "import json,sys; s=json.load(open(sys.argv[1])); print(s['primitives']['median'], s['draw_calls']['median'])" "$out/way_$i.json")
  picture="—"
  if ((i > 0)); then
    picture=$("$godot" --headless --path "$repo/tests/godot" --script "$repo/tools/compare_pictures.gd" -- \
      "$out/way_0.png" "$out/way_$i.png" 2>/dev/null | sed -n 's/^compare_pictures: //p')
  fi
  python3 -c "import sys; p,f,c=float(sys.argv[2]),float(sys.argv[3]),float(sys.argv[4]); print(f'| {sys.argv[1]} | {p/1e6:.2f} M | {p/f:.2f}× | {c:.0f} | {sys.argv[5]} |')" \
    "${ways[$i]%%|*}" "$primitives" "$full" "$calls" "$picture"
done
