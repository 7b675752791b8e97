#!/usr/bin/env python3
"""Lists import cycles among a crate's modules (files), from its `crate::`, `super::`, `self::`
and `child::` paths (grouped ones, `super::{a, b}`, included).

Usage: tools/module_cycles.py CRATE_SRC_DIR. Exits 1 and prints each cycle when there is one.
A module is a file; `crate::a::b::c` names the deepest existing file of the path. A parent's
use of its child is an edge like any other (a `mod.rs` that calls its child while the child
takes the parent's own items is a circle); a re-export (`pub use child::X;`) is not a use,
and a path through it is followed to the file that defines X. `#[cfg(test)]` modules are left
out. CYCLES_WHY=1 prints every edge and the path that made it.
"""
import os, re, sys

root = sys.argv[1]
mods = {}
for dp, _, fs in os.walk(root):
    for f in fs:
        if f.endswith(".rs") and f != "main.rs":
            rel = os.path.relpath(os.path.join(dp, f), root)[:-3]
            parts = rel.split(os.sep)
            if parts[-1] in ("mod", "lib"):
                parts = parts[:-1]
            mods[tuple(parts)] = os.path.join(dp, f)

group = re.compile(r"(?<![\w:])(\w+(?:::\w+)*)::\{([^{}]*)\}")


def ungroup(text):
    """Grouped paths, `super::{a, b::c}`, `crate::x::{y, z}` and `child::{y, z}`: one path per
    member, `self` the prefix itself (nested groups once more)."""
    for _ in range(3):
        text = group.sub(
            lambda g: " ".join(
                g.group(1) + ("" if x.strip() == "self" else "::" + x.strip().split(" as ")[0])
                for x in g.group(2).split(",")
                if x.strip()
            ),
            text,
        )
    return text


def inline_spans(text):
    """The bodies of the inline modules of `text` (`mod tests { .. }`), as (start, end)."""
    spans = []
    for g in re.finditer(r"\bmod\s+\w+\s*\{", text):
        depth, i = 1, g.end()
        while i < len(text) and depth:
            depth += {"{": 1, "}": -1}.get(text[i], 0)
            i += 1
        spans.append((g.end(), i))
    return spans


def targets(m, text):
    """The module paths `text`, written in module `m`, names: `crate::` from the root; `super`
    is the module's parent whether the module is a file (`a/b.rs`: a) or a folder
    (`a/b/mod.rs`: a again), `self` the module itself, and `super::super::` climbs further;
    inside an inline module (`mod tests { .. }`, `mod render { .. }`) the first `super` of
    each level stays in the file. A bare `child::x` in a parent names its child module."""
    out = []
    for p in re.findall(r"\bcrate((?:::\w+)+)", text):
        out.append(p.strip(":").split("::"))
    spans = inline_spans(text)
    for g in re.finditer(r"\b(super|self)((?:::\w+)+)", text):
        kw, parts = g.group(1), g.group(2).strip(":").split("::")
        climbs = 1 if kw == "super" else 0
        while parts and parts[0] == "super":
            climbs, parts = climbs + 1, parts[1:]
        climbs -= sum(a <= g.start() < b for a, b in spans)
        at = list(m)
        for _ in range(max(climbs, 0)):
            at = at[:-1]
        out.append(at + parts)
    children = {c[-1] for c in mods if c[:-1] == m and len(c) == len(m) + 1}
    for first, rest in re.findall(r"(?<![\w:])(\w+)((?:::\w+)+)", text):
        if first in children:
            out.append(list(m) + [first] + rest.strip(":").split("::"))
    return out


# A re-export (`pub use child::Item;`, `pub use super::sibling::f;`) is not a use: the module
# only passes the name on. Its statement adds no edge; a path through it is followed to where
# the item lives (`super::Item` names the sibling that defines Item, not the parent).
reexport = re.compile(r"\bpub(?:\([^)]*\))?\s+use\s+([^;]*);")
passes = {}
for m, f in mods.items():
    text = ungroup(re.sub(r"//.*", "", open(f).read()))
    for stmt in reexport.findall(text):
        for path in targets(m, stmt) + [
            list(m) + x.split("::")
            for x in re.findall(r"(?<![\w:])(\w+(?:::\w+)+)", stmt)
            if x.split("::")[0] not in ("crate", "super", "self")
        ]:
            passes.setdefault(m, {})[path[-1]] = path


def resolve(path, seen=0):
    for k in range(len(path), -1, -1):
        at = tuple(path[:k])
        if at in mods:
            rest = path[k:]
            if rest and rest[0] in passes.get(at, {}) and seen < 8:
                return resolve(passes[at][rest[0]] + rest[1:], seen + 1)
            return at
    return None


def without_tests(text):
    """`text` without its `#[cfg(test)]` inline modules: a unit test may check a module against
    the ones that use it (the squeeze against the samplers' wedges); the library's modules are
    what must not go round in circles."""
    for a, b in reversed([
        (g.start(), b)
        for g in re.finditer(r"#\[cfg\(test\)\]\s*mod\s+\w+\s*\{", text)
        for a, b in inline_spans(text)
        if a == g.end()
    ]):
        text = text[:a] + text[b:]
    return text


edges = {m: set() for m in mods}
for m, f in mods.items():
    text = reexport.sub(" ", ungroup(without_tests(re.sub(r"//.*", "", open(f).read()))))
    for path in targets(m, text):
        t = resolve(path)
        if t is not None and t != m and t != ():
            edges[m].add(t)
            if os.environ.get("CYCLES_WHY"):
                print("::".join(m), "->", "::".join(t), "by", "::".join(path), file=sys.stderr)

cycles, state, stack = [], {}, []
def dfs(v):
    state[v] = 1
    stack.append(v)
    for w in sorted(edges[v]):
        if state.get(w) == 1:
            cycles.append(stack[stack.index(w):] + [w])
        elif w not in state:
            dfs(w)
    stack.pop()
    state[v] = 2
for v in sorted(edges):
    if v not in state:
        dfs(v)
for c in cycles:
    print(" -> ".join("::".join(x) or "crate" for x in c))
sys.exit(1 if cycles else 0)
