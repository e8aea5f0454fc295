#!/usr/bin/env bash
# Regenerates the addon's plant assets: the nine part meshes of the sunflower and of the red sunflower
# (assets/generate_sunflower.gd) and their impostor atlases rendered from the level-1
# models by the addon's baker (assets/bake_impostors.gd, under Xvfb).
set -euo pipefail
repo=$(cd "$(dirname "$0")/.." && pwd)
godot=$("$repo/tools/find_godot.sh")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
echo 'config_version=5' > "$work/project.godot"
ln -s "$repo/addons" "$work/addons"
"$repo/tools/import_project.sh" "$work" >/dev/null # the scripts name the addon's classes
timeout 300 "$godot" --headless --path "$work" --script "$repo/assets/generate_sunflower.gd" -- \
  "$repo/addons/sunflower_field/meshes" 2>&1 | grep -E '^level|ERROR'
timeout 300 xvfb-run -a -s "-screen 0 1280x720x24" "$godot" --audio-driver Dummy --path "$work" \
  --script "$repo/assets/bake_impostors.gd" -- "$repo/addons/sunflower_field/textures" 2>&1 | grep -E '^(views|normals|depths|alpha cuts)|ERROR|SCRIPT'
timeout 300 "$godot" --headless --path "$work" --script "$repo/assets/generate_sunflower.gd" -- \
  "$repo/addons/sunflower_field/meshes" red 2>&1 | grep -E '^level|ERROR'
timeout 300 xvfb-run -a -s "-screen 0 1280x720x24" "$godot" --audio-driver Dummy --path "$work" \
  --script "$repo/assets/bake_impostors.gd" -- "$repo/addons/sunflower_field/textures" \
  res://addons/sunflower_field/plants/red_sunflower.tres red_sunflower 2>&1 | grep -E '^(views|normals|depths|alpha cuts)|ERROR|SCRIPT'
