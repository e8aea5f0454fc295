#!/usr/bin/env bash
# Builds the extension into the addon and imports the projects that use it.
#   tools/build.sh          this machine's libraries (Linux x86_64, debug + release), the core's unit
#                           tests and benchmark; imports the demo and the test project
#   tools/build.sh --all    also every other desktop platform's libraries (Linux, Windows, macOS on
#                           x86_64 and arm64) and the core's tests built for Windows x86_64 and Linux arm64
#   tools/build.sh --demo   only what the demo needs: this machine's debug library; imports the demo
# Other arguments go to scons. Runs tools/setup.sh first (with --demo, its short form).
set -euo pipefail
repo=$(cd "$(dirname "$0")/.." && pwd)
mode=host
args=()
for arg in "$@"; do
  case "$arg" in
    --all) mode=all; args+=(platform=all arch=all cross_tests=windows.x86_64,linux.arm64) ;;
    --demo) mode=demo; args+=(tests=0 target=template_debug) ;;
    *) args+=("$arg") ;;
  esac
done
if [[ $mode == demo ]]; then "$repo/tools/setup.sh" --demo; else "$repo/tools/setup.sh"; fi
godot=$("$repo/tools/find_godot.sh")
cd "$repo"
"$repo/.cache/venv/bin/scons" -Q -j"$(nproc)" godot="$godot" "${args[@]}"
[[ $mode == demo ]] || "$repo/tools/import_project.sh" "$repo/tests/godot"
"$repo/tools/import_project.sh" "$repo/demo_project"
