#!/usr/bin/env bash
# Runs every test: core unit tests (no engine), GDScript lint and format, the engine integration
# and render tests under Xvfb with real renderers (Vulkan and OpenGL), a leak check and a drop-in
# project check; the libraries for every desktop platform are built and inspected, and the core's tests
# run built for Windows (under Wine) and Linux arm64 (under QEMU). Ends with "total: N passed, N failed".
set -uo pipefail
repo=$(cd "$(dirname "$0")/.." && pwd)
cd "$repo"
"$repo/tools/build.sh" --all || { echo "build: 0 passed, 1 failed"; exit 1; }
build_seconds=$SECONDS
echo "== build: $build_seconds s"
godot=$("$repo/tools/find_godot.sh")
artifacts="$repo/tests/artifacts"
mkdir -p "$artifacts"
passed=0
failed=0
since=$SECONDS
record() { # $1 = passed count, $2 = failed count, $3 = what; with the seconds since the last one
  passed=$((passed + $1)); failed=$((failed + $2))
  printf '== %s: %d passed, %d failed (%d s)\n' "$3" "$1" "$2" $((SECONDS - since))
  since=$SECONDS
}

# $1 = label, rest = the doctest program and how to start it
doctest_suite() {
  local label=$1 out status line p f; shift
  echo "== $label"
  out=$(WINEDEBUG=-all timeout 900 "$@" 2>&1); status=$?
  echo "$out" | tail -n 4
  line=$(echo "$out" | grep -E 'test cases:' | tail -n 1)
  p=$(echo "$line" | sed -E 's/.*\| *([0-9]+) passed.*/\1/'); f=$(echo "$line" | sed -E 's/.*\| *([0-9]+) failed.*/\1/')
  [[ "$p" =~ ^[0-9]+$ && "$f" =~ ^[0-9]+$ ]] || { p=0; f=1; }
  ((status != 0 && f == 0)) && f=1
  record "$p" "$f" "$label"
}
# The fuzzer and the core's tests under Wine and QEMU each keep one core busy: the fuzzer runs beside
# them (started here, its result recorded at the end).
fuzz_seconds=${FUZZ_SECONDS:-60}
fuzz_corpus=$(mktemp -d)
(
  "$repo/.cache/venv/bin/scons" -Q -j1 fuzz >"$artifacts/fuzz_build.log" 2>&1 &&
    "$repo/build/fuzz/fuzz_field_map" -max_total_time="$fuzz_seconds" -max_len=4096 -print_final_stats=1 \
      -artifact_prefix="$artifacts/fuzz-" "$fuzz_corpus" "$repo/gdextension/fuzz/corpus" >"$artifacts/fuzz.log" 2>&1
) &
fuzz_pid=$!
fuzz_finish() {
  echo "== fuzzing the map parser and layout for ${fuzz_seconds} s (libFuzzer, ASan + UBSan; run beside the core's tests)"
  if wait "$fuzz_pid"; then
    grep -E "^Done|stat::number_of_executed_units" "$artifacts/fuzz.log" | head -n 2
    record 1 0 "fuzzing"
  else
    tail -n 30 "$artifacts/fuzz_build.log" "$artifacts/fuzz.log"; record 0 1 "fuzzing"
  fi
  rm -rf "$fuzz_corpus"
}
doctest_suite "core unit tests (doctest)" "$repo/build/tests/core_tests"
doctest_suite "core unit tests built for Windows x86_64, under Wine" /usr/lib/wine/wine64 "$repo/build/tests/core_tests.windows.x86_64.exe"
doctest_suite "core unit tests built for Linux arm64, under QEMU" qemu-aarch64-static -L /usr/aarch64-linux-gnu \
  "$repo/build/tests/core_tests.linux.arm64"

