#!/usr/bin/env python3
"""The layout test: docs/design.md's "Map" lists every source folder in
pipeline order, and every #include runs one way down that order.

Fails when a folder of flexmb/ (or of apps/flexmb/) is missing from the map
or listed but absent, and when a file includes a header of a folder that
comes later in the map (an arrow against the pipeline). Usage:
check_layout.py SOURCE_DIR"""
import os
import re
import sys


def map_folders(design_md):
    """Folders in the order of the Map table: rows whose first cell is `path/`."""
    text = open(design_md, encoding="utf-8").read()
    m = re.search(r"^## Map\n(.*?)(?=^## )", text, re.S | re.M)
    if not m:
        sys.exit(f"{design_md}: no '## Map' section")
    folders = re.findall(r"^\| `([a-z_/]+)/` \|", m.group(1), re.M)
    if not folders:
        sys.exit(f"{design_md}: the Map section has no table rows of the form | `folder/` |")
    return folders


def source_folders(root):
    """Top-level folders of flexmb/ and the folders of apps/flexmb/."""
    found = {"flexmb/" + d for d in os.listdir(os.path.join(root, "flexmb"))
             if os.path.isdir(os.path.join(root, "flexmb", d)) and not d.startswith(".")}
    apps = os.path.join(root, "apps", "flexmb")
    found.add("apps/flexmb")
    for d in os.listdir(apps):
        if os.path.isdir(os.path.join(apps, d)):
            found.add("apps/flexmb/" + d)
    return found


def folder_of(path, folders):
    """The longest map folder that contains `path`."""
    best = None
    for f in folders:
        if path.startswith(f + "/") and (best is None or len(f) > len(best)):
            best = f
    return best


def main():
    root = sys.argv[1] if len(sys.argv) > 1 else "."
    order = map_folders(os.path.join(root, "docs", "design.md"))
    errors = []
    have = source_folders(root)
    for f in sorted(have - set(order)):
        errors.append(f"folder {f}/ is not in docs/design.md's Map (add a row in pipeline order)")
    for f in order:
        if f not in have:
            errors.append(f"docs/design.md's Map lists {f}/, which does not exist")
    rank = {f: i for i, f in enumerate(order)}
    include = re.compile(r'^\s*#\s*include\s+"((?:flexmb|apps/flexmb)/[^"]+)"', re.M)
    for top in ("flexmb", "apps/flexmb"):
        for dirpath, _, files in os.walk(os.path.join(root, top)):
            for name in files:
                if not name.endswith((".h", ".cc")):
                    continue
                path = os.path.relpath(os.path.join(dirpath, name), root)
                me = folder_of(path, order)
                if me is None:
                    continue
                text = open(os.path.join(root, path), encoding="utf-8").read()
                for inc in include.findall(text):
                    other = folder_of(inc, order)
                    if other is None:
                        errors.append(f"{path}: includes {inc}, whose folder is not in the Map")
                    elif rank[other] > rank[me]:
                        errors.append(f"{path}: includes {inc}: {other}/ comes after {me}/ in the pipeline")
    for e in errors:
        print("layout:", e)
    print(f"layout: {len(order)} folders in the Map, {len(errors)} problems")
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main())
