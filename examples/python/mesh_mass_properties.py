"""Mass properties of every mesh in a folder (STL and OBJ), exact for the solids they bound:
mass, centre of mass and principal moments, as a table.

    python3 examples/python/mesh_mass_properties.py [FOLDER] [--density KG_PER_M3] [--scale S]

FOLDER defaults to examples/parts/meshes; density to 2700 kg/m³ (aluminium); scale to 0.001
(meshes drawn in millimetres).
"""

import argparse
import pathlib

import momenta
from momenta import inertia

HERE = pathlib.Path(__file__).resolve().parent

parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("folder", nargs="?", type=pathlib.Path, default=HERE.parent / "parts" / "meshes")
parser.add_argument("--density", type=float, default=2700.0)
parser.add_argument("--scale", type=float, default=0.001)
args = parser.parse_args()

paths = sorted(p for p in args.folder.iterdir() if p.suffix.lower() in (".stl", ".obj"))
print(f"{'mesh':<20} {'mass (kg)':>12} {'volume (m³)':>12}   {'centre of mass (m)':<36} principal moments (kg·m²)")
for path in paths:
    try:
        props = inertia.mesh(path, density=args.density, scale=args.scale)
    except momenta.Error as error:  # an open or broken mesh: say why and go on
        print(f"{path.name:<20} {error}")
        continue
    moments, _ = props.principal_axes()
    com = ", ".join(f"{x:+.5f}" for x in props.center_of_mass)
    print(f"{path.name:<20} {props.mass:>12.6g} {props.volume:>12.6g}   [{com}]  "
          + ", ".join(f"{m:.6g}" for m in moments))
