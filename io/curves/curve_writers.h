#pragma once
// Writers for degenerate curves (core::DegenerateCurves), chosen by file extension. Every
// writer goes through io::writeAtomically: no partial file is ever left behind.
//
// .json  — the exchange format other tools read:
//   {"format": "tfd-degenerate-curves", "formatVersion": 1,
//    "curves": [{"id": 0, "type": "linear" | "planar", "closed": false,
//                "points": [[x, y, z], ...],
//                "pattern": ["wedge" | "trisector" | "transition", ...]}]}
//   with one pattern entry per point; a closed curve does not repeat its first point.
// .vtp   — VTK XML PolyData for ParaView: one polyline per curve in <Lines> (a loop repeats
//   its first point id at the end). Point arrays: "type" Int32 (1 linear, −1 planar, as the
//   T.type array of the .vtu export), "pattern" Int32 (1 wedge, −1 trisector, 0 transition:
//   the sign of the 2-D index), "colour" UInt8 × 3 (the paper's Fig. 5 colours, see
//   core::fig5Colour), "tangent" and "eigenvector" Float64 × 3, "curve_id" Int32. Cell
//   arrays: "curve_id" Int32, "type" Int32, "closed" UInt8. ASCII by default (well-formed XML,
//   small files); the binary encodings of io/vtk/vtk_xml.h on request.
// .obj   — Wavefront OBJ: "v x y z" lines and one "l i j k ..." line element per curve (1-based
//   ids, a loop repeats its first id), preceded by "o curve_<id>_<type>".
#include <filesystem>

#include "core/topology/degenerate_curves.h"
#include "io/vtk/vtk_xml.h"

namespace tfd::io {

struct CurveWriteOptions {
  VtkEncoding vtpEncoding = VtkEncoding::Ascii;
};

/// Writes `curves` in the format given by the extension of `path` (.json, .vtp, .obj; case
/// insensitive). Throws core::Error naming the file for an unknown extension or a write failure.
void writeCurves(const std::filesystem::path& path, const core::DegenerateCurves& curves,
                 const CurveWriteOptions& options = {});

void writeCurvesJson(const std::filesystem::path& path, const core::DegenerateCurves& curves);
void writeCurvesVtp(const std::filesystem::path& path, const core::DegenerateCurves& curves,
                    VtkEncoding encoding = VtkEncoding::Ascii);
void writeCurvesObj(const std::filesystem::path& path, const core::DegenerateCurves& curves);

}  // namespace tfd::io
