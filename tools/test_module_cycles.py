#!/usr/bin/env python3
"""Tests tools/module_cycles.py: it must find a circle between sibling files (the shape
core/src/physics/ had: dimension.rs, rotation.rs and species.rs importing `super::model`, whose
model.rs called back into them), through plain, grouped and `self::` paths, and pass a tree
without one. Run by CI before the tool checks the crates."""
import os, subprocess, sys, tempfile

TOOL = os.path.join(os.path.dirname(os.path.abspath(__file__)), "module_cycles.py")


def run(files):
    with tempfile.TemporaryDirectory() as d:
        for name, text in files.items():
            p = os.path.join(d, name)
            os.makedirs(os.path.dirname(p), exist_ok=True)
            with open(p, "w") as f:
                f.write(text)
        r = subprocess.run([sys.executable, TOOL, d], capture_output=True, text=True)
        return r.returncode, r.stdout


def expect(name, files, code, found=None):
    rc, out = run(files)
    assert rc == code, f"{name}: exit {rc}, expected {code}; printed {out!r}"
    if found:
        assert found in out, f"{name}: {found!r} not in {out!r}"
    print(f"ok: {name}")


LIB = "pub mod physics;\n"
MOD = "mod dimension;\nmod model;\npub use model::Model;\n"
expect(
    "sibling circle through super::",
    {
        "lib.rs": LIB,
        "physics/mod.rs": MOD,
        "physics/model.rs": "pub fn f() { super::dimension::g() }\npub struct Model;\n",
        "physics/dimension.rs": "use super::model::Model;\npub fn g() {}\n",
    },
    1,
    "physics::dimension -> physics::model -> physics::dimension",
)
expect(
    "sibling circle through a grouped import",
    {
        "lib.rs": LIB,
        "physics/mod.rs": MOD,
        "physics/model.rs": "use super::{dimension::g, X};\npub struct Model;\n",
        "physics/dimension.rs": "use crate::physics::{model::Model};\npub fn g() {}\n",
    },
    1,
    "physics::dimension -> physics::model",
)
expect(
    "no circle: the axes import the parts, the model imports them all",
    {
        "lib.rs": LIB,
        "physics/mod.rs": MOD + "mod parts;\n",
        "physics/parts.rs": "pub struct Kernel;\n",
        "physics/model.rs": "use super::parts::Kernel;\nuse super::dimension::g;\npub struct Model;\n",
        "physics/dimension.rs": "use super::parts::Kernel;\npub fn g() {}\n",
    },
    0,
)
expect(
    "a parent re-exporting a child is no circle; super::super climbs",
    {
        "lib.rs": "pub mod a;\npub mod b;\n",
        "a/mod.rs": "pub mod inner;\npub use self::inner::X;\n",
        "a/inner.rs": "use super::super::b::Y;\npub struct X;\n",
        "b.rs": "pub struct Y;\n",
    },
    0,
)
expect(
    "super::super reaching back",
    {
        "lib.rs": "pub mod a;\npub mod b;\n",
        "a/mod.rs": "pub mod inner;\n",
        "a/inner.rs": "use super::super::b::Y;\npub struct X;\n",
        "b.rs": "use crate::a::inner::X;\npub struct Y;\n",
    },
    1,
    "a::inner -> b -> a::inner",
)
