#!/usr/bin/env bash
# Runs the demo's recording mode once under Xvfb (Forward+ on lavapipe) for the measurement scripts
# (tools/bench.sh, measure_budget.sh, measure_shadows.sh): the engine's output goes to LOG, the
# demo's figures to STATS (JSON). The engine's exit now and then never ends under lavapipe after the
# demo quits (godot#117064): 20 s after the stats are written, it is stopped. Exits 0 when the
# stats were written.
#   tools/demo_recording.sh LOG STATS [demo arguments...]     (RESOLUTION: default 480x270)
set -uo pipefail
repo=$(cd "$(dirname "$0")/.." && pwd)
godot=$("$repo/tools/find_godot.sh")
log=$1 stats=$2
shift 2
rm -f "$stats"
timeout 1800 xvfb-run -a -s "-screen 0 1280x720x24" "$godot" --audio-driver Dummy --resolution "${RESOLUTION:-480x270}" \
  --path "$repo/demo_project" -- --stats "$stats" "$@" >"$log" 2>&1 &
job=$!
waited=0
while kill -0 "$job" 2>/dev/null; do
  grep -q '^demo: stats' "$log" 2>/dev/null && waited=$((waited + 1))
  ((waited > 10)) && pkill -f -- "--stats $stats"
  sleep 2
done
wait "$job" || [[ -s "$stats" ]]
