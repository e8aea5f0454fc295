#!/usr/bin/env bash
# Builds everything: the extension (debug + release) into the addon, the core unit tests, and the
# imported caches of the demo and test projects.
set -euo pipefail
repo=$(cd "$(dirname "$0")/.." && pwd)
"$repo/tools/setup.sh"
godot=$("$repo/tools/find_godot.sh")
cd "$repo"
"$repo/.cache/venv/bin/scons" -Q -j"$(nproc)" godot="$godot"
"$repo/tools/import_project.sh" "$repo/tests/godot"
"$repo/tools/import_project.sh" "$repo/demo_project"
