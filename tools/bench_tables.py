#!/usr/bin/env python3
"""Prints tables 2-4 and 8 of tools/bench.sh from the demo's JSON statistics in a folder."""
import json
import os
import statistics
import sys

THESIS_TABLE4_1500 = [12, 16, 20, 56, 88]  # FPS, 1 500 plants: model 1, 2, 3, sprite, billboard
THESIS_TABLE5 = {5: [8, 12, 30], 40: [8, 54, 54]}  # angular order only, + LOD, + LOD + culling
NAMES = ["model 1", "model 2", "model 3", "sprite", "billboard"]


def load(folder, name):
    try:
        with open(os.path.join(folder, name + ".json"), encoding="utf-8") as f:
            return json.load(f)
    except (OSError, ValueError):
        return None


def fps(stats):
    return 1000.0 / stats["frame_ms"]["median"] if stats and stats["frame_ms"]["median"] > 0 else float("nan")


def settled_frame_ms(stats):
    """The median frame after the first (which compiles shaders under software rendering)."""
    times = stats.get("frame_times_ms", [])[1:]
    return statistics.median(times) if times else float("nan")


def main(folder):
    print("\n## 2. In the engine (the demo's recording mode along its built-in flight)\n")
    print("Build: blocking, or in the background (maps of 64 KB and more); wall time from the map's assignment to")
    print("field_built (with software rendering this includes the first frames' shader compilation), the work on")
    print("the worker and on the main thread, the frames it spanned and the longest it held one frame up.\n")
    print("| field | plants | build | wall ms | worker ms | main thread ms | frames | longest step ms | FPS | frame ms median / p99 | native update ms median / p99 | CPU MB |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|")
    nan = float("nan")
    for name, label in (("engine_demo", "demo 40 x 30"), ("engine_large", "large 400 x 300"), ("engine_million", "million 1000 x 1000"),
                        ("engine_million_headless", "million, headless (no rendering)")):
        s = load(folder, name)
        if not s:
            print(f"| {label} | run failed | | | | | | | | | | |")
            continue
        b = s.get("build", {})
        kind = "background" if b.get("background") else "blocking"
        shown = "(not drawn)" if name.endswith("headless") else f"{fps(s):.2f}"
        print(f"| {label} | {s['plants']} | {kind} | {b.get('total_ms', nan):.0f} | {b.get('worker_ms', nan):.0f} | "
              f"{b.get('main_thread_ms', nan):.0f} | {b.get('frames', 0)} | {b.get('longest_step_ms', nan):.1f} | {shown} | "
              f"{s['frame_ms']['median']:.1f} / {s['frame_ms']['p99']:.1f} | "
              f"{s['native_update_ms']['median']:.3f} / {s['native_update_ms']['p99']:.3f} | {s['native_memory_bytes'] / 1e6:.1f} |")

    print("\n## 3. The thesis' experiment: 1 500 plants (50 x 30), observer 5 m and 40 m before the field\n")
    print("Every plant as one representation (thesis Table 4, 1 500 plants), FPS and ratio to model 1:\n")
    print("| representation | FPS at 5 m | FPS at 40 m | ratio (5 m) | ratio (40 m) | thesis FPS | thesis ratio |")
    print("|---|---|---|---|---|---|---|")
    base = {view: fps(load(folder, f"thesis_{view}_force0")) for view in (5, 40)}
    for lod, name in enumerate(NAMES):
        row = {view: fps(load(folder, f"thesis_{view}_force{lod}")) for view in (5, 40)}
        print(f"| {name} | {row[5]:.2f} | {row[40]:.2f} | {row[5] / base[5]:.2f} | {row[40] / base[40]:.2f} | "
              f"{THESIS_TABLE4_1500[lod]} | {THESIS_TABLE4_1500[lod] / THESIS_TABLE4_1500[0]:.2f} |")
    print("\nAll optimisations (thesis Table 5), FPS and ratio to LOD off:\n")
    print("| observer | LOD off | LOD on | LOD + culling | ratios | thesis FPS | thesis ratios |")
    print("|---|---|---|---|---|---|---|")
    for view in (5, 40):
        runs = [fps(load(folder, f"thesis_{view}_force0")), fps(load(folder, f"thesis_{view}_lod")), fps(load(folder, f"thesis_{view}_lodcull"))]
        thesis = THESIS_TABLE5[view]
        print(f"| {view} m | {runs[0]:.2f} | {runs[1]:.2f} | {runs[2]:.2f} | 1 : {runs[1] / runs[0]:.2f} : {runs[2] / runs[0]:.2f} | "
              f"{thesis[0]} / {thesis[1]} / {thesis[2]} | 1 : {thesis[1] / thesis[0]:.2f} : {thesis[2] / thesis[0]:.2f} |")

    print("\n## 4. Baselines: the demo field along the built-in flight\n")
    print("| drawing | FPS | frame ms median / p99 | our frame time / theirs |")
    print("|---|---|---|---|")
    ours = load(folder, "baseline_ours")
    for name, label in (("baseline_ours", "this addon (LOD, wind, culling)"), ("baseline_naive", "naive: every plant as the level-1 mesh, no LOD"),
                        ("baseline_native", "Godot-native: chunked MultiMeshes, automatic mesh LOD, visibility cut-off")):
        s = load(folder, name)
        if not s or not ours:
            print(f"| {label} | run failed | | |")
            continue
        print(f"| {label} | {fps(s):.2f} | {s['frame_ms']['median']:.1f} / {s['frame_ms']['p99']:.1f} | "
              f"{ours['frame_ms']['median'] / s['frame_ms']['median']:.2f} |")

    print("\n## 8. The GPU side: still views, the renderer's own counts (median of the recorded frames)\n")
    print("Both drawings are cut off at 100 m. Primitives: the engine counts a MultiMesh whose mesh has automatic")
    print("LODs (the native way's) as one instance of the chosen LOD; the corrected figure multiplies the count by")
    print("the native way's plants per chunk (its MultiMeshes). Ours has no such meshes: its count is exact.")
    print("Memory: render buffers the drawing added (ours: after the field's first frame; native: after its build).")
    print("Frame time: the software renderer's median frame, the first frame (shader compilation) left out.\n")
    print("| field | view | draw calls ours / native | ratio | objects ours / native | primitives ours | native as counted / corrected | frame ms ours / native | ratio |")
    print("|---|---|---|---|---|---|---|---|---|")
    memory = {}
    draw_calls = {}
    for field in ("demo", "large", "million", "4m"):
        for view in ("inside", "outside40", "above45", "down60"):
            ours = load(folder, f"gpu_{field}_{view}_ours")
            native = load(folder, f"gpu_{field}_{view}_native")
            if not ours or not native or "draw_calls" not in ours:
                print(f"| {field} | {view} | run failed | | | | | | |")
                continue
            dc = (ours["draw_calls"]["median"], native["draw_calls"]["median"])
            ob = (ours["objects"]["median"], native["objects"]["median"])
            pr = (ours["primitives"]["median"], native["primitives"]["median"])
            chunks = native.get("baseline_chunks") or 0
            corrected = f"{pr[1] * native['plants'] / chunks:,.0f}" if chunks else "—"
            ratio = dc[0] / dc[1] if dc[1] else float("nan")
            draw_calls[(field, view)] = dc[0]
            ms = (settled_frame_ms(ours), settled_frame_ms(native))
            print(f"| {field} ({ours['plants']:,}) | {view} | {dc[0]:.0f} / {dc[1]:.0f} | {ratio:.2f} | {ob[0]:.0f} / {ob[1]:.0f} | "
                  f"{pr[0]:,.0f} | {pr[1]:,.0f} / {corrected} | {ms[0]:.0f} / {ms[1]:.0f} | {ms[0] / ms[1]:.2f} |")
            mem = native.get("buffer_memory_bytes", {})
            if field not in memory and {"before", "field", "baseline"} <= mem.keys():
                memory[field] = (ours["plants"], mem["field"] - mem["before"], mem["baseline"] - mem["field"])
    scaling = [f"{view} {draw_calls[('4m', view)] / draw_calls[('million', view)]:.2f}"
               for view in ("inside", "outside40", "above45", "down60")
               if ("4m", view) in draw_calls and draw_calls.get(("million", view))]
    if scaling:
        print(f"\nOur draw calls, 4 M plants against 1 M: {', '.join(scaling)}.")
    print("\n| field | plants | render buffers ours | native | ours per plant | native per plant |")
    print("|---|---|---|---|---|---|")
    for field, (plants, ours_bytes, native_bytes) in memory.items():
        print(f"| {field} | {plants:,} | {ours_bytes / 1048576:.1f} MB | {native_bytes / 1048576:.1f} MB | "
              f"{ours_bytes / max(plants, 1):.1f} B | {native_bytes / max(plants, 1):.1f} B |")

    print("\nWithout a cut-off (--draw-distance 0): far tiles merged with distance (tile_merge_distance 200 m, the")
    print("default) and never merged (0). Render buffers: what the field added, per plant.\n")
    print("| view | merged: draw calls 1 M / 4 M | ratio | not merged: 1 M / 4 M | ratio | render buffers per plant, merged / not |")
    print("|---|---|---|---|---|---|")
    for view in ("outside40", "above45"):
        calls = {}
        per_plant = {}
        for merge in (200, 0):
            for field in ("million", "4m"):
                s = load(folder, f"far_{field}_{view}_merge{merge}")
                if s and "draw_calls" in s:
                    calls[(merge, field)] = s["draw_calls"]["median"]
                    mem = s.get("buffer_memory_bytes", {})
                    if field == "million" and {"before", "field"} <= mem.keys():
                        per_plant[merge] = (mem["field"] - mem["before"]) / max(s["plants"], 1)
        if len(calls) < 4:
            print(f"| {view} | run failed | | | | |")
            continue
        print(f"| {view} | {calls[(200, 'million')]:.0f} / {calls[(200, '4m')]:.0f} | {calls[(200, '4m')] / calls[(200, 'million')]:.2f} | "
              f"{calls[(0, 'million')]:.0f} / {calls[(0, '4m')]:.0f} | {calls[(0, '4m')] / calls[(0, 'million')]:.2f} | "
              f"{per_plant.get(200, float('nan')):.1f} B / {per_plant.get(0, float('nan')):.1f} B |")


if __name__ == "__main__":
    main(sys.argv[1])
