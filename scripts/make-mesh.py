#!/usr/bin/env python3
"""Writes a generated test model for `shadowlab bench`: a bumpy sphere on four legs, of about
the given number of triangles, as binary PLY. Usage: make-mesh.py TRIANGLES OUT.ply"""
import math
import struct
import sys


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    target = int(sys.argv[1])
    # A UV sphere of `segments` x `rings` quads has about 2 * segments * rings triangles.
    rings = max(3, int(math.sqrt(target / 4)))
    segments = max(3, 2 * rings)
    vertices = []
    for r in range(rings + 1):
        theta = math.pi * r / rings
        for s in range(segments + 1):
            phi = 2 * math.pi * s / segments
            bump = 1.0 + 0.08 * math.sin(7 * phi) * math.sin(5 * theta)
            vertices.append((bump * math.sin(theta) * math.cos(phi), 1.6 + bump * math.cos(theta), bump * math.sin(theta) * math.sin(phi)))
    faces = []
    for r in range(rings):
        for s in range(segments):
            a = r * (segments + 1) + s
            b = a + segments + 1
            if r > 0:
                faces.append((a, a + 1, b))
            if r < rings - 1:
                faces.append((a + 1, b + 1, b))
    # Four square legs from the ground (y = 0) to the sphere, so the model stands and casts.
    for lx, lz in ((0.5, 0.5), (-0.5, 0.5), (0.5, -0.5), (-0.5, -0.5)):
        base = len(vertices)
        w = 0.06
        for y in (0.0, 1.0):
            for dx, dz in ((-w, -w), (w, -w), (w, w), (-w, w)):
                vertices.append((lx + dx, y, lz + dz))
        for i in range(4):
            j = (i + 1) % 4
            faces.append((base + i, base + 4 + j, base + j))
            faces.append((base + i, base + 4 + i, base + 4 + j))
    with open(sys.argv[2], "wb") as out:
        out.write(("ply\nformat binary_little_endian 1.0\nelement vertex %d\nproperty float x\nproperty float y\nproperty float z\n"
                   "element face %d\nproperty list uchar int vertex_indices\nend_header\n" % (len(vertices), len(faces))).encode())
        out.write(b"".join(struct.pack("<3f", *v) for v in vertices))
        out.write(b"".join(struct.pack("<B3i", 3, *f) for f in faces))
    print("%s: %d triangles, %d vertices" % (sys.argv[2], len(faces), len(vertices)))


if __name__ == "__main__":
    main()
