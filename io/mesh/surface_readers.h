#pragma once
// Strict readers of triangle surface files: OFF, OBJ, PLY (ASCII and binary little/big endian)
// and STL (ASCII and binary). Each returns a core::SurfaceMesh: polygons with more than three
// vertices are fan-triangulated (v0, vi, vi+1), indices are zero-based, the vertex order
// (counter-clockwise seen from outside by convention) is kept as written.
//
// Every reader throws core::Error naming the file and, for text, the line, and saying what
// was expected and what was found: a missing or unreadable file, a bad header, a bad number, an
// out-of-range index, a truncated file ("file 'x.off': expected 120 vertices, found 37 (file
// ended at line 40)"), a mesh without triangles.
#include <filesystem>

#include "core/surface/surface_mesh.h"

namespace tfd::io {

/// OFF (also COFF/NOFF/CNOFF: extra per-vertex values ignored); optional face colours ignored.
core::SurfaceMesh readOff(const std::filesystem::path& path);

/// Wavefront OBJ: `v x y z [w | r g b]` and `f` with `v`, `v/vt`, `v/vt/vn`, `v//vn` corners;
/// negative indices count back from the last vertex defined; every other statement (vt, vn,
/// o, g, s, usemtl, l, ...) is ignored.
core::SurfaceMesh readObj(const std::filesystem::path& path);

/// PLY: the `vertex` element's x, y, z (any numeric type) and the `face` element's
/// `vertex_indices` (or `vertex_index`) list; other elements and properties are skipped.
core::SurfaceMesh readPly(const std::filesystem::path& path);

/// STL, ASCII or binary (binary when the size is exactly 84 + 50 · count, whatever the header
/// says). STL repeats positions per triangle: exactly equal positions are welded (ids in order
/// of first appearance) and triangles that become degenerate are dropped.
core::SurfaceMesh readStl(const std::filesystem::path& path);

}  // namespace tfd::io
