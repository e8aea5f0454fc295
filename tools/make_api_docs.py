#!/usr/bin/env python3
"""Writes the API reference (docs/api/*.md) from the in-editor docs.

    tools/make_api_docs.py [--check] [--godot GODOT]

The engine's doctool dumps the `##` docs of the addon's named classes (`--doctool --gdscript-docs`,
in the imported test project); the native class's docs are gdextension/doc_classes/*.xml. Each class
becomes one Markdown page, and docs/api/README.md lists them. With --check nothing is written: the
exit status is 1, naming the pages, when the committed reference differs from what the docs make.
"""
import argparse
import filecmp
import pathlib
import re
import shutil
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET

REPO = pathlib.Path(__file__).resolve().parent.parent
API = REPO / "docs" / "api"
# The classes a user meets, in the order the index lists them.
CLASSES = ["SunflowerField", "SunflowerFieldPlay", "SunflowerPlant", "SunflowerWind", "SunflowerFieldMap", "SunflowerPlacementRules",
           "SunflowerPlacementLayer", "SunflowerSimulation", "SunflowerDrawing", "SunflowerChanges", "SunflowerParameters",
           "SunflowerPlacement", "SunflowerMap"]
ENGINE_DOCS = "https://docs.godotengine.org/en/stable/classes/class_{}.html"


def bbcode_to_markdown(text, own):
    """The in-editor docs' BBCode as Markdown: links to our pages or the engine's, code spans."""

    def link(kind, target):
        cls, _, member = target.rpartition(".")
        cls = cls or own
        label = target if cls != own else member
        if kind == "method":
            label += "()"
        anchor = member.lower()
        if cls in CLASSES:
            page = "" if cls == own else f"{cls}.md"
            return f"[`{label}`]({page}#{anchor})"
        return f"`{label}`"

    text = text.replace("[br]", "\n\n")
    text = re.sub(r"\[codeblock[^\]]*\](.*?)\[/codeblock\]",
                  lambda m: "\n```gdscript\n" + m.group(1).strip("\n") + "\n```\n", text, flags=re.S)
    text = re.sub(r"\[code\](.*?)\[/code\]", r"`\1`", text, flags=re.S)
    text = re.sub(r"\[(member|method|signal|constant|enum|param) ([^\]]+)\]",
                  lambda m: f"`{m.group(2)}`" if m.group(1) in ("param", "enum", "constant", "signal")
                  else link(m.group(1), m.group(2)), text)
    text = re.sub(r"\[b\](.*?)\[/b\]", r"**\1**", text, flags=re.S)
    text = re.sub(r"\[i\](.*?)\[/i\]", r"*\1*", text, flags=re.S)
    text = re.sub(r"\[url=([^\]]+)\](.*?)\[/url\]", r"[\2](\1)", text, flags=re.S)

    def class_ref(m):
        name = m.group(1)
        if name in CLASSES:
            return f"[{name}]({name}.md)" if name != own else f"`{name}`"
        if name[0].isupper() and name.isidentifier():
            return f"[{name}]({ENGINE_DOCS.format(name.lower())})"
        return m.group(0)

    text = re.sub(r"\[([A-Za-z0-9_]+)\]", class_ref, text)
    lines = [line.strip() for line in text.strip().splitlines()]
    out, in_code = [], False
    for line in lines:
        if line.startswith("```"):
            in_code = not in_code
        out.append(line)
    return "\n".join(out).strip()


def one_line(text, own):
    return bbcode_to_markdown(text, own).replace("\n\n", "<br>").replace("\n", " ").replace("|", "\\|")


def type_of(node):
    t = node.get("type", "")
    if node.get("enum"):
        t = node.get("enum")
    # A script's own type (a preloaded constant, no class_name) is named after its file:
    # "addons/sunflower_field/native/native_field.gd" reads NativeField.
    script = re.fullmatch(r'"?(?:res://)?[\w/]*/(\w+)\.gd"?', t)
    if script:
        t = "".join(word.capitalize() for word in script.group(1).split("_"))
    return t or "Variant"


def with_script_bases(xml_path, sources):
    """A class's docs with those of the unnamed scripts it extends merged in (SunflowerField's
    run-time half is runtime/field_node_base.gd): the user meets them as one class. The engine names
    such a base by its quoted path, and its docs file after the path."""
    root = ET.parse(xml_path).getroot()
    while True:
        base = re.fullmatch(r'"(.+\.gd)"', root.get("inherits", ""))
        if not base:
            return root
        base_path = sources.get(base.group(1).replace("/", "--"))
        if base_path is None:
            sys.exit(f"make_api_docs: no docs for {root.get('name')}'s base script {base.group(1)}")
        base_root = ET.parse(base_path).getroot()
        for section in ("members", "methods", "signals", "constants"):
            own, inherited = root.find(section), base_root.find(section)
            if inherited is None:
                continue
            if own is None:
                own = ET.SubElement(root, section)
            for item in inherited:
                own.append(item)
        root.set("inherits", base_root.get("inherits", ""))


