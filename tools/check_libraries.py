#!/usr/bin/env python3
"""Checks that each built library can be installed where its platform's Godot users are.

    tools/check_libraries.py addons/sunflower_field/bin/*.{so,dll,dylib}

For each file (read with LLVM's llvm-readobj / llvm-nm / llvm-objdump, which read every format):
- the format and architecture its name promises;
- its dependencies: Linux only libc/libm/libdl/libpthread/ld-linux (no libstdc++, no libgcc_s) and
  no glibc symbol version above 2.28; Windows only system DLLs (KERNEL32, the UCRT's api-ms-win-crt-*);
  macOS only libSystem (and the system's libc++);
- its exports: the GDExtension entry symbol and nothing else;
- macOS arm64: an ad-hoc code signature (arm64 macOS refuses unsigned code).
Prints one line per library ("ok" or what is wrong) and the sizes; exits 1 on any violation.
"""
import os
import re
import shutil
import subprocess
import sys

ENTRY = "sunflower_library_init"
MAX_GLIBC = (2, 28)
NAME = re.compile(r"libsunflower\.(linux|windows|macos)\.(template_debug|template_release)\.(x86_64|arm64)\.(so|dll|dylib)$")
EXPECTED = {  # (platform, arch): (llvm-readobj's Format, Arch)
    ("linux", "x86_64"): ("elf64-x86-64", "x86_64"),
    ("linux", "arm64"): ("elf64-littleaarch64", "aarch64"),
    ("windows", "x86_64"): ("COFF-x86-64", "x86_64"),
    ("windows", "arm64"): ("COFF-ARM64", "aarch64"),
    ("macos", "x86_64"): ("Mach-O 64-bit x86-64", "x86_64"),
    ("macos", "arm64"): ("Mach-O arm64", "aarch64"),
}
LINUX_LIBS = {"libc.so.6", "libm.so.6", "libdl.so.2", "libpthread.so.0", "ld-linux-x86-64.so.2",
              "ld-linux-aarch64.so.1"}
WINDOWS_SYSTEM_DLLS = re.compile(r"^(kernel32|ntdll|advapi32|bcrypt|ws2_32|api-ms-win-crt-[a-z0-9-]+|ucrtbase)\.dll$",
                                 re.IGNORECASE)
MACOS_LIBS = {"/usr/lib/libSystem.B.dylib", "/usr/lib/libc++.1.dylib"}
# The C++ runtime's replaceable operator new / delete, which libc++ declares visible: Zig's Mach-O
# linker takes no export list to hide them. They are not ours, and with macOS's two-level namespace
# they replace nothing in the engine.
# Zig's linker also exports the two symbols it makes for every dylib (the image header and the C++
# runtime's handle); likewise not ours and harmless.
NOT_OURS = re.compile(r"^(_Z(nw|na|dl|da)|__dso_handle$|_mh_dylib_header$)")


def tool(name):
    for candidate in (name, name + "-14", name + "-15", name + "-16"):
        if shutil.which(candidate):
            return candidate
    sys.exit(f"check_libraries: {name} is not installed (Debian: llvm)")


def run(*args):
    return subprocess.run(args, check=True, capture_output=True, text=True).stdout


def field(text, key):
    match = re.search(rf"^\s*{key}: (.+)$", text, re.M)
    return match.group(1).strip() if match else ""


def elf_problems(path, text):
    problems = []
    needed = re.search(r"NeededLibraries \[\n(.*?)\n\s*\]", text, re.S)
    libs = set(needed.group(1).split()) if needed else set()
    problems += [f"depends on {lib}" for lib in sorted(libs - LINUX_LIBS)]
    versions = {tuple(int(n) for n in v.split(".")) for v in re.findall(r"@GLIBC_([0-9.]+)", text)}
    too_new = sorted(v for v in versions if v > MAX_GLIBC)
    if too_new:
        problems.append("needs glibc " + ", ".join(".".join(map(str, v)) for v in too_new))
    exports = set()
    for block in re.findall(r"Symbol \{(.*?)\}", text, re.S):
        if "Section: Undefined" in block or not re.search(r"Binding: (Global|Weak)", block):
            continue
        exports.add(field(block, "Name").split(" ")[0].split("@")[0])
    exports.discard("")
    return problems, exports, f"glibc ≤ {'.'.join(map(str, max(versions)))}" if versions else ""


def coff_problems(path, text):
    imports = re.findall(r"Import \{\s*\n\s*Name: (\S+)", text)
    problems = [f"imports {dll}" for dll in imports if not WINDOWS_SYSTEM_DLLS.match(dll)]
    exports = set(re.findall(r"Export \{[^}]*?Name: (\S+)", text, re.S))
    return problems, exports, "imports " + ", ".join(sorted({d.lower() for d in imports}))


def macho_problems(path, text, arch):
    needed = re.search(r"NeededLibraries \[\n(.*?)\n\s*\]", text, re.S)
    # The list holds the library's own install name (LC_ID_DYLIB) too.
    own = run(tool("llvm-objdump"), "--macho", "--dylib-id", "--no-leading-headers", path).split()
    libs = set(needed.group(1).split() if needed else []) - set(own)
    problems = [f"depends on {lib}" for lib in sorted(libs - MACOS_LIBS)]
    trie = run(tool("llvm-objdump"), "--macho", "--exports-trie", path)
    names = re.findall(r"^0x[0-9A-Fa-f]+\s+_(\S+)", trie, re.M)
    exports = {name for name in names if not NOT_OURS.match(name)}
    signed = "LC_CODE_SIGNATURE" in run(tool("llvm-objdump"), "--macho", "--private-headers", path)
    if arch == "arm64" and not signed:
        problems.append("has no code signature (arm64 macOS refuses to load it)")
    return problems, exports, ("ad-hoc signed, " if signed else "") + "links " + ", ".join(sorted(libs))


def check(path):
    match = NAME.search(os.path.basename(path))
    if not match:
        return [f"the name does not follow libsunflower.PLATFORM.TARGET.ARCH.EXT"], ""
    platform, _, arch, _ = match.groups()
    flags = {"linux": ["--needed-libs", "--dyn-syms"], "windows": ["--coff-imports", "--coff-exports"],
             "macos": ["--needed-libs"]}[platform]
    text = run(tool("llvm-readobj"), "--file-headers", *flags, path)
    problems = []
    want_format, want_arch = EXPECTED[(platform, arch)]
    if field(text, "Format") != want_format or field(text, "Arch") != want_arch:
        problems.append(f"is {field(text, 'Format')} / {field(text, 'Arch')}, not {want_format} / {want_arch}")
    if platform == "linux":
        more, exports, note = elf_problems(path, text)
    elif platform == "windows":
        more, exports, note = coff_problems(path, text)
    else:
        more, exports, note = macho_problems(path, text, arch)
    problems += more
    if exports != {ENTRY}:
        extra = sorted(exports - {ENTRY})
        problems.append(f"exports {len(extra)} other symbols ({', '.join(extra[:5])}…)" if extra
                        else f"does not export {ENTRY}")
    return problems, note


def main(paths):
    if not paths:
        sys.exit("usage: check_libraries.py LIBRARY...")
    failed = 0
    for path in sorted(paths):
        problems, note = check(path)
        size = os.path.getsize(path) / 1e6
        if problems:
            failed += 1
            print(f"FAIL {os.path.basename(path)} ({size:.2f} MB): " + "; ".join(problems))
        else:
            print(f"ok   {os.path.basename(path)} ({size:.2f} MB): {note}")
    print(f"libraries: {len(paths) - failed} passed, {failed} failed")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
