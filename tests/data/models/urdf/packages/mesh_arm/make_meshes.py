#!/usr/bin/env python3
"""Writes the mesh arm's meshes (run from anywhere; the files land in meshes/ beside this script).

  upper_arm.stl  ASCII STL, a regular hexagonal prism (circumradius 0.04 m, length 0.375 m, axis z),
                 coordinates with 17 significant digits so they arrive exactly in double precision
  box.stl        binary STL, the unit cube centred at the origin (the URDF scales it per axis)
  base.stl       binary STL, a 0.25 x 0.25 x 0.125 m box centred at the origin
  hand.dae       COLLADA, a 50 x 80 x 30 mm box drawn in millimetres (<unit meter="0.001"/>), Z_UP
  hex_prism.stl  binary STL, the upper arm's prism again (MuJoCo 2.2 reads binary STL only)
  wedge.stl      binary STL, a right-triangular prism away from the origin (legs 0.1 and 0.06 m,
                 0.04 m thick, its corner at (0.05, 0.02, 0.01)): the MJCF arm's hand, whose
                 file coordinates MuJoCo keeps by composing the mesh's offset into the geom frame

Binary STL stores single-precision floats: every coordinate here (±0.5, ±0.125, ±0.0625) is a
binary fraction, exact in single precision. Closed forms of these solids are what the tests hold
the mass properties computed from the meshes to (tests/unit/io/urdf_meshes_test.cpp).
"""
import math
import pathlib
import struct

HERE = pathlib.Path(__file__).resolve().parent / "meshes"


def box_triangles(hx, hy, hz):
    """The 12 outward triangles of the box [-hx, hx] x [-hy, hy] x [-hz, hz]."""
    v = [(sx * hx, sy * hy, sz * hz) for sx in (-1, 1) for sy in (-1, 1) for sz in (-1, 1)]
    idx = lambda sx, sy, sz: ((sx > 0) * 4 + (sy > 0) * 2 + (sz > 0))
    faces = []
    # Each face as a quad (counter-clockwise seen from outside), split in two.
    quads = [
        [(-1, -1, -1), (-1, -1, 1), (-1, 1, 1), (-1, 1, -1)],  # -x
        [(1, -1, -1), (1, 1, -1), (1, 1, 1), (1, -1, 1)],  # +x
        [(-1, -1, -1), (1, -1, -1), (1, -1, 1), (-1, -1, 1)],  # -y
        [(-1, 1, -1), (-1, 1, 1), (1, 1, 1), (1, 1, -1)],  # +y
        [(-1, -1, -1), (-1, 1, -1), (1, 1, -1), (1, -1, -1)],  # -z
        [(-1, -1, 1), (1, -1, 1), (1, 1, 1), (-1, 1, 1)],  # +z
    ]
    for q in quads:
        a, b, c, d = (v[idx(*p)] for p in q)
        faces += [(a, b, c), (a, c, d)]
    return faces


def hexagonal_prism_triangles(radius, length):
    h = length / 2
    ring = [(radius * math.cos(k * math.pi / 3), radius * math.sin(k * math.pi / 3)) for k in range(6)]
    bottom = [(x, y, -h) for x, y in ring]
    top = [(x, y, h) for x, y in ring]
    faces = []
    for k in range(6):
        n = (k + 1) % 6
        faces += [(bottom[k], bottom[n], top[n]), (bottom[k], top[n], top[k])]
    for k in range(1, 5):  # caps as fans from corner 0
        faces.append((top[0], top[k], top[k + 1]))
        faces.append((bottom[0], bottom[k + 1], bottom[k]))
    return faces


def wedge_triangles(a, b, thickness, corner):
    """A right-triangular prism: legs a along x and b along y from `corner`, `thickness` along z."""
    cx, cy, cz = corner
    lo = [(cx, cy, cz), (cx + a, cy, cz), (cx, cy + b, cz)]
    hi = [(x, y, z + thickness) for x, y, z in lo]
    faces = [(lo[0], lo[2], lo[1]), (hi[0], hi[1], hi[2])]
    for k in range(3):
        n = (k + 1) % 3
        faces += [(lo[k], lo[n], hi[n]), (lo[k], hi[n], hi[k])]
    return faces


