#!/usr/bin/env python3
"""Writes the small meshes the example parts use. Run from anywhere; rewrites the files beside it.

l_bracket.obj  an L-shaped aluminium bracket in millimetres: a base leg 80 x 40 x 6 and an upright
               leg 6 x 40 x 60 on its x = 0 end (x along the base, y across, z up), 12 vertices.
bus.stl        a satellite bus 1.0 x 0.75 x 1.25 m with a corner at the origin, binary STL (all
               coordinates exact in single precision).

Every mesh is closed and outward-oriented (counter-clockwise seen from outside); the script checks
both before writing.
"""
import os
import struct

HERE = os.path.dirname(os.path.abspath(__file__))


def extrude(profile, y0, y1):
    """Prism over a simple polygon `profile` [(x, z), ...] (counter-clockwise seen from -y) between
    y0 < y1. Caps are fans from profile[0], valid for the star-shaped L used here."""
    n = len(profile)
    vertices = [(x, y0, z) for x, z in profile] + [(x, y1, z) for x, z in profile]
    triangles = []
    for k in range(1, n - 1):
        triangles.append((0, k, k + 1))              # y0 cap: counter-clockwise seen from -y.
        triangles.append((n, n + k + 1, n + k))      # y1 cap: reversed, seen from +y.
    for k in range(n):
        a, b = k, (k + 1) % n
        triangles.append((a, a + n, b + n))          # Side quad over edge a -> b.
        triangles.append((a, b + n, b))
    return vertices, triangles


def signed_volume(vertices, triangles):
    v = 0.0
    for a, b, c in triangles:
        (ax, ay, az), (bx, by, bz), (cx, cy, cz) = vertices[a], vertices[b], vertices[c]
        v += (ax * (by * cz - bz * cy) - ay * (bx * cz - bz * cx) + az * (bx * cy - by * cx)) / 6
    return v


def check_closed(vertices, triangles, expected_volume):
    edges = {}
    for t in triangles:
        for i in range(3):
            e = (t[i], t[(i + 1) % 3])
            edges[e] = edges.get(e, 0) + 1
    for (a, b), count in edges.items():
        assert count == 1 and edges.get((b, a)) == 1, f"edge {a}-{b} is not shared properly"
    volume = signed_volume(vertices, triangles)
    assert abs(volume - expected_volume) <= 1e-9 * expected_volume, (volume, expected_volume)


def write_obj(path, vertices, triangles, comment):
    with open(path, "w") as f:
        f.write(f"# {comment}\n# Written by make_meshes.py.\n")
        for x, y, z in vertices:
            f.write(f"v {x:g} {y:g} {z:g}\n")
        for a, b, c in triangles:
            f.write(f"f {a + 1} {b + 1} {c + 1}\n")


def write_binary_stl(path, vertices, triangles, header):
    with open(path, "wb") as f:
        f.write(header.encode().ljust(80, b" ")[:80])
        f.write(struct.pack("<I", len(triangles)))
        for t in triangles:
            f.write(struct.pack("<3f", 0.0, 0.0, 0.0))  # Normals unused: winding tells outward.
            for i in t:
                f.write(struct.pack("<3f", *vertices[i]))
            f.write(b"\0\0")


def main():
    # L bracket, mm: base [0, 80] x [-20, 20] x [0, 6], upright [0, 6] x [-20, 20] x [6, 66].
    profile = [(0, 0), (80, 0), (80, 6), (6, 6), (6, 66), (0, 66)]
    v, t = extrude(profile, -20, 20)
    check_closed(v, t, 80 * 40 * 6 + 6 * 40 * 60)
    write_obj(os.path.join(HERE, "l_bracket.obj"), v, t, "L bracket, millimetres")

    # Satellite bus, m: the box [0, 1] x [0, 0.75] x [0, 1.25].
    v, t = extrude([(0, 0), (1.0, 0), (1.0, 1.25), (0, 1.25)], 0.0, 0.75)
    check_closed(v, t, 1.0 * 0.75 * 1.25)
    write_binary_stl(os.path.join(HERE, "bus.stl"), v, t, "satellite bus 1.0 x 0.75 x 1.25 m")


if __name__ == "__main__":
    main()
