#!/usr/bin/env python3
"""Writes pebble.obj: a closed, smooth, genus-0 surface (a squashed, bumpy icosphere) used by
surface_mesh.tfd.json. Regenerate with: python3 examples/make_pebble.py > examples/pebble.obj"""
import math

def icosphere(levels):
    t = (1 + 5 ** 0.5) / 2
    verts = [(-1, t, 0), (1, t, 0), (-1, -t, 0), (1, -t, 0), (0, -1, t), (0, 1, t),
             (0, -1, -t), (0, 1, -t), (t, 0, -1), (t, 0, 1), (-t, 0, -1), (-t, 0, 1)]
    verts = [tuple(c / math.sqrt(sum(x * x for x in v)) for c in v) for v in verts]
    faces = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4),
             (11, 10, 2), (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8),
             (3, 8, 9), (4, 9, 5), (2, 4, 11), (6, 2, 10), (8, 6, 7), (9, 8, 1)]
    for _ in range(levels):
        cache, out = {}, []
        def mid(a, b):
            key = (min(a, b), max(a, b))
            if key not in cache:
                m = [(p + q) / 2 for p, q in zip(verts[a], verts[b])]
                n = math.sqrt(sum(x * x for x in m))
                verts.append(tuple(x / n for x in m))
                cache[key] = len(verts) - 1
            return cache[key]
        for a, b, c in faces:
            ab, bc, ca = mid(a, b), mid(b, c), mid(c, a)
            out += [(a, ab, ca), (b, bc, ab), (c, ca, bc), (ab, bc, ca)]
        faces = out
    return verts, faces

def pebble(p):
    x, y, z = p
    bump = 1 + 0.08 * math.sin(3 * x + 1) * math.sin(2 * y) + 0.05 * math.cos(4 * z)
    return (1.3 * x * bump, 0.9 * y * bump, 0.6 * z * bump)

verts, faces = icosphere(4)
print("# pebble.obj: written by examples/make_pebble.py")
for v in verts:
    print("v %.6f %.6f %.6f" % pebble(v))
for a, b, c in faces:
    print("f %d %d %d" % (a + 1, b + 1, c + 1))
