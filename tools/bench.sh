#!/usr/bin/env bash
# Benchmarks (numbers, not pass/fail). Prints seventeen tables:
#   1. the C++ core alone: per-frame time and memory, 1M vs 4M plants;
#   2. the engine: the demo's recording mode on the demo, large and million-plant fields;
#   3. the thesis' experiment (Tables 3-5): a 1 500-plant field at distances 5 and 40 m, every plant
#      as one representation, then LOD off / on / on + culling, ratios beside the thesis' ratios;
#   4. baselines on one field and path: naive (every plant as the level-1 mesh) and Godot-native
#      (whole plants everywhere, the demo's --baseline native-whole).
#   5. ground placement: a million plants on a height map and on colliders (the build's figures).
#   6. painting: a brush stroke on a million-plant field, main-thread time per frame, chunks rebuilt.
#   7. GPU memory: the render buffers a million far plants take (the renderer's own count).
#   8. The GPU side: draw calls, objects, primitives and render-buffer memory per view, against the
#      Godot-native way (whole plants everywhere), on the demo, large, million and 4-million-plant
#      fields; then without a cut-off, far tiles merged with distance and not, a million and 4 million
#      plants.
#   9. The editor: its frame times while a scene with a million-plant field opens and builds
#      (headless, and rendering with Vulkan lavapipe under Xvfb), against the editor alone.
#  10. A million-plant build while the scene is drawn (Vulkan lavapipe under Xvfb): the load call,
#      the build's wall time, frames and steps, then the first frames that draw the field.
#  11. The frame budget (tools/measure_budget.sh): quality, primitives, draw calls and software frame
#      time at head height in the large field, without a budget and under caps on the near triangles.
#  12. Far plants against the native way (tools/measure_far_cost.sh): primitives, draw calls and software
#      frame time from 40 m outside and 25 m up at 45°, against whole plants near and front-view quads far.
#  13–14. Placement by rules and play's changes, the core alone; 15. play's changes in the engine.
#  16. Forests of the Sapling test plants, their levels thinned against every level mesh 1.
#  17. Making a plant's levels: plants of many foliage cards, the test plants and curtains of twigs through SunflowerPlant.from_scene.
# Results (JSON per run) go to build/bench/; BENCH_FRAMES and BENCH_RESOLUTION change the runs.
set -euo pipefail
repo=$(cd "$(dirname "$0")/.." && pwd)
"$repo/tools/build.sh" >/dev/null
godot=$("$repo/tools/find_godot.sh")
out="$repo/build/bench"
mkdir -p "$out/fields" "$out/runs"
rm -f "$out"/runs/*.json
frames=${BENCH_FRAMES:-12}
resolution=${BENCH_RESOLUTION:-480x270}

echo "Machine: $(nproc) cores, $(free -g | awk '/Mem:/ {print $2}') GiB, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs)"
echo "Engine: $("$godot" --version | head -n 1); rendering: Forward+ on Vulkan lavapipe (software) under Xvfb, $resolution"
echo
echo "## 1. The core alone"
"$repo/build/bench/core_bench"
echo
echo "## 13. Placement by rules, the core alone"
"$repo/build/bench/placement_bench"
echo
echo "## 14. Play's changes, the core alone"
"$repo/build/bench/play_bench"

"$repo/tools/make_field.py" 50 30 "$out/fields/thesis1500.field" >/dev/null
"$repo/tools/make_field.py" 1000 1000 "$out/fields/million.field" >/dev/null
printf '12.5 1.7 20 12.5 1.0 7.5\n12.5 1.7 20 12.5 1.0 7.5\n' >"$out/fields/view5.path"
printf '12.5 1.7 55 12.5 1.0 7.5\n12.5 1.7 55 12.5 1.0 7.5\n' >"$out/fields/view40.path"

run() { # $1 = name, rest = demo arguments
  local name=$1
  shift
  RESOLUTION=$resolution "$repo/tools/demo_recording.sh" "$out/runs/$name.log" "$out/runs/$name.json" \
    --frames "$frames" "$@" || echo "bench: run $name failed; see $out/runs/$name.log" >&2
  printf '.' >&2
}

echo >&2
echo "bench: engine runs (about $((frames * 20)) frames in all, software rendering: minutes)" >&2
run engine_demo --map res://fields/demo.field
run engine_large --map res://fields/large.field
run engine_million --map "$out/fields/million.field"
# The million-plant field once more without rendering, where frames are short as on a GPU: the load
# without software rendering's slow frames, and 600 frames of the flight (small steps, as at 60 FPS;
# the rendered runs above jump along it in 12 frames).
timeout 600 "$godot" --headless --audio-driver Dummy --path "$repo/demo_project" -- --frames 600 \
  --stats "$out/runs/engine_million_headless.json" --map "$out/fields/million.field" \
  >"$out/runs/engine_million_headless.log" 2>&1 || echo "bench: the headless million run failed" >&2
for view in 5 40; do
  for lod in 0 1 2 3 4; do
    run "thesis_${view}_force${lod}" --map "$out/fields/thesis1500.field" --path "$out/fields/view$view.path" --force-lod "$lod" --culling off
  done
  run "thesis_${view}_lod" --map "$out/fields/thesis1500.field" --path "$out/fields/view$view.path" --culling off
  run "thesis_${view}_lodcull" --map "$out/fields/thesis1500.field" --path "$out/fields/view$view.path"
done
run baseline_ours --map res://fields/demo.field
run baseline_naive --map res://fields/demo.field --force-lod 0 --culling off
run baseline_native --map res://fields/demo.field --baseline native-whole
# The GPU side: still views of four fields, drawn by the addon and the Godot-native way, both cut
# off at 100 m (the native way's visibility range).
"$repo/tools/make_field.py" 2000 2000 "$out/fields/4m.field" >/dev/null
for field in demo:res://fields/demo.field large:res://fields/large.field million:"$out/fields/million.field" 4m:"$out/fields/4m.field"; do
  for view in inside outside40 above45 down60; do
    # Still views: 3 frames are enough for the counts. (At 160 x 90 lavapipe under Xvfb sometimes hangs
    # in the frame after quit; 480 x 270 has not.)
    frames=3 run "gpu_${field%%:*}_${view}_ours" --map "${field#*:}" --view "$view" --draw-distance 100 --no-hud
    frames=3 run "gpu_${field%%:*}_${view}_native" --map "${field#*:}" --view "$view" --draw-distance 100 --baseline native-whole --no-hud
  done
done
# Without a cut-off: far tiles merged with distance (the default) and never merged, on the million and
# 4-million-plant fields (draw calls per field size: table 8's second part).
for field in million:"$out/fields/million.field" 4m:"$out/fields/4m.field"; do
  for view in outside40 above45; do
    for merge in 200 0; do
      frames=3 run "far_${field%%:*}_${view}_merge${merge}" --map "${field#*:}" --view "$view" --draw-distance 0 \
        --tile-merge "$merge" --no-hud
    done
  done
done
echo >&2
python3 "$repo/tools/bench_tables.py" "$out/runs"
echo
echo "## 5. Ground placement in the engine (headless): a million plants on a 1025 x 1025 terrain, 8 ms build budget"
"$repo/tools/import_project.sh" "$repo/tests/godot" >/dev/null
timeout 600 "$godot" --headless --audio-driver Dummy --path "$repo/tests/godot" --script res://bench/ground_bench.gd 2>&1 | grep '^|' ||
  echo "bench: the ground benchmark failed" >&2
echo
echo "## 6. Painting a million-plant field: a brush stroke, one mouse move a frame (headless)"
timeout 600 "$godot" --headless --audio-driver Dummy --path "$repo/tests/godot" --script res://bench/paint_bench.gd 2>&1 | grep '^|' ||
  echo "bench: the painting benchmark failed" >&2
echo
echo "## 7. GPU memory: a million far plants' render buffers (Forward+ on Vulkan lavapipe under Xvfb)"
timeout 600 xvfb-run -a -s "-screen 0 1280x720x24" "$godot" --rendering-driver vulkan --audio-driver Dummy \
  --resolution "$resolution" --path "$repo/tests/godot" --script res://bench/gpu_memory_bench.gd 2>&1 | grep '^|' ||
  echo "bench: the GPU memory benchmark failed" >&2
echo
echo "## 15. Play's changes in the engine: 1 000 changes landing in a frame of a million-plant field (Vulkan lavapipe under Xvfb)"
timeout 900 xvfb-run -a -s "-screen 0 1280x720x24" "$godot" --rendering-driver vulkan --audio-driver Dummy \
  --resolution "$resolution" --path "$repo/tests/godot" --script res://bench/play_bench.gd 2>&1 | grep '^|' ||
  echo "bench: the play benchmark failed" >&2
echo
echo "## 16. Forests: a field of each Sapling test plant, its levels thinned against every level mesh 1 (Vulkan lavapipe under Xvfb)"
timeout 900 xvfb-run -a -s "-screen 0 1280x720x24" "$godot" --rendering-driver vulkan --audio-driver Dummy \
  --resolution "$resolution" --path "$repo/tests/godot" --script res://bench/forest_bench.gd 2>&1 | grep '^|' ||
  echo "bench: the forest benchmark failed" >&2
echo
echo "## 17. Making a plant's levels: plants of many foliage cards, the test plants and curtains of twigs through SunflowerPlant.from_scene (headless)"
timeout 900 "$godot" --headless --audio-driver Dummy --path "$repo/tests/godot" --script res://bench/levels_bench.gd 2>&1 | grep '^|' ||
  echo "bench: the levels benchmark failed" >&2
echo
echo "## 9. The editor opening a scene with a million-plant field (frame intervals; the plugin's frame probe)"
editor_project=$(mktemp -d)
mkdir -p "$editor_project/addons"
cp -rL "$repo/addons/sunflower_field" "$editor_project/addons/"
cp -r "$repo/tools/bench_editor/frame_probe" "$editor_project/addons/"
cp "$repo/tools/bench_editor/project.godot" "$repo/tools/bench_editor/million.tscn" "$editor_project/"
cp "$out/fields/million.field" "$editor_project/"
if "$repo/tools/import_project.sh" "$editor_project" >"$out/runs/editor_import.log" 2>&1; then
  for mode in headless vulkan; do
    launch=(xvfb-run -a -s "-screen 0 1600x900x24" "$godot" --rendering-driver vulkan)
    [[ $mode == headless ]] && launch=("$godot" --headless)
    echo
    echo "Editor, $([[ $mode == headless ]] && echo "headless (no rendering)" || echo "Forward+ on Vulkan lavapipe under Xvfb, 1600 x 900"):"
    echo
    rm -rf "$editor_project/.godot/editor" # else the editor reopens the scene the last run left open
    RUN_PROBE=1 timeout 900 "${launch[@]}" --editor --audio-driver Dummy --path "$editor_project" \
      >"$out/runs/editor_$mode.log" 2>&1
    grep -E '^\||^probe: build' "$out/runs/editor_$mode.log" || echo "bench: the editor run ($mode) failed; see $out/runs/editor_$mode.log" >&2
  done
else
  echo "bench: importing the editor project failed; see $out/runs/editor_import.log" >&2
fi
rm -rf "$editor_project"
echo
echo "## 10. A million-plant map loaded in the background while the scene is drawn (Forward+ on Vulkan lavapipe under Xvfb)"
timeout 600 xvfb-run -a -s "-screen 0 1280x720x24" "$godot" --rendering-driver vulkan --audio-driver Dummy \
  --resolution "$resolution" --path "$repo/tests/godot" --script res://bench/build_bench.gd 2>&1 | grep '^|' ||
  echo "bench: the build benchmark failed" >&2
echo
echo "## 11. The frame budget (tools/measure_budget.sh)"
"$repo/tools/measure_budget.sh" || echo "bench: the budget measurement failed" >&2
echo
echo "## 12. Far plants against the native way (tools/measure_far_cost.sh)"
"$repo/tools/measure_far_cost.sh" || echo "bench: the far-plant measurement failed" >&2
