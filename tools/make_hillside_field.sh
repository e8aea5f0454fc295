#!/bin/bash
# Writes fields/hillside.field, the demo's "Hillside" map, from its placement rules
# (demo_project/rules/hillside_rules.tres) on the demo's hills. Needs the built library (tools/build.sh).
set -euo pipefail
repo="$(cd "$(dirname "$0")/.." && pwd)"
godot="$("$repo/tools/find_godot.sh")"
"$godot" --headless --path "$repo/demo_project" --script res://scripts/make_hillside.gd