def normal(t):
    (ax, ay, az), (bx, by, bz), (cx, cy, cz) = t
    u = (bx - ax, by - ay, bz - az)
    w = (cx - ax, cy - ay, cz - az)
    n = (u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0])
    s = math.sqrt(sum(c * c for c in n))
    return tuple(c / s for c in n)


def write_ascii_stl(path, name, triangles):
    lines = [f"solid {name}"]
    for t in triangles:
        lines.append("  facet normal {:.17g} {:.17g} {:.17g}".format(*normal(t)))
        lines.append("    outer loop")
        for p in t:
            lines.append("      vertex {:.17g} {:.17g} {:.17g}".format(*p))
        lines.append("    endloop")
        lines.append("  endfacet")
    lines.append(f"endsolid {name}")
    path.write_text("\n".join(lines) + "\n")


def write_binary_stl(path, triangles):
    data = bytearray(b"momenta mesh arm".ljust(80, b" "))
    data += struct.pack("<I", len(triangles))
    for t in triangles:
        data += struct.pack("<3f", *normal(t))
        for p in t:
            data += struct.pack("<3f", *p)
        data += struct.pack("<H", 0)
    path.write_bytes(bytes(data))


def write_collada_box(path, size_mm):
    triangles = box_triangles(*(s / 2 for s in size_mm))
    points = sorted({p for t in triangles for p in t})
    index = {p: i for i, p in enumerate(points)}
    positions = " ".join("{:g} {:g} {:g}".format(*p) for p in points)
    faces = " ".join(str(index[p]) for t in triangles for p in t)
    path.write_text(f"""<?xml version="1.0" encoding="utf-8"?>
<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">
  <asset>
    <unit name="millimeter" meter="0.001"/>
    <up_axis>Z_UP</up_axis>
  </asset>
  <library_geometries>
    <geometry id="hand-mesh" name="hand">
      <mesh>
        <source id="hand-positions">
          <float_array id="hand-positions-array" count="{3 * len(points)}">{positions}</float_array>
          <technique_common>
            <accessor source="#hand-positions-array" count="{len(points)}" stride="3">
              <param name="X" type="float"/>
              <param name="Y" type="float"/>
              <param name="Z" type="float"/>
            </accessor>
          </technique_common>
        </source>
        <vertices id="hand-vertices">
          <input semantic="POSITION" source="#hand-positions"/>
        </vertices>
        <triangles count="{len(triangles)}">
          <input semantic="VERTEX" source="#hand-vertices" offset="0"/>
          <p>{faces}</p>
        </triangles>
      </mesh>
    </geometry>
  </library_geometries>
  <library_visual_scenes>
    <visual_scene id="scene" name="scene">
      <node id="hand" name="hand">
        <instance_geometry url="#hand-mesh"/>
      </node>
    </visual_scene>
  </library_visual_scenes>
  <scene>
    <instance_visual_scene url="#scene"/>
  </scene>
</COLLADA>
""")


if __name__ == "__main__":
    HERE.mkdir(exist_ok=True)
    write_ascii_stl(HERE / "upper_arm.stl", "upper_arm", hexagonal_prism_triangles(0.04, 0.375))
    write_binary_stl(HERE / "box.stl", box_triangles(0.5, 0.5, 0.5))
    write_binary_stl(HERE / "base.stl", box_triangles(0.125, 0.125, 0.0625))
    write_collada_box(HERE / "hand.dae", (50, 80, 30))
    write_binary_stl(HERE / "hex_prism.stl", hexagonal_prism_triangles(0.04, 0.375))
    write_binary_stl(HERE / "wedge.stl", wedge_triangles(0.1, 0.06, 0.04, (0.05, 0.02, 0.01)))
