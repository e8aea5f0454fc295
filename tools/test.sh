#!/usr/bin/env bash
# Runs the tests. Ends with "total: N passed, N failed" and a non-zero exit on any failure.
#   tools/test.sh                    every suite; builds every platform's library first (what CI runs);
#                                    the engine suite in one lane, the others beside it (see "Two lanes")
#   tools/test.sh --quick            the inner loop: this machine's build, the core's tests, lint and
#                                    the engine tests that need no renderer (headless)
#   tools/test.sh --suite NAME[,..]  only these suites (repeatable); see --list
#   tools/test.sh --filter PATTERN   only the tests matching PATTERN (a doctest name pattern for the
#                                    core, a runner pattern such as test_render or *lone* for the
#                                    engine and demo suites); without --suite: the core and engine suites
#   tools/test.sh --no-build         use what is built (after a build of your own)
#   tools/test.sh --list | --help
set -uo pipefail
repo=$(cd "$(dirname "$0")/.." && pwd)
cd "$repo"

# name|what it checks; the order is the order they run in.
SUITES=(
  "core|the C++ core's unit tests (doctest), no engine"
  "lint|gdlint and gdformat over every GDScript file"
  "platforms|every platform's library inspected; the core's tests built for Windows x86_64 (Wine) and Linux arm64 (QEMU)"
  "docs|links, images and GDScript snippets of README.md and docs/, the API reference and ARCHITECTURE.md current"
  "headless|the engine tests that need no renderer (headless Godot)"
  "engine|every engine test: Godot under Xvfb, Forward+ on Vulkan lavapipe"
  "opengl|the render tests again on the Compatibility renderer (OpenGL on llvmpipe)"
  "demo|the demo's own tests, its recording mode, and tools/demo.sh failing on a broken map or a missing library"
  "dropin|the release zip in a new project; an exported game's map; a project with no library"
  "editor|the editor: scenes with fields, painting, baking impostors, a malformed map's import"
  "fuzz|libFuzzer (ASan + UBSan) over the map parser, the layout and a simulation step, and over play's changes"
)
# The engine tests that need no renderer: the "headless" suite runs them alone (the others read back
# what the renderer holds or draw pictures; the "engine" suite runs every test).
HEADLESS_TESTS=(test_addon test_settings test_budget test_scene_import '!test_budget.test_the_field_holds_a_gpu_time_*' test_build test_field test_ground test_interaction test_plant test_robustness test_species
  test_scene_plant '!test_scene_plant.test_a_lone_scene_plant_*'
  '!test_scene_plant.test_each_test_plants_impostor_*' '!test_scene_plant.test_each_test_plants_lone_*'
  '!test_scene_plant.test_empty_slots_of_a_plant_drawn_*'
  '!test_scene_plant.test_a_field_of_each_test_plant_*' '!test_scene_plant.test_a_thin_plants_far_impostor_*'
  '!test_scene_plant.test_a_dense_plants_impostors_*' '!test_field.test_a_plant_of_fewer_parts_*'
  '!test_field.test_buffers_reach_the_rendering_server' '!test_field.test_near_plants_cast_*'
  '!test_field.test_every_plant_is_drawn_exactly_once_*'
  '!test_field.test_merged_far_tiles_draw_each_place_once_*' '!test_species.test_a_hilly_field_*')
# The render tests the "opengl" suite repeats: those whose result depends on the renderer (and the
# back-light bake's, whose far leaves are lit by the renderer's own back-light term, and the test
# plants' lone impostors, baked on the renderer the test runs on: its normals and depths passes write
# what each renderer stores differently, and a dense plant's impostors in the sun: the Compatibility
# renderer finds where a pixel lies in the shadow from the vertices).
# (Not the stumps': their shader path is plant_bend's, which every render test's plants draw with.)
OPENGL_TESTS=(test_render test_plant_materials 'test_bake.test_a_backlit_*' 'test_scene_plant.test_each_test_plants_lone_*'
  'test_scene_plant.test_a_dense_*'
  '!test_render.test_cut_plants_leave_the_stumps_*')

