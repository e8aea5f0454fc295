#!/usr/bin/env bash
# The frame budget measured (table 11 of tools/bench.sh; runs alone too): the demo's recording mode
# at head height inside the large field (113 000 plants), calm, without a budget and with caps on
# the near meshes' triangles; per run the renderer's primitives and draw calls for the whole frame
# (main pass, depth pre-pass, shadow cascades), the software frame time (medians over the frames
# after the budget settled) and the quality the field chose. Under Xvfb with lavapipe: minutes.
#   tools/measure_budget.sh [CAP ...]     caps in triangles (default: 2000000 1000000 500000; the field
#                                        holds 2.6 M there without one)
set -euo pipefail
repo=$(cd "$(dirname "$0")/.." && pwd)
"$repo/tools/build.sh" >/dev/null
godot=$("$repo/tools/find_godot.sh")
out="$repo/build/bench/budget"
mkdir -p "$out"
frames=${BENCH_FRAMES:-16}
resolution=${BENCH_RESOLUTION:-480x270}
caps=("$@")
((${#caps[@]})) || caps=(2000000 1000000 500000)

for cap in 0 "${caps[@]}"; do
  budget=()
  ((cap > 0)) && budget=(--budget-primitives "$cap")
  rm -f "$out/cap_$cap.json"
  log="$out/cap_$cap.log"
  timeout 900 xvfb-run -a -s "-screen 0 1280x720x24" "$godot" --audio-driver Dummy --resolution "$resolution" \
    --path "$repo/demo_project" -- --map res://fields/large.field --view inside --wind 0 --no-hud \
    --frames "$frames" --stats "$out/cap_$cap.json" "${budget[@]}" >"$log" 2>&1 &
  job=$!
  waited=0 # the engine's exit now and then hangs under lavapipe (see tools/bench.sh): stopped 20 s after the stats
  while kill -0 "$job" 2>/dev/null; do
    grep -q '^demo: stats' "$log" 2>/dev/null && waited=$((waited + 1))
    ((waited > 10)) && pkill -f -- "--stats $out/cap_$cap.json"
    sleep 2
  done
  wait "$job" || [[ -s "$out/cap_$cap.json" ]] || { echo "measure_budget: the run with cap $cap failed; see $log" >&2; exit 1; }
  printf '.' >&2
done
echo >&2
python3 - "$out" "$frames" "${caps[@]}" <<'EOF'
import json, statistics, sys
out, frames, caps = sys.argv[1], int(sys.argv[2]), [0] + [int(c) for c in sys.argv[3:]]
print(f"Large field (113 000 plants), head height inside, calm, {frames} frames; medians of the last half")
print()
print("| cap on near triangles | quality | near triangles | primitives (whole frame) | draw calls | software frame |")
print("|---|---|---|---|---|---|")
for cap in caps:
    s = json.load(open(f"{out}/cap_{cap}.json"))
    half = lambda values: statistics.median(values[len(values) // 2:])
    print(f"| {'none' if cap == 0 else f'{cap / 1e6:.1f} M'} | {s['quality_final']:.2f} "
          f"| {s['near_primitives_final'] / 1e6:.2f} M | {half(s['primitives_per_frame']) / 1e6:.2f} M "
          f"| {half(s['draw_calls_per_frame']):.0f} | {half(s['frame_times_ms']) / 1000:.2f} s |")
EOF
