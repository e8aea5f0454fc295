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
out="$repo/build/bench/budget"
mkdir -p "$out"
frames=${BENCH_FRAMES:-16}
resolution=${BENCH_RESOLUTION:-480x270}
caps=("$@")
((${#caps[@]})) || caps=(2000000 1000000 500000)

for cap in 0 "${caps[@]}"; do
  budget=()
  ((cap > 0)) && budget=(--budget-primitives "$cap")
  RESOLUTION=$resolution "$repo/tools/demo_recording.sh" "$out/cap_$cap.log" "$out/cap_$cap.json" \
    --map res://fields/large.field --view inside --wind 0 --no-hud --frames "$frames" "${budget[@]}" ||
    { echo "measure_budget: the run with cap $cap failed; see $out/cap_$cap.log" >&2; exit 1; }
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