def page(root):
    name = root.get("name")
    out = [f"# {name}", ""]
    inherits = root.get("inherits")
    if inherits:
        out += [f"*Inherits* {bbcode_to_markdown('[' + inherits + ']', name)}", ""]
    brief = (root.findtext("brief_description") or "").strip()
    if brief:
        out += [bbcode_to_markdown(brief, name), ""]
    description = (root.findtext("description") or "").strip()
    if description:
        out += [bbcode_to_markdown(description, name), ""]
    # A script's own state (a leading underscore) is not part of the API either.
    members = [m for m in root.find("members") or [] if not m.get("name").startswith("_")]
    if members:
        out += ["## Properties", "", "| property | type | default | |", "|---|---|---|---|"]
        for m in members:
            default = m.get("default")
            default = f"`{default}`" if default not in (None, "") else ""
            out.append(f"| <a id=\"{m.get('name')}\"></a>`{m.get('name')}` | `{type_of(m)}` | "
                       f"{default} | {one_line(m.text or '', name)} |")
        out.append("")
    # The API: a script's own helpers and the engine's callbacks (a leading underscore) are not in it.
    methods = [m for m in root.find("methods") or [] if not m.get("name").startswith("_")]
    if methods:
        out += ["## Methods", ""]
        for m in methods:
            params = []
            for p in sorted(m.findall("param"), key=lambda p: int(p.get("index"))):
                text = f"{p.get('name')}: {type_of(p)}"
                if p.get("default") is not None:
                    text += f" = {p.get('default')}"
                params.append(text)
            ret = m.find("return")
            returns = type_of(ret) if ret is not None else "void"
            qualifiers = f" {m.get('qualifiers')}" if m.get("qualifiers") else ""
            out += [f"### {m.get('name')}", "", f"`{m.get('name')}({', '.join(params)}) -> {returns}`{qualifiers}", ""]
            text = bbcode_to_markdown(m.findtext("description") or "", name)
            out += [text, ""] if text else []
    signals = root.find("signals")
    if signals is not None and len(signals):
        out += ["## Signals", ""]
        for s in signals:
            params = ", ".join(f"{p.get('name')}: {type_of(p)}"
                               for p in sorted(s.findall("param"), key=lambda p: int(p.get("index"))))
            out += [f"### {s.get('name')}", "", f"`{s.get('name')}({params})`", ""]
            text = bbcode_to_markdown(s.findtext("description") or "", name)
            out += [text, ""] if text else []
    # A preloaded script (value <Object>) is the class's own wiring, not part of its face.
    constants = [c for c in root.find("constants") or [] if c.get("value") != "<Object>"]
    if constants:
        out += ["## Constants and enums", "", "| name | value | |", "|---|---|---|"]
        for c in constants:
            qualified = f"{c.get('enum')}.{c.get('name')}" if c.get("enum") else c.get("name")
            out.append(f"| `{qualified}` | `{c.get('value')}` | {one_line(c.text or '', name)} |")
        out.append("")
    return name, "\n".join(out).rstrip() + "\n", brief


def dump_gdscript_docs(godot, folder):
    """The engine's doctool over the addon's scripts, in the imported test project."""
    project = REPO / "tests" / "godot"
    result = subprocess.run([godot, "--headless", "--path", str(project), "--doctool", str(folder),
                             "--gdscript-docs", "res://addons/sunflower_field"],
                            capture_output=True, text=True, timeout=300)
    if result.returncode != 0:
        sys.exit(f"make_api_docs: the doctool failed ({result.returncode}):\n{result.stdout}{result.stderr}")


def write(target, godot):
    with tempfile.TemporaryDirectory() as dumped:
        dumped = pathlib.Path(dumped)
        dump_gdscript_docs(godot, dumped)
        sources = {p.stem: p for p in dumped.glob("*.xml")}
        sources.update({p.stem: p for p in (REPO / "gdextension" / "doc_classes").glob("*.xml")})
        target.mkdir(parents=True, exist_ok=True)
        index = ["# API reference", "",
                 "Generated by `tools/make_api_docs.py` from the in-editor docs (the `##` comments of the "
                 "addon's scripts and `gdextension/doc_classes/`); the test command fails when it is stale. "
                 "The same text is the editor's help (F1).", "", "| class | |", "|---|---|"]
        for cls in CLASSES:
            if cls not in sources:
                sys.exit(f"make_api_docs: no docs for {cls} (looked in the doctool's output and doc_classes/)")
            name, text, brief = page(with_script_bases(sources[cls], sources))
            (target / f"{name}.md").write_text(text, encoding="utf-8")
            index.append(f"| [{name}]({name}.md) | {one_line(brief, name).replace('](#', f']({name}.md#')} |")
        (target / "README.md").write_text("\n".join(index) + "\n", encoding="utf-8")


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--check", action="store_true", help="compare with docs/api/ instead of writing it")
    parser.add_argument("--godot", default="", help="the engine (default: tools/find_godot.sh)")
    args = parser.parse_args()
    godot = args.godot or subprocess.check_output(["bash", str(REPO / "tools" / "find_godot.sh")], text=True).strip()
    if not args.check:
        if API.exists():
            shutil.rmtree(API)
        write(API, godot)
        print(f"make_api_docs: wrote {API.relative_to(REPO)}/")
        return 0
    with tempfile.TemporaryDirectory() as fresh:
        fresh = pathlib.Path(fresh)
        write(fresh, godot)
        made = {p.name for p in fresh.glob("*.md")}
        committed = {p.name for p in API.glob("*.md")} if API.exists() else set()
        stale = sorted(n for n in made & committed if not filecmp.cmp(fresh / n, API / n, shallow=False))
        stale += sorted(f"{n} (missing)" for n in made - committed)
        stale += sorted(f"{n} (no such class)" for n in committed - made)
        if stale:
            print("make_api_docs: docs/api/ is stale: " + ", ".join(stale) + "; run tools/make_api_docs.py")
            return 1
        print(f"make_api_docs: docs/api/ is current ({len(made)} pages)")
        return 0


if __name__ == "__main__":
    sys.exit(main())
