#pragma once
// A small ParaView Python script that opens a field's .vtu, its degenerate curves (.vtp) and
// tensor glyphs together, written next to them:
//   paraview --script=field.paraview.py              (the GUI, scene ready)
//   pvpython field.paraview.py --png view.png        (renders a picture; needs a display or
//                                                      xvfb-run -a)
// The scene: the mesh as a translucent grey surface; the curves as tubes coloured by their
// `colour` array with Map Scalars off, so the RGB values show as they are (the paper's Fig. 5
// colours, core::fig5Colour); ellipsoid glyphs of the glyph tensor (io/vtk/vtu_writer.h,
// T.glyph) at a random subset of the vertices, coloured by `T.type`. Files are named relative
// to the script's folder (absolute paths as written when __file__ is not set).
#include <filesystem>
#include <string>

#include "core/tensor_field.h"
#include "core/topology/degenerate_curves.h"

namespace tfd::io {

struct ParaviewScene {
  std::filesystem::path mesh;        ///< the .vtu (writeFieldVtu)
  std::filesystem::path curves;      ///< the curves .vtp (writeCurvesVtp); empty: no curves
  std::string glyphTensor;           ///< point array for the glyphs (e.g. "T.glyph"); empty: none
  std::string typeArray = "T.type";  ///< point array the glyphs are coloured by; empty: solid
  double glyphScale = 1;             ///< ParaView's Tensor Glyph scale factor
  int maxGlyphs = 800;               ///< glyphs at most this many (random) vertices
  double tubeRadius = 0;             ///< curve tube radius in world units; 0: plain lines
};

/// Writes the script (atomically). Throws core::Error naming the file when it cannot be
/// written, or when a scene file is not in the script's folder (the script names files by
/// their name only).
void writeParaviewScript(const std::filesystem::path& path, const ParaviewScene& scene);

/// The files of writeFieldParaviewScene, named after the .vtu: field.vtu gives
/// field.curves.vtp and field.paraview.py.
struct ParaviewSceneFiles {
  std::filesystem::path curves;  ///< empty when no curves were given
  std::filesystem::path script;
};

/// Next to `vtu` (already written by writeFieldVtu with glyphTensor, so it holds
/// `glyphTensor`): the curves as .vtp (writeCurvesVtp, when `curves` is not null) and the
/// script. The glyph scale makes the largest glyph axis 0.6 × the mean spacing of the sites
/// (cube root of the mesh volume per glyph) for T + c I, c = glyphTensorShift(values, margin);
/// the tube radius is 0.3 % of the mesh's bounding-box diagonal.
ParaviewSceneFiles writeFieldParaviewScene(const std::filesystem::path& vtu,
                                           const core::TensorField& field,
                                           const core::DegenerateCurves* curves,
                                           const std::string& glyphTensor, double glyphMargin);

}  // namespace tfd::io