echo "== the libraries for every platform: format, architecture, dependencies, exports"
python3 "$repo/tools/check_libraries.py" "$repo"/addons/sunflower_field/bin/*.{so,dll,dylib} | tee "$artifacts/libraries.log"
line=$(grep -E '^libraries: [0-9]+ passed, [0-9]+ failed$' "$artifacts/libraries.log")
if [[ "$line" =~ ([0-9]+)\ passed,\ ([0-9]+)\ failed ]] && ((BASH_REMATCH[1] == 12)); then
  record "${BASH_REMATCH[1]}" "${BASH_REMATCH[2]}" "libraries"
else
  record 0 1 "libraries (expected 12: $line)"
fi
# The check can fail: a library linked the ordinary way needs libstdc++ and exports everything.
bad=$(mktemp -d)
printf '#include <string>\nstd::string sunflower_name() { return "x"; }\nextern "C" int sunflower_library_init() { return 0; }\n' >"$bad/bad.cpp"
g++ -shared -fPIC -o "$bad/libsunflower.linux.template_debug.x86_64.so" "$bad/bad.cpp"
if ! python3 "$repo/tools/check_libraries.py" "$bad/libsunflower.linux.template_debug.x86_64.so" >"$bad/out" &&
  grep -q "depends on libstdc++" "$bad/out" && grep -q "exports .* other symbols" "$bad/out"; then
  record 1 0 "the library check refuses a libstdc++ library with every symbol exported"
else
  cat "$bad/out"; record 0 1 "the library check refuses a libstdc++ library with every symbol exported"
fi
rm -rf "$bad"

echo "== gdlint and gdformat"
mapfile -t scripts < <(git ls-files '*.gd')
if (cd "$repo" && "$repo/.cache/venv/bin/gdlint" "${scripts[@]}"); then record 1 0 "gdlint"; else record 0 1 "gdlint"; fi
if "$repo/.cache/venv/bin/gdformat" --check --line-length 120 "${scripts[@]}"; then record 1 0 "gdformat"; else record 0 1 "gdformat"; fi

# $1 = label, $2 = project, $3 = rendering driver ("headless": no renderer), $4 = log, rest = tests (none: all)
engine_suite() {
  local label=$1 project=$2 driver=$3 log=$4; shift 4
  echo "== $label"
  local launch=(xvfb-run -a -s "-screen 0 1280x720x24" "$godot" --rendering-driver "$driver")
  [[ "$driver" == headless ]] && launch=("$godot" --headless)
  timeout 2400 "${launch[@]}" --verbose --audio-driver Dummy --resolution 640x360 \
    --path "$project" --script "res://$( [[ -d "$project/runner" ]] && echo runner || echo tests/runner )/run_tests.gd" \
    -- "$@" >"$log" 2>&1
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

engine_suite "engine tests (Godot under Xvfb, Forward+ on Vulkan lavapipe)" "$repo/tests/godot" vulkan "$artifacts/godot_tests.log"
cp "$artifacts/render_demo_field.png" "$artifacts/render_demo_field_vulkan.png" 2>/dev/null
engine_suite "render test (Compatibility renderer, OpenGL on llvmpipe)" "$repo/tests/godot" opengl3 "$artifacts/godot_render_gl.log" test_render
mv "$artifacts/render_demo_field.png" "$artifacts/render_demo_field_opengl.png" 2>/dev/null

engine_suite "demo tests (headless)" "$repo/demo_project" headless "$artifacts/demo_tests.log"

echo "== demo recording mode (Xvfb, Forward+): screenshot and stats"
frames=12
rm -f "$artifacts/demo_recording.png" "$artifacts/demo_stats.json"
timeout 600 xvfb-run -a -s "-screen 0 1280x720x24" "$godot" --audio-driver Dummy --resolution 640x360 \
  --path "$repo/demo_project" -- --frames "$frames" --screenshot "$artifacts/demo_recording.png" \
  --stats "$artifacts/demo_stats.json" >"$artifacts/demo_recording.log" 2>&1
grep '^demo:' "$artifacts/demo_recording.log"
if timeout 120 "$godot" --headless --path "$repo/demo_project" --script res://tests/cases/check_recording.gd -- \
  "$artifacts/demo_stats.json" "$artifacts/demo_recording.png" "$frames" 2>&1 | tee "$artifacts/demo_check.log" | grep '^recording:' &&
  grep -q '^recording: ok$' "$artifacts/demo_check.log"; then
  record 1 0 "demo recording"
else
  record 0 1 "demo recording"
fi

echo "== leaks at exit (--verbose output of the engine runs)"
if grep -E "leaked at exit|Leaked instance|were leaked|Orphan StringName|instances leaked" "$artifacts/godot_tests.log" "$artifacts/godot_render_gl.log" "$artifacts/demo_tests.log"; then
  record 0 1 "no leaks"
else
  record 1 0 "no leaks"
fi

echo "== drop-in: the release zip (tools/package.sh) unzipped into a new project, a scene without code"
dropin=$(mktemp -d)
if "$repo/tools/package.sh" >"$artifacts/dropin.log" 2>&1 && unzip -q "$repo"/build/dist/sunflower_field-*.zip -d "$dropin" &&
  cp "$repo/fields/demo.field" "$repo/tests/dropin/project.godot" "$repo/tests/dropin/main.tscn" "$repo/tests/dropin/terrain.tscn" \
    "$repo/tests/dropin/check_dropin.gd" "$repo/tests/dropin/check_exported_map.gd" "$dropin/" &&
  "$repo/tools/import_project.sh" "$dropin" >>"$artifacts/dropin.log" 2>&1 &&
  timeout 300 xvfb-run -a -s "-screen 0 1280x720x24" "$godot" --audio-driver Dummy \
    --path "$dropin" --script res://check_dropin.gd >>"$artifacts/dropin.log" 2>&1 &&
  grep -q '^dropin: ok$' "$artifacts/dropin.log"; then
  grep '^package:\|^dropin:' "$artifacts/dropin.log"; record 1 0 "drop-in from the release zip"
else
  tail -n 20 "$artifacts/dropin.log"; record 0 1 "drop-in from the release zip"
fi
echo "== an exported game has only the imported map: load_map_file(res://...) without the .field source"
if timeout 120 "$godot" --headless --path "$dropin" --script res://check_exported_map.gd -- record "$dropin/expected.txt" \
  >"$artifacts/exported_map.log" 2>&1 && rm "$dropin/demo.field" &&
  timeout 120 "$godot" --headless --path "$dropin" --script res://check_exported_map.gd -- compare "$dropin/expected.txt" \
    >>"$artifacts/exported_map.log" 2>&1 && grep -q '^exported map: ok' "$artifacts/exported_map.log"; then
  grep '^exported map:' "$artifacts/exported_map.log"; record 1 0 "exported map"
else
  tail -n 20 "$artifacts/exported_map.log"; record 0 1 "exported map"
fi
rm -rf "$dropin"

echo "== no library for this platform: the addon without bin/ in a new project, editor and game"
nolib=$(mktemp -d)
mkdir -p "$nolib/addons" "$nolib/.godot"
cp -rL "$repo/addons/sunflower_field" "$nolib/addons/" && rm -rf "$nolib/addons/sunflower_field/bin"
cp "$repo/fields/demo.field" "$repo/tests/dropin/project.godot" "$repo/tests/dropin/main.tscn" "$nolib/"
echo "res://addons/sunflower_field/sunflower_field.gdextension" >"$nolib/.godot/extension_list.cfg"
timeout 300 "$godot" --headless --path "$nolib" --import >"$artifacts/nolib_import.log" 2>&1
timeout 300 "$godot" --headless --editor --path "$nolib" res://main.tscn --quit-after 150 >"$artifacts/nolib_editor.log" 2>&1
timeout 300 "$godot" --headless --path "$nolib" --quit-after 150 >"$artifacts/nolib_game.log" 2>&1
for run in editor game; do
  log="$artifacts/nolib_$run.log"
  ours=$(grep -c "Sunflower Field: no native library for Linux x86_64 .*tools/build.sh --all" "$log")
  # The engine's own loader reports the missing file in its words (lines an addon cannot silence);
  # every other error counts.
  others=$(grep -E "^(ERROR|SCRIPT ERROR|USER ERROR)" "$log" | grep -v "Sunflower Field: no native library" |
    grep -v -E 'GDExtension dynamic library not found|Error loading extension|No GDExtension library found|Condition "!FileAccess::exists\(path\)"' | wc -l)
  if ((ours == 1 && others == 0)); then
    record 1 0 "no library ($run): one clear error, no other"
  else
    grep -E "^(ERROR|SCRIPT ERROR|USER ERROR)" "$log" | head -n 10; record 0 1 "no library ($run): $ours of ours, $others other errors"
  fi
done
rm -rf "$nolib"

echo "== editor (headless): open and close scenes with a field (a large one builds in the background, with"
echo "   the plugin's progress bar); import a malformed map"
for scene in field_scene large_field_scene; do
  if timeout 300 "$godot" --headless --editor --path "$repo/tests/godot" "res://scenes/$scene.tscn" --quit-after 200 \
    >"$artifacts/editor_$scene.log" 2>&1 && ! grep -E "SCRIPT ERROR|^ERROR" "$artifacts/editor_$scene.log"; then
    record 1 0 "editor opens $scene"
  else
    tail -n 20 "$artifacts/editor_$scene.log"; record 0 1 "editor opens $scene"
  fi
done
echo "== editor (headless): painting a field with synthetic mouse events, undo and redo, the file written back"
paintproj=$(mktemp -d)
mkdir -p "$paintproj/addons"
cp -rL "$repo/addons/sunflower_field" "$paintproj/addons/"
cp -r "$repo/tests/editor_paint/paint_probe" "$paintproj/addons/"
cp "$repo/tests/editor_paint/"{project.godot,paint.field,paint.tscn} "$paintproj/"
if "$repo/tools/import_project.sh" "$paintproj" >"$artifacts/editor_paint.log" 2>&1 &&
  RUN_PROBE=1 timeout 300 "$godot" --headless --editor --path "$paintproj" >>"$artifacts/editor_paint.log" 2>&1 &&
  grep -q '^probe: ok$' "$artifacts/editor_paint.log"; then
  record 1 0 "editor: paint, erase, undo, redo, write-back, a missing file"
else
  grep -E '^probe:|ERROR' "$artifacts/editor_paint.log" | head -n 10
  record 0 1 "editor: paint, erase, undo, redo, write-back, a missing file"
fi
rm -rf "$paintproj"
echo "== editor (Xvfb, Vulkan): a plant selected in the inspector, its 'Bake impostors' button pressed"
bakeproj=$(mktemp -d)
mkdir -p "$bakeproj/addons"
cp -rL "$repo/addons/sunflower_field" "$bakeproj/addons/"
cp -r "$repo/tests/editor_bake/bake_probe" "$bakeproj/addons/"
cp "$repo/tests/editor_bake/"{project.godot,my_plant.tres,own_plant_terrain.tscn,check_own_plant.gd} "$repo/fields/demo.field" \
  "$bakeproj/"
if "$repo/tools/import_project.sh" "$bakeproj" >"$artifacts/editor_bake.log" 2>&1 &&
  RUN_PROBE=1 PROBE_SHOT="$artifacts/editor_bake.png" timeout 300 xvfb-run -a -s "-screen 0 1600x900x24" "$godot" --editor \
    --audio-driver Dummy --path "$bakeproj" >>"$artifacts/editor_bake.log" 2>&1 &&
  grep -q '^probe: ok$' "$artifacts/editor_bake.log"; then
  record 1 0 "editor: Bake impostors writes, imports and saves the plant's textures"
else
  grep -E '^probe:|ERROR' "$artifacts/editor_bake.log" | head -n 10
  record 0 1 "editor: Bake impostors writes, imports and saves the plant's textures"
fi
# Then the game: a scene without code grows that plant, with its baked impostors, on a collider terrain.
if timeout 300 xvfb-run -a -s "-screen 0 1280x720x24" "$godot" --audio-driver Dummy --path "$bakeproj" \
  --script res://check_own_plant.gd >"$artifacts/own_plant.log" 2>&1 && grep -q '^own plant: ok$' "$artifacts/own_plant.log"; then
  grep '^own plant:' "$artifacts/own_plant.log" | head -n 1; record 1 0 "own plant on a collider terrain"
else
  grep -E '^own plant:|ERROR' "$artifacts/own_plant.log" | head -n 10; record 0 1 "own plant on a collider terrain"
fi
rm -rf "$bakeproj"
badproject=$(mktemp -d)
mkdir -p "$badproject/addons" "$badproject/.godot"
cp -rL "$repo/addons/sunflower_field" "$badproject/addons/"
cp "$repo/tests/dropin/project.godot" "$badproject/"
printf '4 2\n****\n*?**\n' > "$badproject/bad.field"
echo "res://addons/sunflower_field/sunflower_field.gdextension" > "$badproject/.godot/extension_list.cfg"
timeout 300 "$godot" --headless --path "$badproject" --import >"$artifacts/import_bad.log" 2>&1
status=$?
if ((status == 0)) && grep -q "cannot import res://bad.field:3:2: unexpected '?'" "$artifacts/import_bad.log"; then
  grep -o "cannot import res://bad.field:3:2: [^\"]*" "$artifacts/import_bad.log" | head -n 1
  record 1 0 "import error names file, line and column"
else
  tail -n 20 "$artifacts/import_bad.log"; record 0 1 "import error names file, line and column"
fi
rm -rf "$badproject"

fuzz_finish
echo "artifacts: $artifacts"
echo "time: $SECONDS s ($build_seconds s of it the build)"
echo "total: $passed passed, $failed failed"
((failed == 0 && passed > 0))
