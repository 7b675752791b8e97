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
expect(
    "through a parent's use of its child: the runner's circle (run/columns.rs named "
    "analysis::power_tail's constant, power_tail used run's types, run used columns)",
    {
        "lib.rs": "pub mod analysis;\npub mod run;\n",
        "run/mod.rs": "pub mod columns;\npub struct RunStats;\npub fn go() { columns::names(); }\n",
        "run/columns.rs": "pub fn names() { let _ = crate::analysis::power_tail::EXPONENT; }\n",
        "analysis/mod.rs": "pub mod power_tail;\n",
        "analysis/power_tail.rs": "use crate::run::RunStats;\npub const EXPONENT: &str = \"x\";\n",
    },
    1,
    "analysis::power_tail -> run -> run::columns -> analysis::power_tail",
)
expect(
    "a child taking its parent's own item while the parent calls the child",
    {
        "lib.rs": "pub mod sweep;\n",
        "sweep/mod.rs": "mod shard;\npub struct Sweep;\nimpl Sweep { fn go(&self) { shard::merged(self) } }\n",
        "sweep/shard.rs": "use super::Sweep;\npub fn merged(_: &Sweep) {}\n",
    },
    1,
    "sweep -> sweep::shard -> sweep",
)
expect(
    "no circle: the parent re-exports (grouped) what its child takes from a sibling",
    {
        "lib.rs": "pub mod sweep;\n",
        "sweep/mod.rs": "mod shard;\nmod spec;\npub use spec::{Sweep};\n"
        "impl Sweep { fn go(&self) { shard::merged(self) } }\n",
        "sweep/spec.rs": "pub struct Sweep;\n",
        "sweep/shard.rs": "use super::Sweep;\npub fn merged(_: &Sweep) {}\n",
    },
    0,
)
expect(
    "no circle: a unit test checks a module against one that uses it; an inline module's "
    "super stays in the file",
    {
        "lib.rs": "pub mod sample;\n",
        "sample/mod.rs": "pub mod squeeze;\npub mod normal;\n",
        "sample/squeeze.rs": "pub const W: u8 = 1;\n"
        "#[cfg(test)]\nmod tests {\n    use super::super::normal::wedge;\n}\n"
        "mod render {\n    use super::W;\n}\n",
        "sample/normal.rs": "use super::squeeze::W;\npub fn wedge() {}\n",
    },
    0,
)
