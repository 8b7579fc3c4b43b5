#!/usr/bin/env python3
"""Counts casteljau's public surface from rustdoc's JSON output.

    RUSTC_BOOTSTRAP=1 cargo rustdoc --lib -- -Z unstable-options --output-format json
    python3 scripts/public_surface.py target/doc/casteljau.json [--list]

Items: functions, types (struct, enum, union, type alias), traits, constants and statics
reachable from the crate root through public modules and re-exports (an item re-exported in
several places counts once; `#[doc(hidden)]` modules are left out). Methods: public inherent
associated functions of those types (trait impls are not counted: their names are the trait's).
"""
import json
import sys

path = sys.argv[1] if len(sys.argv) > 1 else "target/doc/casteljau.json"
doc = json.load(open(path))
index = doc["index"]
KINDS = {"function": "function", "struct": "type", "enum": "type", "union": "type",
         "type_alias": "type", "trait": "trait", "constant": "constant", "static": "constant",
         "macro": "macro"}


def hidden(item):
    return any("doc(hidden)" in str(a) for a in item.get("attrs", []))


items = {}  # id -> (kind, path)
seen_modules = set()


def walk(mod_id, prefix):
    if mod_id in seen_modules:
        return
    seen_modules.add(mod_id)
    for child in index[str(mod_id)]["inner"]["module"]["items"]:
        visit(child, prefix)


def visit(item_id, prefix, name=None):
    item = index.get(str(item_id))
    if item is None or hidden(item):
        return
    if item["visibility"] != "public" and item["visibility"] != "default":
        return
    if item["visibility"] != "public":
        return
    kind = next(iter(item["inner"]))
    name = name or item["name"]
    if kind == "module":
        walk(item_id, prefix + [name])
    elif kind == "use":
        use = item["inner"]["use"]
        if use["id"] is None:
            return
        target = index.get(str(use["id"]))
        if target is None:
            return
        if use["is_glob"]:
            if next(iter(target["inner"])) == "module":
                walk(use["id"], prefix)
            return
        tk = next(iter(target["inner"]))
        if tk == "module":
            walk(use["id"], prefix + [use["name"]])
        elif tk in KINDS:
            items.setdefault(use["id"], (KINDS[tk], "::".join(prefix + [use["name"]])))
    elif kind in KINDS:
        items.setdefault(item_id, (KINDS[kind], "::".join(prefix + [name])))


walk(doc["root"], ["casteljau"])
methods = []
for item_id, (kind, p) in items.items():
    inner = index[str(item_id)]["inner"]
    k = next(iter(inner))
    if k not in ("struct", "enum", "union"):
        continue
    for impl_id in inner[k].get("impls", []):
        impl = index[str(impl_id)]["inner"]["impl"]
        if impl["trait"] is not None or impl.get("is_synthetic") or impl.get("blanket_impl"):
            continue
        for m in impl["items"]:
            mi = index[str(m)]
            if mi["visibility"] == "public" and "function" in mi["inner"] and not hidden(mi):
                methods.append(p + "::" + mi["name"])
by_kind = {}
for kind, _ in items.values():
    by_kind[kind] = by_kind.get(kind, 0) + 1
print(f"public items: {len(items)} ({', '.join(f'{v} {k}s' for k, v in sorted(by_kind.items()))})")
print(f"public methods: {len(methods)}")
if "--list" in sys.argv:
    for kind, p in sorted(items.values(), key=lambda x: x[1]):
        print(f"  {kind:9s} {p}")
    for m in sorted(methods):
        print(f"  method    {m}")
