#!/usr/bin/env bash
# Builds everything and runs the demo. With a display: the interactive demo. Without one: the
# demo's recording mode under Xvfb, which saves a screenshot and prints the field's statistics.
#   tools/demo.sh [extra demo arguments, e.g. --frames 120 --screenshot /tmp/shot.png]
set -euo pipefail
repo=$(cd "$(dirname "$0")/.." && pwd)
"$repo/tools/build.sh"
godot=$("$repo/tools/find_godot.sh")
if [[ -n "${DISPLAY:-}" && -z "${CI:-}" ]]; then
  exec "$godot" --path "$repo/demo_project" -- "$@"
fi
shot="$repo/build/demo/demo.png"
args=("$@")
((${#args[@]})) || args=(--frames 60 --screenshot "$shot")
echo "demo: no display; running the recording mode under Xvfb (Forward+ on Vulkan lavapipe)"
timeout 600 xvfb-run -a -s "-screen 0 1280x720x24" "$godot" --audio-driver Dummy \
  --path "$repo/demo_project" -- "${args[@]}" 2>&1 | grep -E '^demo:|SCRIPT ERROR|^ERROR' | grep -v 'status < 0' || true
[[ " ${args[*]} " == *" --screenshot "* ]] && echo "demo: pictures are in $(dirname "${args[-1]}")"
exit 0
