#pragma once
// Writers for traced lines (core::Polylines, e.g. hyperstreamlines), chosen by extension.
// Every writer goes through io::writeAtomically: no partial file is ever left behind.
//
// .vtp — VTK XML PolyData for ParaView: one polyline cell per line in <Lines>. Point arrays:
//   "eigenvalues" Float64 × 3 (λ1 ≥ λ2 ≥ λ3 of the interpolated tensor, components named
//   major, medium, minor; active scalars), "major", "medium", "minor" Float64 (the same, one
//   array each, for colouring by name), "arc_length" Float64 (from the line's first point),
//   "line_id" Int32. Cell arrays: "line_id" Int32, "length" Float64, "start_stop" and
//   "end_stop" Int32 (why each end stopped: 0 degenerate, 1 boundary, 2 sharp turn, 3 max
//   length, 4 too close to another line). Field data "family" (the followed eigenvector).
//   Appended binary by default (VTK's default), ASCII or base64 on request.
// .obj — Wavefront OBJ: "v x y z" lines, then per line "o line_<i>" and one two-point
//   "l i j" element per segment (1-based ids), which every importer reads.
#include <filesystem>

#include "core/trace/polylines.h"
#include "io/vtk/vtk_xml.h"

namespace tfd::io {

/// Writes `lines` in the format given by the extension of `path` (.vtp, .obj; case
/// insensitive). Throws core::Error naming the file for an unknown extension or a write failure.
void writeLines(const std::filesystem::path& path, const core::Polylines& lines,
                VtkEncoding vtpEncoding = VtkEncoding::Appended);

void writeLinesVtp(const std::filesystem::path& path, const core::Polylines& lines,
                   VtkEncoding encoding = VtkEncoding::Appended);
void writeLinesObj(const std::filesystem::path& path, const core::Polylines& lines);

}  // namespace tfd::io
