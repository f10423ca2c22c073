#pragma once
// Building a Scene from core values: the boundary of a tet mesh, degenerate curves in the
// paper's Figure 5 colours with their transition points, design elements (constraint curves
// with their frames, design points), a cutting plane coloured by a quantity of the field, and
// outlines of regions. Deterministic; no OpenGL (runs on any thread).
#include <optional>
#include <string_view>
#include <vector>

#include "core/design/design_element.h"
#include "core/tensor_field.h"
#include "core/tet_mesh.h"
#include "core/topology/degenerate_curves.h"
#include "core/trace/polylines.h"
#include "render/scene.h"

namespace tfd::render {

/// What the cutting plane shows: mode (linear +1 red, planar −1 blue, Fig. 2's two kinds of
/// region), degeneracy (the normalised discriminant: dark on degenerate curves), or the norm.
enum class SliceQuantity { Mode, Degeneracy, Norm };
std::optional<SliceQuantity> parseSliceQuantity(std::string_view name);
const char* toString(SliceQuantity quantity);

struct SliceSettings {
  int axis = 2;           ///< the plane is perpendicular to x (0), y (1) or z (2)
  double position = 0.5;  ///< where along the mesh's extent on that axis, in [0, 1]
  SliceQuantity quantity = SliceQuantity::Mode;
};

struct SceneInput {
  const core::TetMesh* mesh = nullptr;
  const core::TensorField* field = nullptr;
  const core::DegenerateCurves* curves = nullptr;
  const core::Polylines* lines = nullptr;
  std::vector<const core::ConstraintSet*> constraints;
  std::optional<SliceSettings> slice;  ///< needs a field
};

Scene buildScene(const SceneInput& input);

void addBoundary(Scene& scene, const core::TetMesh& mesh);
/// Segments coloured by curve type and the pattern of their points (L-wedge green,
/// L-trisector blue, P-wedge yellow, P-trisector red); transition points white.
void addCurves(Scene& scene, const core::DegenerateCurves& curves);
/// Curve elements as polylines through their samples with short frame axes (in shades of
/// magenta: light u, violet v, white-pink tangent); point elements as points with their frames.
/// `frameLength` in world units.
/// Traced lines, thin, coloured by the eigenvalue of the field they follow (sequential map
/// from its smallest to its largest value over all lines).
void addLines(Scene& scene, const core::Polylines& lines);
void addConstraints(Scene& scene, const core::ConstraintSet& set, double frameLength);
void addSlice(Scene& scene, const core::TensorField& field, const SliceSettings& slice);
void addSphereOutline(Scene& scene, const Vec3& center, double radius, Rgba colour);
void addBoxOutline(Scene& scene, const Vec3& center, const Vec3& size, Rgba colour);
void addMarker(Scene& scene, const Vec3& position, Rgba colour);

/// Colours used for overlays (also by tests looking for them in pictures).
inline constexpr Rgba kConstraintColour{255, 60, 255, 255};
inline constexpr Rgba kRegionColour{0, 230, 230, 255};
inline constexpr Rgba kMarkerColour{255, 140, 0, 255};

}  // namespace tfd::render
