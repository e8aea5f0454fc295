#!/usr/bin/env bash
# The far levels against the full-mesh picture, every view and every switch: runs the engine test
# tests/godot/cases/test_fidelity.gd with FIDELITY_FULL=1 under Xvfb (Forward+ on Vulkan lavapipe,
# 640 × 360). Per view (head height inside, 5 m and 40 m outside, 25 m up at 45°, 60 m straight
# down) it prints the SSIM and mean difference to the same view with every plant as mesh 1 and the
# impostor region's share and brightness relative to it; for the aerial views, also anti-aliased
# (drawn at 2 560 × 1 440 and box-filtered 4 × 4) and the meshes against themselves moved a quarter
# and half a pixel; per switch distance, the pop ratio of a 2 cm-a-frame walk across it. The test
# command runs the same test on three views and one switch.
# Pictures: tests/artifacts/fidelity/<view>.{auto,mesh1,mask}.png, and side by side in
# tests/artifacts/fidelity/<view>.pair.png (automatic LOD left, every plant as mesh 1 right).
set -euo pipefail
repo=$(cd "$(dirname "$0")/.." && pwd)
"$repo/tools/build.sh" >/dev/null
godot=$("$repo/tools/find_godot.sh")
"$repo/tools/import_project.sh" "$repo/tests/godot" >/dev/null
log="$repo/tests/artifacts/fidelity.log"
mkdir -p "$repo/tests/artifacts"
FIDELITY_FULL=1 timeout 3600 xvfb-run -a -s "-screen 0 2560x1440x24" "$godot" --rendering-driver vulkan \
  --audio-driver Dummy --resolution 640x360 --path "$repo/tests/godot" --script res://runner/run_tests.gd \
  -- test_fidelity >"$log" 2>&1 || true
grep -E '^(ok|FAIL) |^     |^godot:' "$log"
"$repo/.cache/venv/bin/python" - "$repo/tests/artifacts/fidelity" <<'PY'
import pathlib, sys
from PIL import Image
folder = pathlib.Path(sys.argv[1])
for auto in sorted(folder.glob("*.auto.png")):
    full = auto.with_name(auto.name.replace(".auto.", ".mesh1."))
    if not full.exists():  # a picture of another run, without its full-mesh one
        continue
    a, b = Image.open(auto), Image.open(full)
    pair = Image.new("RGB", (a.width + b.width + 8, a.height), "white")
    pair.paste(a, (0, 0))
    pair.paste(b, (a.width + 8, 0))
    pair.save(auto.with_name(auto.name.replace(".auto.", ".pair.")))
PY
