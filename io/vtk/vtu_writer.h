#pragma once
// Export of a tet mesh, or of a TensorField on its mesh, to a VTK XML UnstructuredGrid (.vtu)
// that VTK and ParaView open directly.
//
// File: <VTKFile type="UnstructuredGrid" version="1.0" byte_order="LittleEndian"
// header_type="UInt64">, one Piece; Points Float64 (3); Cells: connectivity and offsets Int64,
// types UInt8 = 10 (VTK_TETRA, vertex order as in TetMesh: positively oriented, which is
// VTK's convention too). Encoding per VtkEncoding (vtk_xml.h): raw appended binary by default.
//
// Point data written by writeFieldVtu (names use the tensor name, "T" by default):
//   T         Float64 × 6, the tensor in VTK order XX, YY, ZZ, XY, YZ, XZ (ComponentName0…5),
//             marked active with <PointData Tensors="T"> so ParaView's Tensor Glyph uses it
//   T.eigval  Float64 × 3, eigenvalues λ1 ≥ λ2 ≥ λ3 (core::eigenDecompose)
//   T.e1 T.e2 T.e3  Float64 × 3, unit eigenvectors of λ1, λ2, λ3 (right-handed; sign arbitrary)
//   T.type    Int32, the tensor's type by the deviator's middle eigenvalue (core::classify):
//             1 linear, −1 planar, 0 neutral
//   T.glyph   Float64 × 6 (optional, glyphTensor): T + c I, one c for the whole field
//             (glyphTensorShift), positive definite with T's eigenvectors; it is then the
//             active tensor, so ParaView's Tensor Glyph draws ellipsoids with no set-up
// followed by the caller's extra point arrays, then the caller's cell arrays as CellData.
// Each of the derived arrays can be switched off. Eigen-decompositions run in parallel with
// one output per vertex: the file is byte-identical for any thread count.
#include <filesystem>
#include <string>
#include <vector>

#include "core/progress.h"
#include "core/tensor_field.h"
#include "core/tet_mesh.h"
#include "io/vtk/vtk_xml.h"

namespace tfd::io {

/// An extra point or cell array: `values` holds count × components numbers, tuple after tuple.
/// They are written as `type`; integer types require integral values in range.
struct NamedArray {
  std::string name;
  int components = 1;
  std::vector<double> values;
  VtkType type = VtkType::Float64;
};

struct VtuMeshOptions {
  VtkEncoding encoding = VtkEncoding::Appended;
  std::vector<NamedArray> pointData;  ///< one tuple per mesh vertex
  std::vector<NamedArray> cellData;   ///< one tuple per tet
  std::string activeTensors;          ///< point array named in <PointData Tensors="…">, if any
  /// Further 6-component Float64 point arrays that, like the active one, get the component
  /// names XX YY ZZ XY YZ XZ.
  std::vector<std::string> tensorArrays;
};

struct VtuFieldOptions {
  VtkEncoding encoding = VtkEncoding::Appended;
  std::string tensorName = "T";
  bool eigenvalues = true;
  bool eigenvectors = true;
  bool tensorType = true;
  double neutralTolerance = 1e-12;    ///< |λ2| / ‖A‖ at or below which a tensor is neutral
  bool glyphTensor = false;           ///< add T.glyph (above) and make it the active tensor
  double glyphMargin = 0.1;           ///< ε of glyphTensorShift
  std::vector<NamedArray> pointData;  ///< extra arrays after the field's
  std::vector<NamedArray> cellData;
};

/// Writes the mesh and the given arrays. Throws core::Error naming the array when its size
/// does not match (count × components), its name is empty or repeated, or an integer array
/// holds a non-integral or out-of-range value; and naming the file when it cannot be written.
/// The file is written atomically (io::writeAtomically).
void writeMeshVtu(const std::filesystem::path& path, const core::TetMesh& mesh,
                  const VtuMeshOptions& options, const core::Progress& progress = core::Progress());

/// The multiple c of the identity that makes every T + c I positive definite for glyphs:
/// c = −min λ3 + ε R, with min λ3 the smallest eigenvalue over all `tensors` and R the largest
/// eigenvalue magnitude (1 when every tensor is zero), so the thinnest glyph axis is at least
/// ε R. One c for all tensors keeps glyph sizes comparable across the field and leaves each
/// tensor's eigenvectors and eigenvalue differences (its shape: linear cigars, planar discs)
/// as they are. Throws core::Error for ε ≤ 0.
double glyphTensorShift(const std::vector<core::Tensor>& tensors, double margin);

/// Writes the field's mesh, its tensors and the derived arrays described above.
void writeFieldVtu(const std::filesystem::path& path, const core::TensorField& field,
                   const VtuFieldOptions& options = {},
                   const core::Progress& progress = core::Progress());

}  // namespace tfd::io
