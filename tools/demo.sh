#!/usr/bin/env bash
# Builds everything (the libraries for every desktop platform, as tools/test.sh does) and runs the demo. With a display: the interactive demo. Without one: the
# demo's recording mode under Xvfb, which saves a screenshot and prints the field's statistics.
#   tools/demo.sh [extra demo arguments, e.g. --frames 120 --screenshot /tmp/shot.png]
set -euo pipefail
repo=$(cd "$(dirname "$0")/.." && pwd)
"$repo/tools/build.sh" --all
godot=$("$repo/tools/find_godot.sh")
if [[ -n "${DISPLAY:-}" && -z "${CI:-}" ]]; then
  exec "$godot" --path "$repo/demo_project" -- "$@"
fi
out="$repo/build/demo"
args=("$@")
# Without arguments: the built-in flight, a picture every 10 frames (low and high viewpoints), stats.
((${#args[@]})) || args=(--frames 41 --screenshot "$out/demo.png" --screenshot-every 10 --stats "$out/stats.json")
echo "demo: no display; running the recording mode under Xvfb (Forward+ on Vulkan lavapipe)"
timeout 900 xvfb-run -a -s "-screen 0 1280x720x24" "$godot" --audio-driver Dummy --resolution 960x540 \
  --path "$repo/demo_project" -- "${args[@]}" 2>&1 | grep -E '^demo:|SCRIPT ERROR|^ERROR' | grep -v 'status < 0' || true
for ((i = 0; i + 1 < ${#args[@]}; i++)); do
  [[ "${args[i]}" == --screenshot ]] && echo "demo: pictures are in $(dirname "${args[i + 1]}")"
  [[ "${args[i]}" == --stats ]] && echo "demo: statistics are in ${args[i + 1]}"
done
exit 0
