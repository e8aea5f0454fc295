#!/usr/bin/env bash
# Runs every test: core unit tests (no engine), GDScript lint and format, the engine integration
# and render tests under Xvfb with real renderers (Vulkan and OpenGL), a leak check and a drop-in
# project check. Ends with "total: N passed, N failed".
set -uo pipefail
repo=$(cd "$(dirname "$0")/.." && pwd)
cd "$repo"
"$repo/tools/build.sh" || { echo "build: 0 passed, 1 failed"; exit 1; }
godot=$("$repo/tools/find_godot.sh")
artifacts="$repo/tests/artifacts"
mkdir -p "$artifacts"
passed=0
failed=0
record() { # $1 = passed count, $2 = failed count, $3 = what
  passed=$((passed + $1)); failed=$((failed + $2))
  printf '== %s: %d passed, %d failed\n' "$3" "$1" "$2"
}

echo "== core unit tests (doctest)"
out=$("$repo/build/tests/core_tests" 2>&1); status=$?
echo "$out" | tail -n 4
line=$(echo "$out" | grep -E 'test cases:' | tail -n 1)
p=$(echo "$line" | sed -E 's/.*\| *([0-9]+) passed.*/\1/'); f=$(echo "$line" | sed -E 's/.*\| *([0-9]+) failed.*/\1/')
[[ "$p" =~ ^[0-9]+$ && "$f" =~ ^[0-9]+$ ]] || { p=0; f=1; }
((status != 0 && f == 0)) && f=1
record "$p" "$f" "core unit tests"

echo "== gdlint and gdformat"
mapfile -t scripts < <(git ls-files '*.gd')
if (cd "$repo" && "$repo/.cache/venv/bin/gdlint" "${scripts[@]}"); then record 1 0 "gdlint"; else record 0 1 "gdlint"; fi
if "$repo/.cache/venv/bin/gdformat" --check --line-length 120 "${scripts[@]}"; then record 1 0 "gdformat"; else record 0 1 "gdformat"; fi

# $1 = label, $2 = rendering driver, $3 = log file, rest = test names (none: all)
engine_suite() {
  local label=$1 driver=$2 log=$3; shift 3
  echo "== $label"
  timeout 900 xvfb-run -a -s "-screen 0 1280x720x24" "$godot" --verbose --audio-driver Dummy --rendering-driver "$driver" \
    --path "$repo/tests/godot" --script res://run_tests.gd -- "$@" >"$log" 2>&1
  local status=$? line p f
  grep -E '^(ok|FAIL) |^     |^godot:' "$log"
  line=$(grep -E '^godot: [0-9]+ passed, [0-9]+ failed$' "$log" | tail -n 1)
  if [[ -z "$line" ]]; then
    echo "the engine run ended without its summary line (exit $status); the log is $log"; tail -n 30 "$log"
    record 0 1 "$label"
    return
  fi
  p=$(echo "$line" | sed -E 's/godot: ([0-9]+) passed.*/\1/'); f=$(echo "$line" | sed -E 's/.* ([0-9]+) failed/\1/')
  ((status != 0 && f == 0)) && f=1
  record "$p" "$f" "$label"
}

engine_suite "engine tests (Godot under Xvfb, Forward+ on Vulkan lavapipe)" vulkan "$artifacts/godot_tests.log"
cp "$artifacts/render_demo_field.png" "$artifacts/render_demo_field_vulkan.png" 2>/dev/null
engine_suite "render test (Compatibility renderer, OpenGL on llvmpipe)" opengl3 "$artifacts/godot_render_gl.log" test_render
mv "$artifacts/render_demo_field.png" "$artifacts/render_demo_field_opengl.png" 2>/dev/null

echo "== leaks at exit (--verbose output of both engine runs)"
if grep -E "leaked at exit|Leaked instance|were leaked|Orphan StringName|instances leaked" "$artifacts/godot_tests.log" "$artifacts/godot_render_gl.log"; then
  record 0 1 "no leaks"
else
  record 1 0 "no leaks"
fi

echo "== drop-in: a new project with only addons/sunflower_field/ copied in, a scene without code"
dropin=$(mktemp -d)
cp -rL "$repo/addons/sunflower_field" "$dropin/addons_copy" && mkdir -p "$dropin/addons" && mv "$dropin/addons_copy" "$dropin/addons/sunflower_field"
cp "$repo/fields/demo.field" "$repo/tests/dropin/project.godot" "$repo/tests/dropin/main.tscn" "$repo/tests/dropin/check_dropin.gd" "$dropin/"
if "$repo/tools/import_project.sh" "$dropin" >"$artifacts/dropin.log" 2>&1 &&
  timeout 300 xvfb-run -a -s "-screen 0 1280x720x24" "$godot" --audio-driver Dummy \
    --path "$dropin" --script res://check_dropin.gd >>"$artifacts/dropin.log" 2>&1 &&
  grep -q '^dropin: ok$' "$artifacts/dropin.log"; then
  grep '^dropin:' "$artifacts/dropin.log"; record 1 0 "drop-in"
else
  tail -n 20 "$artifacts/dropin.log"; record 0 1 "drop-in"
fi
rm -rf "$dropin"

echo "artifacts: $artifacts"
echo "total: $passed passed, $failed failed"
((failed == 0 && passed > 0))
