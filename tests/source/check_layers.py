#!/usr/bin/env python3
"""Layers point down only: every file of a layer (include/momenta/<area>/ and src/<area>/)
includes momenta headers of its own layer and of the layers it depends on, as
docs/architecture.md's table and src/CMakeLists.txt's DEPENDS say — no more. Also: every layer of
the map below has its row in docs/architecture.md. Exits 1 naming each include that points up.

    check_layers.py SOURCE_DIR
"""

import pathlib
import re
import sys

# Each folder (include/momenta/<folder>, src/<folder>) and its layer; a layer and the layers it
# depends on directly (src/CMakeLists.txt's PUBLIC and PRIVATE DEPENDS).
LAYER_OF = {
    "common": "core", "math": "core", "inertia": "inertia", "model": "model",
    "dynamics": "dynamics", "integrate": "integrate", "rigid_body": "rigid_body",
    "system": "system", "simulate": "simulate", "analysis": "analysis", "symbolic": "symbolic",
    "sweep_design": "sweep_design", "io": "io", "identify": "identify", "frontend": "frontend",
    "sweep": "sweep",
    "report": "report",
}
DEPENDS = {
    "core": [],
    "inertia": ["core"],
    "model": ["inertia"],
    "dynamics": ["model"],
    "integrate": ["core"],
    "rigid_body": ["inertia"],
    "system": ["dynamics", "integrate", "rigid_body"],
    "simulate": ["system"],
    "analysis": ["system"],
    "symbolic": ["model"],
    "sweep_design": ["model"],
    "io": ["inertia", "model", "sweep_design"],
    "identify": ["io", "simulate", "analysis"],
    "frontend": ["io", "simulate"],
    "sweep": ["frontend", "simulate", "analysis", "sweep_design"],
    "report": ["io", "simulate", "analysis", "symbolic"],
}


def reachable(layer):
    seen, stack = {layer}, [layer]
    while stack:
        for below in DEPENDS[stack.pop()]:
            if below not in seen:
                seen.add(below)
                stack.append(below)
    return seen


def folder_of_header(header):
    """'momenta/sweep/design.hpp' → 'sweep'; the sweep-design headers live in sweep/ too."""
    parts = header.split("/")
    return parts[1] if len(parts) > 2 else None


def main():
    root = pathlib.Path(sys.argv[1])
    problems = []
    # The sweep-design layer's headers sit in include/momenta/sweep/ beside the sweep layer's:
    # which layer a sweep header belongs to is read from where its source is built.
    cmake = (root / "src" / "CMakeLists.txt").read_text(encoding="utf-8")
    design = re.search(r"momenta_add_library\(sweep_design(.*?)PUBLIC_DEPENDS", cmake, re.S).group(1)
    design_stems = {pathlib.Path(f).stem for f in re.findall(r"sweep/(\S+)\.cpp", design)}
    design_stems.add("sweep_spec")  # the description itself, header only

    def layer_of(path_parts, stem):
        folder = path_parts[0]
        if folder == "sweep" and stem in design_stems:
            return "sweep_design"
        return LAYER_OF.get(folder)

    checked = 0
    for top, prefix in (("include/momenta", 2), ("src", 1)):
        for path in sorted((root / top).rglob("*")):
            if path.suffix not in (".cpp", ".hpp"):
                continue
            relative = path.relative_to(root / top).parts
            layer = layer_of(relative, path.stem)
            if layer is None:
                continue
            allowed = reachable(layer)
            for number, line in enumerate(path.read_text(encoding="utf-8").splitlines(), 1):
                match = re.match(r'\s*#include\s+"(momenta/[^"]+)"', line)
                if not match:
                    continue
                checked += 1
                header = match.group(1)
                folder = folder_of_header(header)
                target = layer_of([folder], pathlib.Path(header).stem) if folder else None
                if target is not None and target not in allowed:
                    problems.append(f"{path.relative_to(root)}:{number}: the {layer} layer includes "
                                    f"{header} of the {target} layer, which is not below it")
    page = (root / "docs" / "architecture.md").read_text(encoding="utf-8")
    for layer in DEPENDS:
        if f"`momenta::{layer}`" not in page:
            problems.append(f"docs/architecture.md: no row names `momenta::{layer}`")
    for problem in problems:
        print(problem)
    print(f"{checked} includes checked, {len(problems)} problems")
    return 1 if problems or checked < 100 else 0


if __name__ == "__main__":
    sys.exit(main())
