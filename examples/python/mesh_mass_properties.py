"""Mass properties of every mesh in a folder (STL and OBJ), exact for the solids they bound:
mass, centre of mass and principal moments, as a table.

    python3 examples/python/mesh_mass_properties.py [FOLDER] [--density KG_PER_M3] [--units UNIT]

FOLDER defaults to examples/parts/meshes; density to 2700 kg/m³ (aluminium). A mesh file's numbers
carry no unit, so each row says which it was read in: --units (m, cm, mm or in) for every file;
else the unit its header names, where it names one (an STL's 80-byte header, an OBJ's opening
comments: "... 1.0 x 0.75 x 1.25 m", "# L bracket, millimetres"); else metres, momenta's unit.
"""

import argparse
import pathlib
import re
import sys

import momenta
from momenta import inertia

HERE = pathlib.Path(__file__).resolve().parent
METRES_PER = {"m": 1.0, "cm": 0.01, "mm": 0.001, "in": 0.0254}
# Words a header may use for each unit, whole words only ("m" in "mesh" is no unit).
UNIT_WORDS = {"mm": r"mm|millimet(?:re|er)s?", "cm": r"cm|centimet(?:re|er)s?",
              "in": r"in(?:ch|ches)|\"", "m": r"m|met(?:re|er)s?"}


def header_of(path):
    """The text a mesh file opens with: an STL's header or an OBJ's leading comments."""
    data = path.read_bytes()
    if path.suffix.lower() == ".stl" and not data[:5].lower() == b"solid":
        return data[:80].decode("ascii", "replace")
    lines = data.decode("utf-8", "replace").splitlines()
    comments = []
    for line in lines[:20]:
        if line.startswith("#") or line.lower().startswith("solid"):
            comments.append(line.lstrip("#").strip())
        elif line.strip():
            break
    return " ".join(comments)


def units_of(path, given):
    """(unit, where it came from) for one mesh."""
    if given:
        return given, "--units"
    header = header_of(path)
    for unit, words in UNIT_WORDS.items():
        if re.search(rf"(?<![\w.])(?:{words})(?!\w)", header, re.IGNORECASE):
            return unit, "header"
    return "m", "default"


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("folder", nargs="?", type=pathlib.Path,
                        default=HERE.parent / "parts" / "meshes")
    parser.add_argument("--density", type=float, default=2700.0, help="kg/m³ (default 2700)")
    parser.add_argument("--units", choices=sorted(METRES_PER),
                        help="the unit of every file's coordinates (default: each file's header, "
                             "else m)")
    args = parser.parse_args()

    if not args.folder.is_dir():
        sys.exit(f"mesh_mass_properties.py: {args.folder} is not a folder")
    paths = sorted(p for p in args.folder.iterdir() if p.suffix.lower() in (".stl", ".obj"))
    if not paths:
        sys.exit(f"mesh_mass_properties.py: no .stl or .obj file in {args.folder}")

    print(f"density {args.density:g} kg/m³")
    print(f"{'mesh':<16} {'units':<12} {'mass (kg)':>12} {'volume (m³)':>12}   "
          f"{'centre of mass (m)':<36} principal moments (kg·m²)")
    failures = 0
    for path in paths:
        unit, source = units_of(path, args.units)
        try:
            props = inertia.mesh(path, density=args.density, scale=METRES_PER[unit])
        except momenta.Error as error:  # an open or broken mesh: say why and go on
            print(f"{path.name:<16} {error}")
            failures += 1
            continue
        moments, _ = props.principal_axes()
        com = ", ".join(f"{x:+.5f}" for x in props.center_of_mass)
        print(f"{path.name:<16} {unit + ' (' + source + ')':<12} {props.mass:>12.6g} "
              f"{props.volume:>12.6g}   [{com}]  " + ", ".join(f"{m:.6g}" for m in moments))
    sys.exit(1 if failures == len(paths) else 0)


if __name__ == "__main__":
    main()