usage() { sed -n '2,12p' "$0" | sed 's/^# \{0,1\}//'; }
list() { local s; for s in "${SUITES[@]}"; do printf '  %-10s %s\n' "${s%%|*}" "${s#*|}"; done; }
wanted=()
filter=""
build=all
quick=0
lane=0
while (($#)); do
  case "$1" in
    --quick) quick=1 ;;
    --suite) shift; IFS=, read -r -a more <<<"${1:-}"; wanted+=("${more[@]}") ;;
    --suite=*) IFS=, read -r -a more <<<"${1#--suite=}"; wanted+=("${more[@]}") ;;
    --filter) shift; filter=${1:-} ;;
    --filter=*) filter=${1#--filter=} ;;
    --no-build) build=none ;;
    --lane) lane=1; build=none ;; # run by this script itself: the suites beside the engine's (see below)
    --list) list; exit 0 ;;
    -h | --help) usage; echo; echo "suites:"; list; exit 0 ;;
    *) echo "test.sh: unknown argument '$1'" >&2; usage >&2; exit 2 ;;
  esac
  shift
done
((quick)) && wanted+=(core lint headless)
[[ -n "$filter" && ${#wanted[@]} -eq 0 ]] && wanted=(core engine)
if ((${#wanted[@]} == 0)); then
  for s in "${SUITES[@]}"; do [[ "${s%%|*}" == headless ]] || wanted+=("${s%%|*}"); done
fi
for w in "${wanted[@]}"; do
  known=0
  for s in "${SUITES[@]}"; do [[ "${s%%|*}" == "$w" ]] && known=1; done
  ((known)) || { echo "test.sh: no suite '$w'; the suites are:" >&2; list >&2; exit 2; }
done
runs() { local w; for w in "${wanted[@]}"; do [[ "$w" == "$1" ]] && return 0; done; return 1; }
# Only the platforms suite needs the other platforms' builds.
[[ $build == all ]] && ! runs platforms && build=host

passed=0
failed=0
since=$SECONDS
timings=()
# cpu = the CPU time (user + system, whole seconds) of every child that has ended so far (bash's
# times: its second line is the children's; run in this shell, not in a subshell, which has children
# of its own): with the wall time per suite it shows how much of a suite could run beside another.
# Call it as a command, not inside $(...).
times_file=$(mktemp)
trap 'rm -f "$times_file"' EXIT
cpu=0
children_cpu() {
  times >"$times_file"
  cpu=$(awk 'NR == 2 { for (i = 1; i <= 2; i++) { sub(/s$/, "", $i); split($i, t, "m"); s += t[1] * 60 + t[2] } printf "%d", s }' "$times_file")
}
cpu_since=0
record() { # $1 = passed count, $2 = failed count, $3 = what; with the seconds since the last one
  passed=$((passed + $1)); failed=$((failed + $2))
  printf '== %s: %d passed, %d failed (%d s)\n' "$3" "$1" "$2" $((SECONDS - since))
  since=$SECONDS
}
suite_done() { # $1 = suite; the wall time since it started and the CPU time its programs took
  children_cpu
  timings+=("$(printf '%-10s %4d s wall %5d s CPU' "$1" $((SECONDS - suite_start)) $((cpu - cpu_since)))")
  cpu_since=$cpu
}

case $build in
  all) "$repo/tools/build.sh" --all || { echo "build: 0 passed, 1 failed"; echo "total: 0 passed, 1 failed"; exit 1; } ;;
  host) "$repo/tools/build.sh" || { echo "build: 0 passed, 1 failed"; echo "total: 0 passed, 1 failed"; exit 1; } ;;
esac
if ((!lane)); then
  echo "== build: $SECONDS s"
  suite_start=0
  suite_done build
fi
since=$SECONDS
godot=$("$repo/tools/find_godot.sh")
artifacts="$repo/tests/artifacts"
mkdir -p "$artifacts"
xvfb=(xvfb-run -a -s "-screen 0 1280x720x24")

# $1 = label, rest = the doctest program and how to start it
doctest_suite() {
  local label=$1 out status line p f; shift
  echo "== $label"
  out=$(WINEDEBUG=-all timeout 900 "$@" ${filter:+-tc="*${filter}*"} 2>&1); status=$?
  echo "$out" | tail -n 4
  line=$(echo "$out" | grep -E 'test cases:' | tail -n 1)
  p=$(echo "$line" | sed -E 's/.*\| *([0-9]+) passed.*/\1/'); f=$(echo "$line" | sed -E 's/.*\| *([0-9]+) failed.*/\1/')
  [[ "$p" =~ ^[0-9]+$ && "$f" =~ ^[0-9]+$ ]] || { p=0; f=1; }
  ((status != 0 && f == 0)) && f=1
  ((p + f == 0)) && f=1 # a filter that selects nothing is a mistake, not a pass
  record "$p" "$f" "$label"
}

# $1 = label, $2 = project, $3 = rendering driver ("headless": no renderer), $4 = log, rest = tests
# (none: all); the --filter pattern, when given, in their place. suite_env: more of the run's environment.
suite_env=()
engine_suite() {
  local label=$1 project=$2 driver=$3 log=$4; shift 4
  [[ -n "$filter" ]] && set -- "$filter"
  echo "== $label"
  local launch=("${xvfb[@]}" "$godot" --rendering-driver "$driver")
  [[ "$driver" == headless ]] && launch=("$godot" --headless)
  env "${suite_env[@]}" timeout 2400 "${launch[@]}" --verbose --audio-driver Dummy --resolution 640x360 \
    --path "$project" --script "res://$([[ -d "$project/runner" ]] && echo runner || echo tests/runner)/run_tests.gd" \
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

# A project dir with a copy of the addon (and what else is given), its extension listed before import.
new_project() { # $1 = dir; copies the addon without following it being a link
  mkdir -p "$1/addons" "$1/.godot"
  cp -rL "$repo/addons/sunflower_field" "$1/addons/"
  echo "res://addons/sunflower_field/sunflower_field.gdextension" >"$1/.godot/extension_list.cfg"
}

# --- Two lanes -----------------------------------------------------------------------------------------
# The engine suite alone keeps 1.7 of the two cores busy: lavapipe shades vertices on the engine's
# main thread, its rasterising threads wait for them. After the core and lint suites it runs in this
# lane; the platforms, docs, fuzz, opengl, demo, dropin and editor suites run beside it in a second
# run of this script, each in a project or user folder of its own, with the engine suite's
# BESIDE_ENGINE_TESTS (which balance the two lanes' time); their output follows the engine suite's.
# (Measured in a fresh-clone run: the engine suite 643 s, the second lane about 660 s with this pop
# walk in it, 64 s; the walk where far tiles merge, 42 s, runs in the engine suite, which it would
# otherwise outlast.)
BESIDE_ENGINE_TESTS=('test_fidelity.test_no_pops_where_plants_switch_level')
beside=()
if ((!lane)) && [[ -z "$filter" ]] && runs engine; then
  for s in platforms docs fuzz opengl demo dropin editor; do runs "$s" && beside+=("$s"); done
  for s in "${beside[@]}"; do # run there, not here
    for i in "${!wanted[@]}"; do [[ "${wanted[i]}" == "$s" ]] && unset 'wanted[i]'; done
  done
fi

# --- The fuzzer starts first and runs beside the platforms and docs suites (in the second lane, when
# there is one) -----------------------------------------------------------------------------------------
# It keeps one core busy for its build and 60 s; the core's tests under Wine and QEMU keep the other.
if runs fuzz; then
  fuzz_seconds=${FUZZ_SECONDS:-60}
  (
    corpus=$(mktemp -d)
    changes_corpus=$(mktemp -d)
    # Two thirds of the time to the map parser and layout, a third to sequences of play's changes.
    "$repo/.cache/venv/bin/scons" -Q -j1 fuzz >"$artifacts/fuzz_build.log" 2>&1 &&
      "$repo/build/fuzz/fuzz_field_map" -max_total_time=$((fuzz_seconds * 2 / 3)) -max_len=4096 -print_final_stats=1 \
        -artifact_prefix="$artifacts/fuzz-" "$corpus" "$repo/gdextension/fuzz/corpus" >"$artifacts/fuzz.log" 2>&1 &&
      "$repo/build/fuzz/fuzz_field_changes" -max_total_time=$((fuzz_seconds / 3)) -max_len=2048 -print_final_stats=1 \
        -artifact_prefix="$artifacts/fuzz-changes-" "$changes_corpus" "$repo/gdextension/fuzz/corpus_changes" >"$artifacts/fuzz_changes.log" 2>&1
    status=$?
    rm -rf "$changes_corpus"
    rm -rf "$corpus"
    exit $status
  ) &
  fuzz_pid=$!
fi

if runs core; then
  suite_start=$SECONDS
  doctest_suite "core unit tests (doctest)" "$repo/build/tests/core_tests"
  suite_done core
fi

if runs lint; then
  suite_start=$SECONDS
  echo "== gdlint and gdformat"
  mapfile -t scripts < <(git ls-files '*.gd')
  if "$repo/.cache/venv/bin/gdlint" "${scripts[@]}"; then record 1 0 "gdlint"; else record 0 1 "gdlint"; fi
  if "$repo/.cache/venv/bin/gdformat" --check --line-length 120 "${scripts[@]}"; then record 1 0 "gdformat"; else record 0 1 "gdformat"; fi
  # An addon script does one job and is read whole: at most 500 lines (tests and tools may be longer).
  long_scripts=$(git ls-files 'addons/*.gd' | xargs wc -l | awk '$2 != "total" && $1 > 500 {print $2 " (" $1 " lines)"}')
  if [[ -z "$long_scripts" ]]; then record 1 0 "addon scripts of at most 500 lines"
  else echo "over 500 lines: $long_scripts"; record 0 1 "addon scripts of at most 500 lines"; fi
  suite_done lint
fi

# --- The second lane starts ----------------------------------------------------------------------------
if ((${#beside[@]})); then
  lane_log="$artifacts/lane.log"
  LANE_ENGINE_TESTS="${BESIDE_ENGINE_TESTS[*]}" bash "$repo/tools/test.sh" --lane --suite "$(IFS=,; echo "${beside[*]}")" \
    >"$lane_log" 2>&1 &
  lane_pid=$!
  echo "== beside the engine suite: ${beside[*]} (their output follows the engine suite's)"
fi

if runs platforms; then
  suite_start=$SECONDS
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
  doctest_suite "core unit tests built for Windows x86_64, under Wine" /usr/lib/wine/wine64 \
    "$repo/build/tests/core_tests.windows.x86_64.exe"
  # Under QEMU the core's tests run about 15 times slower than here (43 s alone, 127 s under the engine suite's
  # load); the three slowest (1.4 of the 3 s they take natively: long walks of the observer over
  # the layout, arithmetic the runs here and under Wine check on x86_64) are left to those runs, and
  # the arm64 run keeps every other case, the threaded ones among them (19 s alone).
  doctest_suite "core unit tests built for Linux arm64, under QEMU (all but the three slowest)" \
    qemu-aarch64-static -L /usr/aarch64-linux-gnu "$repo/build/tests/core_tests.linux.arm64" \
    -tce="far tiles merge with distance*,every plant is drawn exactly once along a path*,chunks out of view or wholly in it*"
  suite_done platforms
fi

if runs docs; then
  suite_start=$SECONDS
  echo "== the docs: links and images resolve, GDScript snippets parse, the API reference and ARCHITECTURE.md current"
  if python3 "$repo/tools/check_docs.py" --godot "$godot" --gdparse "$repo/.cache/venv/bin/gdparse" | tee "$artifacts/docs.log"; then
    record 1 0 "docs"
  else
    record 0 1 "docs"
  fi
  suite_done docs
fi

# --- The fuzzer, which ran beside the first suites, ends before the engine suites begin ----------
if runs fuzz; then
  suite_start=$SECONDS
  echo "== fuzzing the map parser and layout, then play's changes against a model, ${fuzz_seconds} s (libFuzzer, ASan + UBSan; run beside the first suites)"
  if wait "$fuzz_pid"; then
    grep -E "^Done" "$artifacts/fuzz.log" "$artifacts/fuzz_changes.log"
    record 1 0 "fuzzing"
  else
    tail -n 30 "$artifacts/fuzz_build.log" "$artifacts/fuzz.log" "$artifacts/fuzz_changes.log" 2>/dev/null; record 0 1 "fuzzing"
  fi
  suite_done fuzz
fi

if runs headless; then
  suite_start=$SECONDS
  engine_suite "engine tests that need no renderer (headless)" "$repo/tests/godot" headless \
    "$artifacts/godot_headless.log" "${HEADLESS_TESTS[@]}"
  suite_done headless
fi

if runs engine; then
  suite_start=$SECONDS
  left_out=()
  ((${#beside[@]})) && for t in "${BESIDE_ENGINE_TESTS[@]}"; do left_out+=("!$t"); done
  engine_suite "engine tests (Godot under Xvfb, Forward+ on Vulkan lavapipe)" "$repo/tests/godot" vulkan \
    "$artifacts/godot_tests.log" "${left_out[@]}"
  engine_wall=$((SECONDS - suite_start))
  [[ ${#beside[@]} -eq 0 ]] && suite_done engine
fi

if ((${#beside[@]})); then
  wait "$lane_pid"
  # The children's CPU time now holds the lane's programs as well as the engine suite's (the shell
  # reaps each as it ends, during the engine suite or in this wait): the engine suite's is what is left.
  lane_cpu=$(sed -n -E 's/^time: [0-9]+ s wall, ([0-9]+) s CPU.*/\1/p' "$lane_log")
  children_cpu
  timings+=("$(printf '%-10s %4d s wall %5d s CPU' engine "$engine_wall" $((cpu - cpu_since - ${lane_cpu:-0})))")
  sed -n '/^== /,/^artifacts: /{/^artifacts: /d;p}' "$lane_log"
  line=$(grep -E '^total: [0-9]+ passed, [0-9]+ failed$' "$lane_log")
  if [[ "$line" =~ ([0-9]+)\ passed,\ ([0-9]+)\ failed ]]; then
    passed=$((passed + BASH_REMATCH[1])); failed=$((failed + BASH_REMATCH[2]))
  else
    tail -n 20 "$lane_log"; record 0 1 "the suites beside the engine's ended without their total (log: $lane_log)"
  fi
  mapfile -t -O "${#timings[@]}" timings < <(sed -n '/^time per suite/,/^time:/p' "$lane_log" | grep -E '^  [a-z]' |
    sed -E 's/^  //; s/ wall / wall, beside the engine suite, /')
  cpu_since=$cpu
  since=$SECONDS
fi

# The engine suite's tests that run in the second lane, in a user folder of their own.
if ((lane)) && [[ -n "${LANE_ENGINE_TESTS:-}" ]]; then
  suite_start=$SECONDS
  read -r -a part <<<"$LANE_ENGINE_TESTS"
  suite_env=(XDG_DATA_HOME="$repo/.cache/lane_user_data")
  engine_suite "engine tests beside the others: ${part[*]}" "$repo/tests/godot" vulkan "$artifacts/godot_tests_beside.log" "${part[@]}"
  suite_env=()
  suite_done "engine, ${part[*]}"
fi

if runs opengl; then
  suite_start=$SECONDS
  # Its own user folder (the engine suite may run the same project beside it) and pictures folder.
  suite_env=(XDG_DATA_HOME="$repo/.cache/opengl_user_data" TEST_ARTIFACTS="$artifacts/opengl")
  engine_suite "render tests (Compatibility renderer, OpenGL on llvmpipe)" "$repo/tests/godot" opengl3 \
    "$artifacts/godot_render_gl.log" "${OPENGL_TESTS[@]}"
  suite_env=()
  suite_done opengl
fi

if runs demo; then
  suite_start=$SECONDS
  engine_suite "demo tests (headless)" "$repo/demo_project" headless "$artifacts/demo_tests.log"
  if [[ -z "$filter" ]]; then
    echo "== demo recording mode (Xvfb, Forward+): screenshot and stats"
    frames=12
    rm -f "$artifacts/demo_recording.png" "$artifacts/demo_stats.json"
    timeout 300 "${xvfb[@]}" "$godot" --audio-driver Dummy --resolution 640x360 \
      --path "$repo/demo_project" -- --frames "$frames" --screenshot "$artifacts/demo_recording.png" \
      --stats "$artifacts/demo_stats.json" >"$artifacts/demo_recording.log" 2>&1
    grep '^demo:' "$artifacts/demo_recording.log"
    if timeout 120 "$godot" --headless --path "$repo/demo_project" --script res://tests/cases/check_recording.gd -- \
      "$artifacts/demo_stats.json" "$artifacts/demo_recording.png" "$frames" 2>&1 | tee "$artifacts/demo_check.log" |
      grep '^recording:' && grep -q '^recording: ok$' "$artifacts/demo_check.log"; then
      record 1 0 "demo recording"
    else
      record 0 1 "demo recording"
    fi
    echo "== the Hillside map rendered (Xvfb, Forward+, 60 m above): its track bare, its meadows planted"
    rm -f "$artifacts/hillside.png" "$artifacts/hillside_stats.json"
    timeout 300 "${xvfb[@]}" "$godot" --audio-driver Dummy --resolution 640x360 --path "$repo/demo_project" -- \
      --map res://fields/hillside.field --view down60 --frames 4 --shadows off --no-hud \
      --screenshot "$artifacts/hillside.png" --stats "$artifacts/hillside_stats.json" >"$artifacts/hillside.log" 2>&1
    if timeout 120 "$godot" --headless --path "$repo/demo_project" --script res://tests/cases/check_hillside.gd -- \
      "$artifacts/hillside_stats.json" "$artifacts/hillside.png" 2>&1 | tee "$artifacts/hillside_check.log" |
      grep '^hillside:' && grep -q '^hillside: ok$' "$artifacts/hillside_check.log"; then
      record 1 0 "hillside render"
    else
      grep '^demo:' "$artifacts/hillside.log" | tail -n 5; record 0 1 "hillside render"
    fi
    echo "== the demo's play: a trail walked and the scythe swung, saved at quit, restored by --load-changes"
    play_dir=$(mktemp -d)
    printf '1 1.7 7.5 6 1.0 7.5\n19 1.7 7.5 24 1.0 7.5\n' >"$play_dir/walk.path"
    printf '10 12 11 10 0 7.5\n10 12 11 10 0 7.5\n' >"$play_dir/look.path"
    play_run() { # $1 = log, rest = demo arguments
      local log=$1
      shift
      timeout 300 "${xvfb[@]}" "$godot" --audio-driver Dummy --resolution 320x180 --path "$repo/demo_project" -- \
        --map res://fields/demo.field --shadows off --no-hud "$@" >"$log" 2>&1
    }
    play_run "$artifacts/play_walk.log" --path "$play_dir/walk.path" --frames 24 --cut-every 6
    play_run "$artifacts/play_loaded.log" --path "$play_dir/look.path" --frames 3 --wind 0 --load-changes \
      --screenshot "$artifacts/play_loaded.png"
    play_run "$artifacts/play_plain.log" --path "$play_dir/look.path" --frames 3 --wind 0 \
      --screenshot "$artifacts/play_plain.png"
    rm -rf "$play_dir"
    if timeout 120 "$godot" --headless --path "$repo/demo_project" --script res://tests/cases/check_play.gd -- \
      "$artifacts/play_plain.png" "$artifacts/play_loaded.png" "$artifacts/play_walk.log" "$artifacts/play_loaded.log" 2>&1 |
      tee "$artifacts/play_check.log" | grep '^play:' && grep -q '^play: ok$' "$artifacts/play_check.log"; then
      record 1 0 "demo play restored"
    else
      grep '^demo:' "$artifacts/play_walk.log" "$artifacts/play_loaded.log" | tail -n 6; record 0 1 "demo play restored"
    fi
    echo "== tools/demo.sh fails, saying why, on a broken map and on a missing library"
    broken=$(mktemp -d)
    printf '4 2\n****\n*?**\n' >"$broken/broken.field"
    if ! env -u DISPLAY bash "$repo/tools/demo.sh" --no-build --map "$broken/broken.field" --frames 2 >"$artifacts/demo_broken_map.log" 2>&1 &&
      grep -q "demo: FAILED: .*broken.field:3:2" "$artifacts/demo_broken_map.log"; then
      grep "demo: FAILED" "$artifacts/demo_broken_map.log" | head -n 1; record 1 0 "demo.sh: a broken map fails the demo"
    else
      tail -n 10 "$artifacts/demo_broken_map.log"; record 0 1 "demo.sh: a broken map fails the demo"
    fi
    lib="$repo/addons/sunflower_field/bin/libsunflower.linux.template_debug.x86_64.so"
    mv "$lib" "$broken/"
    if ! env -u DISPLAY bash "$repo/tools/demo.sh" --no-build --frames 2 >"$artifacts/demo_no_library.log" 2>&1 &&
      grep -q "demo: FAILED" "$artifacts/demo_no_library.log" && grep -q "no native library" "$artifacts/demo_no_library.log"; then
      grep "demo: FAILED" "$artifacts/demo_no_library.log" | head -n 1; record 1 0 "demo.sh: a missing library fails the demo"
    else
      tail -n 10 "$artifacts/demo_no_library.log"; record 0 1 "demo.sh: a missing library fails the demo"
    fi
    mv "$broken/$(basename "$lib")" "$lib"
    rm -rf "$broken"
  fi
  suite_done demo
fi

if runs dropin; then
  suite_start=$SECONDS
  echo "== drop-in: the release zip (tools/package.sh) unzipped into a new project, a scene without code"
  dropin=$(mktemp -d)
  if "$repo/tools/package.sh" >"$artifacts/dropin.log" 2>&1 && unzip -q "$repo"/build/dist/sunflower_field-*.zip -d "$dropin" &&
    cp "$repo/fields/demo.field" "$repo/tests/dropin/"{project.godot,main.tscn,terrain.tscn,check_dropin.gd,check_exported_map.gd} \
      "$dropin/" &&
    "$repo/tools/import_project.sh" "$dropin" >>"$artifacts/dropin.log" 2>&1 &&
    timeout 300 "${xvfb[@]}" "$godot" --audio-driver Dummy \
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
  new_project "$nolib"
  rm -rf "$nolib/addons/sunflower_field/bin"
  cp "$repo/fields/demo.field" "$repo/tests/dropin/project.godot" "$repo/tests/dropin/main.tscn" "$nolib/"
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
  suite_done dropin
fi

if runs editor; then
  suite_start=$SECONDS
  echo "== editor (headless): open and close scenes with a field (a large one builds in the background, with"
  echo "   the plugin's progress bar); a new field's inspector and saved scene"
  # In a copy of the test project, imported as it is: the engine suite may be running the project itself.
  scenes=$(mktemp -d)
  cp -rL "$repo/tests/godot/." "$scenes/"
  for scene in field_scene large_field_scene; do
    if timeout 300 "$godot" --headless --editor --path "$scenes" "res://scenes/$scene.tscn" --quit-after 200 \
      >"$artifacts/editor_$scene.log" 2>&1 && ! grep -E "SCRIPT ERROR|^ERROR" "$artifacts/editor_$scene.log"; then
      record 1 0 "editor opens $scene"
    else
      tail -n 20 "$artifacts/editor_$scene.log"; record 0 1 "editor opens $scene"
    fi
  done
  rm -rf "$scenes"
  echo "== editor (headless): painting a field with synthetic mouse events, undo and redo, the file written back"
  paintproj=$(mktemp -d)
  new_project "$paintproj"
  cp -r "$repo/tests/editor_paint/paint_probe" "$paintproj/addons/"
  cp "$repo/tests/editor_paint/"{project.godot,paint.field,paint.tscn} "$paintproj/"
  if "$repo/tools/import_project.sh" "$paintproj" >"$artifacts/editor_paint.log" 2>&1 &&
    RUN_PROBE=1 timeout 300 "$godot" --headless --editor --path "$paintproj" >>"$artifacts/editor_paint.log" 2>&1 &&
    grep -q '^probe: ok$' "$artifacts/editor_paint.log" &&
    # The one error expected is the probe's missing file; Ctrl+Z printed "Inconsistent undo history" once.
    ! grep -E "SCRIPT ERROR|^ERROR" "$artifacts/editor_paint.log" | grep -v "res://gone.field"; then
    grep '^probe:' "$artifacts/editor_paint.log" | tail -n 1
    record 1 0 "editor: paint, erase, Ctrl+Z, Ctrl+Y, write-back, a missing file, a new field; no unexpected error"
  else
    grep -E '^probe:|ERROR' "$artifacts/editor_paint.log" | head -n 10
    record 0 1 "editor: paint, erase, Ctrl+Z, Ctrl+Y, write-back, a missing file, a new field; no unexpected error"
  fi
  rm -rf "$paintproj"
  echo "== editor (Xvfb, Vulkan): a plant selected in the inspector, its 'Bake impostors' button pressed; three glTF"
  echo "   plants dropped on a field's 'Plant from scene…' (the steps shown); a field removed while its plant bakes; a"
  echo "   scene of 307 200 triangles merged while the editor draws"
  bakeproj=$(mktemp -d)
  new_project "$bakeproj"
  cp -r "$repo/tests/editor_bake/bake_probe" "$bakeproj/addons/"
  cp "$repo/tests/editor_bake/"{project.godot,my_plant.tres,own_plant_terrain.tscn,check_own_plant.gd} "$repo/fields/demo.field" \
    "$repo/assets/test_plants/"*.glb "$bakeproj/"
  if "$repo/tools/import_project.sh" "$bakeproj" >"$artifacts/editor_bake.log" 2>&1 &&
    RUN_PROBE=1 PROBE_SHOT="$artifacts/editor_bake.png" timeout 300 xvfb-run -a -s "-screen 0 1600x900x24" "$godot" --editor \
      --audio-driver Dummy --path "$bakeproj" >>"$artifacts/editor_bake.log" 2>&1 &&
    grep -q '^probe: ok$' "$artifacts/editor_bake.log" &&
    grep -q "the field left the edited scene while res://grass_clump_plant.*tres baked" "$artifacts/editor_bake.log" &&
    ! grep -E "SCRIPT ERROR|leaked at exit|still in use at exit" "$artifacts/editor_bake.log"; then
    grep '^probe:' "$artifacts/editor_bake.log" | head -n 4
    record 1 0 "editor: Bake impostors writes, imports and saves the plant's textures; glTF plants dropped on a field; a field removed mid-bake"
  else
    grep -E '^probe:|ERROR' "$artifacts/editor_bake.log" | head -n 10
    record 0 1 "editor: Bake impostors writes, imports and saves the plant's textures; glTF plants dropped on a field; a field removed mid-bake"
  fi
  # Then the game: a scene without code grows that plant, with its baked impostors, on a collider terrain.
  if timeout 300 "${xvfb[@]}" "$godot" --audio-driver Dummy --path "$bakeproj" \
    --script res://check_own_plant.gd >"$artifacts/own_plant.log" 2>&1 && grep -q '^own plant: ok$' "$artifacts/own_plant.log"; then
    grep '^own plant:' "$artifacts/own_plant.log" | head -n 1; record 1 0 "own plant on a collider terrain"
  else
    grep -E '^own plant:|ERROR' "$artifacts/own_plant.log" | head -n 10; record 0 1 "own plant on a collider terrain"
  fi
  rm -rf "$bakeproj"
  badproject=$(mktemp -d)
  new_project "$badproject"
  cp "$repo/tests/dropin/project.godot" "$badproject/"
  printf '4 2\n****\n*\t**\n' >"$badproject/bad.field"
  timeout 300 "$godot" --headless --path "$badproject" --import >"$artifacts/import_bad.log" 2>&1
  status=$?
  if ((status == 0)) && grep -q "cannot import res://bad.field:3:2: unexpected tab character" "$artifacts/import_bad.log"; then
    grep -o "cannot import res://bad.field:3:2: [^\"]*" "$artifacts/import_bad.log" | head -n 1
    record 1 0 "import error names file, line and column"
  else
    tail -n 20 "$artifacts/import_bad.log"; record 0 1 "import error names file, line and column"
  fi
  rm -rf "$badproject"
  suite_done editor
fi

# The suites run here or beside the engine suite (whose run leaves this check to this one).
ran() { runs "$1" || [[ " ${beside[*]} " == *" $1 "* ]]; }
if ((!lane)) && { ran engine || ran opengl || ran demo; }; then
  echo "== leaks at exit (--verbose output of the engine runs)"
  logs=()
  ran engine && logs+=("$artifacts/godot_tests.log")
  ((${#beside[@]})) && logs+=("$artifacts/godot_tests_beside.log")
  ran opengl && logs+=("$artifacts/godot_render_gl.log")
  ran demo && logs+=("$artifacts/demo_tests.log")
  if grep -E "leaked at exit|Leaked instance|were leaked|Orphan StringName|instances leaked" "${logs[@]}"; then
    record 0 1 "no leaks"
  else
    record 1 0 "no leaks"
  fi
fi

echo "artifacts: $artifacts"
echo "time per suite (wall, and the CPU time of its programs; the fuzzer's wall time is the wait for it, its"
echo "CPU time counted in the suite that ran when it ended):"
printf '  %s\n' "${timings[@]}"
children_cpu
echo "time: $SECONDS s wall, $cpu s CPU (this work on $(nproc) cores takes at least $((cpu / $(nproc))) s)"
echo "total: $passed passed, $failed failed"
((failed == 0 && passed > 0))
