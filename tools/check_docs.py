#!/usr/bin/env python3
"""Checks the docs: each failure on a line with its file and line. Ends with "docs: N passed, N failed".

    tools/check_docs.py [--godot GODOT] [--gdparse GDPARSE] [--only links|snippets|architecture|api|face|history]

- links: every relative link and image in README.md, CONTRIBUTING.md, CHANGELOG.md, ARCHITECTURE.md
  and docs/ resolves, to a file and, for a #fragment, to a heading or anchor in it;
- snippets: every ```gdscript block in them parses (gdtoolkit's gdparse; a block of statements is
  parsed as a function's body);
- architecture: ARCHITECTURE.md names every script and shader of the addon and every source file of
  the extension, and no such file that does not exist;
- api: docs/api/ is what tools/make_api_docs.py makes from the in-editor docs now;
- face: addons/sunflower_field/native/native_field.gd is what tools/make_native_face.py makes from the
  native classes' docs now;
- history: no development history (the word session or turn and a number) outside CHANGELOG.md and
  commit messages.
"""
import argparse
import pathlib
import re
import subprocess
import sys
import tempfile

REPO = pathlib.Path(__file__).resolve().parent.parent
ADDON = REPO / "addons" / "sunflower_field"
SOURCES = REPO / "gdextension" / "src"
failures = []
passed = 0


def fail(where, message):
    failures.append(f"{where}: {message}")


def ok():
    global passed
    passed += 1


def documents():
    docs = [REPO / n for n in ("README.md", "CONTRIBUTING.md", "CHANGELOG.md", "ARCHITECTURE.md")]
    return [d for d in docs if d.exists()] + sorted((REPO / "docs").rglob("*.md"))


def anchors(path):
    """GitHub's heading anchors of a Markdown file, and its explicit <a id> anchors."""
    found, in_code = set(), False
    for line in path.read_text(encoding="utf-8").splitlines():
        if line.startswith("```"):
            in_code = not in_code
        if in_code:
            continue
        heading = re.match(r"#+\s+(.*)", line)
        if heading:
            text = re.sub(r"[`*]|\[([^\]]*)\]\([^)]*\)", lambda m: m.group(1) or "", heading.group(1)).strip().lower()
            found.add(re.sub(r"[^\w\- ]", "", text).replace(" ", "-"))
        found.update(re.findall(r'<a id="([^"]+)"', line))
    return found


def check_links():
    for doc in documents():
        in_code = False
        for number, line in enumerate(doc.read_text(encoding="utf-8").splitlines(), 1):
            if line.startswith("```"):
                in_code = not in_code
            if in_code:
                continue
            line = re.sub(r"`[^`]*`", "", line)
            targets = re.findall(r"\]\(([^)\s]+)\)", line) + re.findall(r'<img[^>]*src="([^"]+)"', line)
            for target in targets:
                if re.match(r"[a-z]+:", target):
                    continue  # a web address: not checked here (no network)
                path, _, fragment = target.partition("#")
                resolved = (doc.parent / path).resolve() if path else doc
                where = f"{doc.relative_to(REPO)}:{number}"
                if not resolved.exists():
                    fail(where, f"'{target}' does not exist")
                elif fragment and resolved.suffix == ".md" and fragment not in anchors(resolved):
                    fail(where, f"'{target}': {resolved.name} has no heading or anchor '{fragment}'")
                else:
                    ok()


def check_snippets(gdparse):
    for doc in documents():
        text = doc.read_text(encoding="utf-8").splitlines()
        block, start = None, 0
        for number, line in enumerate(text, 1):
            if block is None and line.strip() == "```gdscript":
                block, start = [], number
            elif block is not None and line.strip() == "```":
                snippet = "\n".join(block) + "\n"
                where = f"{doc.relative_to(REPO)}:{start}"
                error = parse(gdparse, snippet)
                if error and parse(gdparse, "func _snippet() -> void:\n" + "".join(
                        "\t" + l + "\n" for l in block)) is not None:
                    fail(where, f"the GDScript snippet does not parse: {error}")
                else:
                    ok()
                block = None
            elif block is not None:
                block.append(line)


def parse(gdparse, source):
    with tempfile.NamedTemporaryFile("w", suffix=".gd", delete=False) as f:
        f.write(source)
    try:
        result = subprocess.run([gdparse, f.name], capture_output=True, text=True)
    finally:
        pathlib.Path(f.name).unlink()
    return None if result.returncode == 0 else (result.stderr or result.stdout).strip().splitlines()[-1]


def check_architecture():
    architecture = REPO / "ARCHITECTURE.md"
    text = architecture.read_text(encoding="utf-8")
    named = set(re.findall(r"`([\w./]+\.(?:gd|gdshader|gdshaderinc|h|cpp))`", text))
    files = {p.relative_to(ADDON).as_posix() for p in ADDON.rglob("*.gd")}
    files |= {p.relative_to(ADDON).as_posix() for p in (ADDON / "shaders").iterdir()
              if p.suffix in (".gdshader", ".gdshaderinc")}
    sources = {p.relative_to(SOURCES).as_posix() for p in SOURCES.rglob("*") if p.suffix in (".h", ".cpp")}
    for name in sorted(files | sources):
        if name in named:
            ok()
        else:
            fail("ARCHITECTURE.md", f"'{name}' is not in the table of every file")
    for name in sorted(named - files - sources):
        if not (REPO / name).exists():
            fail("ARCHITECTURE.md", f"names '{name}', which does not exist")


def check_api(godot):
    command = [sys.executable, str(REPO / "tools" / "make_api_docs.py"), "--check"] + (["--godot", godot] if godot else [])
    result = subprocess.run(command, capture_output=True, text=True)
    if result.returncode == 0:
        ok()
    else:
        fail("docs/api", (result.stdout + result.stderr).strip())


def check_face():
    result = subprocess.run([sys.executable, str(REPO / "tools" / "make_native_face.py"), "--check"],
                            capture_output=True, text=True)
    if result.returncode == 0:
        ok()
    else:
        fail("addons/sunflower_field/native/native_field.gd", (result.stdout + result.stderr).strip())


def check_history():
    listed = subprocess.run(["git", "ls-files"], cwd=REPO, capture_output=True, text=True).stdout.split()
    pattern = re.compile(r"\b(session|turn) [0-9]+", re.I)
    found = 0
    for name in listed:
        path = REPO / name
        if name == "CHANGELOG.md" or not path.is_file() or path.suffix in (".png", ".res", ".svg", ".import", ".uid"):
            continue
        try:
            lines = path.read_text(encoding="utf-8").splitlines()
        except (UnicodeDecodeError, OSError):
            continue
        for number, line in enumerate(lines, 1):
            if pattern.search(line):
                found += 1
                fail(f"{name}:{number}", f"development history belongs in CHANGELOG.md: {line.strip()[:100]}")
    if not found:
        ok()


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--godot", default="")
    parser.add_argument("--gdparse", default=str(REPO / ".cache" / "venv" / "bin" / "gdparse"))
    parser.add_argument("--only", choices=["links", "snippets", "architecture", "api", "face", "history"])
    args = parser.parse_args()
    checks = {
        "links": check_links,
        "snippets": lambda: check_snippets(args.gdparse),
        "architecture": check_architecture,
        "api": lambda: check_api(args.godot),
        "face": check_face,
        "history": check_history,
    }
    for name, check in checks.items():
        if args.only in (None, name):
            check()
    for failure in failures:
        print(failure)
    print(f"docs: {passed} passed, {len(failures)} failed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
