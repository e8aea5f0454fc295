#!/usr/bin/env python3
"""Writes the method hashes the extension needs, read from the engine's extension_api.json."""
import json
import sys

ENGINE_METHODS = {
    "RS_MULTIMESH_ALLOCATE_DATA": ("RenderingServer", "multimesh_allocate_data"),
    "RS_MULTIMESH_SET_BUFFER": ("RenderingServer", "multimesh_set_buffer"),
    "RS_MULTIMESH_SET_VISIBLE_INSTANCES": ("RenderingServer", "multimesh_set_visible_instances"),
    "RS_MULTIMESH_SET_CUSTOM_AABB": ("RenderingServer", "multimesh_set_custom_aabb"),
}
BUILTIN_METHODS = {
    f"{prefix}_{method.upper()}": (cls, method)
    for prefix, cls in (
        ("PACKED_BYTE_ARRAY", "PackedByteArray"),
        ("PACKED_INT32_ARRAY", "PackedInt32Array"),
        ("PACKED_INT64_ARRAY", "PackedInt64Array"),
        ("PACKED_FLOAT32_ARRAY", "PackedFloat32Array"),
    )
    for method in ("size", "resize")
}


def find(entries, cls, method):
    for entry in entries:
        if entry["name"] == cls:
            for m in entry.get("methods", []):
                if m["name"] == method:
                    return m["hash"]
    sys.exit(f"gen_api_hashes: {cls}.{method} is not in the engine's API")


def main(api_path, out_path):
    with open(api_path, encoding="utf-8") as f:
        api = json.load(f)
    lines = [
        "#pragma once",
        f"// Generated from {api['header']['version_full_name']}'s API dump. Do not edit.",
        "#include <cstdint>",
        "namespace gdx::hashes {",
    ]
    for name, (cls, method) in ENGINE_METHODS.items():
        lines.append(f"constexpr int64_t {name} = {find(api['classes'], cls, method)};")
    for name, (cls, method) in BUILTIN_METHODS.items():
        lines.append(f"constexpr int64_t {name} = {find(api['builtin_classes'], cls, method)};")
    lines.append("} // namespace gdx::hashes")
    with open(out_path, "w", encoding="utf-8") as f:
        f.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
