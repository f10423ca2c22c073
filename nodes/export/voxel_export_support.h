#pragma once
// Parameters shared by the voxel exporters (ExportVDB, ExportEXR).
#include <string>
#include <vector>

#include "core/tet_mesh.h"
#include "graph/cook_context.h"
#include "graph/node_decl.h"
#include "io/volume/vdb_writer.h"
#include "io/volume/voxel_density.h"

namespace tfd::nodes {

/// The quantities a voxel export can write, as users name them.
inline const graph::Choices<bool io::VoxelQuantities::*> kVoxelQuantityChoices{
    {"tensor", &io::VoxelQuantities::tensor},
    {"eigenvalues", &io::VoxelQuantities::eigenvalues},
    {"eigenvectors", &io::VoxelQuantities::eigenvectors}};

/// The scalar measures of a field a voxel export can write as `density` / preview colours.
inline const graph::Choices<io::VoxelDensity> kVoxelDensityChoices{
    {"degeneracy", io::VoxelDensity::Degeneracy},
    {"anisotropy", io::VoxelDensity::Anisotropy},
    {"none", io::VoxelDensity::None}};

/// What the measures of kVoxelDensityChoices are, for parameter docs.
inline constexpr const char* kVoxelDensityDoc =
    "degeneracy: closeness to degeneracy by the Lode angle, (2/pi)|asin(mode)| with mode = "
    "3 sqrt(6) det(A/|A|) of the deviator A: 1 on degenerate tensors (a repeated eigenvalue, "
    "where degenerate curves run), 0 on neutral ones (middle eigenvalue 0), linear in the angle "
    "between; anisotropy: |A| divided by its largest value at a mesh vertex, 0 isotropic to 1 "
    "most anisotropic; none: nothing.";

/// Declares `voxel_size` (0: automatic, the mesh's longest bounding-box side / 128).
void declareVoxelSize(graph::NodeDecl& d);

/// Declares `voxel_size` (declareVoxelSize) and the quantity list named `quantitiesName`.
void declareVoxelParams(graph::NodeDecl& d, const std::string& quantitiesName);

/// Declares the inputs of a voxel exporter: `field` and `volume`, both optional (exactly one
/// must be connected: voxelSourceOf).
void declareVoxelInputs(graph::NodeDecl& d);

/// What a voxel exporter writes: its `field` (resampled, with the chosen quantities) or its
/// `volume` (on the volume's own voxels).
enum class VoxelSource { Field, Volume };

/// Exactly one of the inputs `field` and `volume` must be connected, and with `volume` the
/// field-only parameters (`voxel_size` other than 0, quantities other than the default
/// ["tensor"], in the list `quantitiesName`, and `densityName` when given and not its default
/// or "none") are errors naming them.
VoxelSource voxelSourceOf(const graph::CookContext& c, const std::string& quantitiesName,
                          const std::string& densityName = "");

/// Migration of typeVersion 1 parameters: the comma-separated string `from` ("tensor,
/// eigenvalues") becomes the list `to` (["tensor", "eigenvalues"]).
void splitQuantityText(graph::Json& params, const std::string& from, const std::string& to);

/// `voxel_size`, or for 0 the mesh's longest bounding-box side / 128.
double voxelSizeOf(const graph::CookContext& c, const core::TetMesh& mesh);

/// The quantities of the list parameter `name`; a repeated one is an error naming it.
io::VoxelQuantities quantitiesOf(const graph::CookContext& c, const std::string& name);

/// The voxel grid of `voxel_size` (voxelSizeOf) over the mesh's bounding box.
core::VoxelGrid voxelGridOf(const graph::CookContext& c, const core::TetMesh& mesh);

/// "wrote PATH: NX x NY x NZ voxels of SIZE, N active".
std::string voxelInfo(const std::string& what, const io::VoxelExportStats& stats);

}  // namespace tfd::nodes
