#pragma once
// Streamtubes: a circle or flat-ribbon profile swept along each line with twist-free frames
// (bishop_frames.h), the paper's noodles (§8, Figure 20). Each line becomes one closed,
// consistently oriented (outward, counter-clockwise seen from outside) surface: the swept
// side and a flat cap at each end.
#include "core/progress.h"
#include "core/surface/surface_mesh.h"
#include "core/trace/polylines.h"

namespace tfd::core {

enum class TubeProfile { Circle, Ribbon };
/// What scales the width along a line: nothing, or the magnitude of one eigenvalue.
enum class TubeWidth { Constant, Major, Medium, Minor };

struct TubeOptions {
  TubeProfile profile = TubeProfile::Circle;
  double radius = 0.01;          ///< circle radius, or half the ribbon's width
  int sides = 8;                 ///< circle: polygon sides (3..64)
  double ribbonThickness = 0.2;  ///< ribbon: thickness over width, in (0, 1]
  TubeWidth width = TubeWidth::Constant;
  /// With an eigenvalue width: the radius runs from minWidth × radius at the smallest |λ| of
  /// all lines to radius at the largest.
  double minWidth = 0.25;
};

/// Vertices: one ring per line point plus the two cap centres; lines with fewer than two
/// points are skipped. Lines are swept in parallel into precomputed ranges, so the mesh is
/// the same for any thread count. Throws core::Error for bad options.
SurfaceMesh sweepTubes(const Polylines& lines, const TubeOptions& options,
                       const Progress& progress = {});

/// The profile's corners in the (normal, binormal) plane for unit width, counter-clockwise.
std::vector<Eigen::Vector2d> tubeProfile(const TubeOptions& options);

}  // namespace tfd::core
