#!/usr/bin/env python3
"""Lists import cycles among a crate's modules (files), from its `crate::`, `super::` and `self::`
paths (grouped ones, `super::{a, b}`, included).

Usage: tools/module_cycles.py CRATE_SRC_DIR. Exits 1 and prints each cycle when there is one.
A module is a file; `crate::a::b::c` names the deepest existing file of the path.
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

def resolve(path):
    for k in range(len(path), -1, -1):
        if tuple(path[:k]) in mods:
            return tuple(path[:k])
    return None

edges = {m: set() for m in mods}
for m, f in mods.items():
    text = open(f).read()
    text = re.sub(r"//.*", "", text)
    # Grouped paths, `super::{a, b::c}` and `crate::x::{y, z}`: one path per member (nested
    # groups once more).
    group = re.compile(r"\b((?:crate|super|self)(?:::\w+)*)::\{([^{}]*)\}")
    for _ in range(3):
        text = group.sub(
            lambda g: " ".join(
                g.group(1) + "::" + x.strip().split(" as ")[0]
                for x in g.group(2).split(",")
                if x.strip() and x.strip() != "self"
            )
            + " " + g.group(1),
            text,
        )
    for p in re.findall(r"\bcrate((?:::\w+)+)", text):
        t = resolve(p.strip(":").split("::"))
        if t is not None and t != m and t != ():
            edges[m].add(t)
    # `super` is the module's parent whether the module is a file (`a/b.rs`: a) or a folder
    # (`a/b/mod.rs`: a again); `self` the module itself. `super::super::` climbs further.
    for kw, p in re.findall(r"\b(super|self)((?:::\w+)+)", text):
        parts = p.strip(":").split("::")
        at = list(m[:-1]) if kw == "super" else list(m)
        while parts and parts[0] == "super":
            at, parts = at[:-1], parts[1:]
        t = resolve(at + parts)
        if t is not None and t != m and t != ():
            edges[m].add(t)

# A parent module re-exporting its children is not a cycle: drop parent -> child edges.
for m in edges:
    edges[m] = {t for t in edges[m] if t[: len(m)] != m}

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
