#pragma once
// Writers of triangle surface files, for round trips and export: OFF, OBJ, PLY (ASCII or
// binary little/big endian), STL (ASCII or binary). Coordinates are written exactly: shortest
// round-trip decimals in text, float64 in binary PLY; STL stores float32 by definition.
// Every writer writes atomically (io/atomic_file.h) and throws core::Error naming the file.
#include <filesystem>

#include "core/surface/surface_mesh.h"
#include "io/binary_io.h"

namespace tfd::io {

void writeOff(const std::filesystem::path& path, const core::SurfaceMesh& mesh);
void writeObj(const std::filesystem::path& path, const core::SurfaceMesh& mesh);

enum class PlyEncoding { Ascii, BinaryLittleEndian, BinaryBigEndian };
void writePly(const std::filesystem::path& path, const core::SurfaceMesh& mesh,
              PlyEncoding encoding = PlyEncoding::BinaryLittleEndian);

/// Facet normals are computed from the triangles (zero for degenerate ones).
void writeStl(const std::filesystem::path& path, const core::SurfaceMesh& mesh, bool binary = true);

}  // namespace tfd::io
