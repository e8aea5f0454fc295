#!/usr/bin/env bash
# Builds what the demo needs (this machine's debug library; no other platform) and runs the demo.
# With a display: the interactive demo. Without one: the demo's recording mode under Xvfb, which
# flies the built-in path, saves pictures and prints the field's statistics.
#   tools/demo.sh [--no-build] [demo arguments, e.g. --map fields/hills.field --frames 120]
# Exits non-zero, saying why, when the build or the demo fails (an error, a crash, no picture).
set -uo pipefail
repo=$(cd "$(dirname "$0")/.." && pwd)
fail() { echo "demo: FAILED: $*" >&2; exit 1; }
if [[ "${1:-}" == --no-build ]]; then
  shift
else
  "$repo/tools/build.sh" --demo || fail "the build failed (above)"
fi
godot=$("$repo/tools/find_godot.sh") || fail "no engine (above)"
if [[ -n "${DISPLAY:-}" && -z "${CI:-}" ]]; then
  exec "$godot" --path "$repo/demo_project" -- "$@"
fi
out="$repo/build/demo"
mkdir -p "$out"
args=("$@")
# Without arguments: the built-in flight, a picture every 5 frames (low and high viewpoints).
((${#args[@]})) || args=(--frames 11 --screenshot "$out/demo.png" --screenshot-every 5)
screenshot=""
for ((i = 0; i + 1 < ${#args[@]}; i++)); do
  [[ "${args[i]}" == --screenshot ]] && screenshot=${args[i + 1]}
done
[[ -n "$screenshot" ]] && rm -f "$screenshot"
log="$out/demo.log"
echo "demo: no display; running the recording mode under Xvfb (Forward+ on Vulkan lavapipe); log $log"
: >"$log" # there before the engine's shell opens it, for the watch below
# The engine's own "status < 0" line comes from the X server's shared-memory probe under Xvfb.
errors_in_log() { grep -E '^(SCRIPT ERROR|ERROR|USER ERROR)' "$log" | grep -v 'status < 0'; }
setsid timeout 900 xvfb-run -a -s "-screen 0 1280x720x24" "$godot" --audio-driver Dummy --resolution 640x360 \
  --path "$repo/demo_project" -- "${args[@]}" >"$log" 2>&1 &
engine=$! # its own process group: the engine, Xvfb and the wrappers stop together
# A demo that cannot run (a script that does not load, no library) would never finish its recording:
# once the engine reports an error it gets five seconds more to say the rest (two were too few for
# the missing library's message on a busy machine), then it is stopped.
while kill -0 "$engine" 2>/dev/null; do
  if [[ -n "$(errors_in_log)" ]]; then
    sleep 5
    kill -TERM -- -"$engine" 2>/dev/null
    break
  fi
  sleep 1
done
wait "$engine"
status=$?
grep -E '^demo:' "$log"
errors=$(errors_in_log)
[[ -z "$errors" ]] || { echo "$errors" >&2; fail "the demo reported errors (above; the whole log is $log)"; }
((status == 0)) || fail "the engine exited with status $status (the log is $log)"
[[ -z "$screenshot" || -s "$screenshot" ]] || fail "no picture was saved at $screenshot (the log is $log)"
[[ -n "$screenshot" ]] && echo "demo: pictures are in $(dirname "$screenshot")"
for ((i = 0; i + 1 < ${#args[@]}; i++)); do
  [[ "${args[i]}" == --stats ]] && echo "demo: statistics are in ${args[i + 1]}"
done
exit 0
