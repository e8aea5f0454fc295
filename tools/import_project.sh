#!/usr/bin/env bash
# Imports a Godot project's assets (headless). The extension is listed in .godot/extension_list.cfg
# beforehand, so the import does not hot-load it (which crashes at exit: godot#111048).
set -euo pipefail
repo=$(cd "$(dirname "$0")/.." && pwd)
project=${1:?usage: import_project.sh PROJECT_DIR}
godot=$("$repo/tools/find_godot.sh")
# Done already when nothing in the project (its linked folders too) changed since the last import.
stamp="$project/.godot/.imported_by_import_project"
if [[ -f "$stamp" && -z "$(find -L "$project" -path "$project/.godot" -prune -o -newer "$stamp" -print -quit)" ]]; then
  echo "import_project: $(basename "$project") is up to date"; exit 0
fi
mkdir -p "$project/.godot"
echo "res://addons/sunflower_field/sunflower_field.gdextension" > "$project/.godot/extension_list.cfg"
log=$(mktemp)
if ! timeout 600 "$godot" --headless --path "$project" --import >"$log" 2>&1; then
  cat "$log"; echo "import_project: importing $project failed" >&2; exit 1
fi
if grep -E "SCRIPT ERROR|^ERROR" "$log" | grep -v "Condition \"status < 0\"" >/dev/null; then
  grep -E -A3 "SCRIPT ERROR|^ERROR" "$log" >&2; echo "import_project: errors while importing $project" >&2; rm -f "$log"; exit 1
fi
rm -f "$log"
touch "$stamp"
echo "import_project: imported $(basename "$project")"
