#!/usr/bin/env python3
"""Lists import cycles among a crate's modules (files), from its `crate::` and `super::` paths.

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
    for p in re.findall(r"\bcrate((?:::\w+)+)", text):
        t = resolve(p.strip(":").split("::"))
        if t is not None and t != m and t != ():
            edges[m].add(t)
    base = m if f.endswith("mod.rs") else m[:-1]
    for p in re.findall(r"\bsuper((?:::\w+)+)", text):
        t = resolve(list(base[:-1]) + p.strip(":").split("::"))
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
