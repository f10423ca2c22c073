#include "io/vtk/paraview_script.h"

#include <iomanip>
#include <sstream>

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "io/atomic_file.h"
#include "io/curves/curve_writers.h"
#include "io/vtk/vtu_writer.h"

namespace tfd::io {

namespace {

/// A Python string literal (single quotes, backslashes and quotes escaped).
std::string pyString(const std::string& text) {
  std::string out = "'";
  for (char c : text) {
    if (c == '\\' || c == '\'') out += '\\';
    if (c == '\n') {
      out += "\\n";
      continue;
    }
    out += c;
  }
  return out + "'";
}

std::string nameInFolder(const std::filesystem::path& script, const std::filesystem::path& file) {
  const auto folder = std::filesystem::absolute(script).parent_path().lexically_normal();
  if (std::filesystem::absolute(file).parent_path().lexically_normal() != folder) {
    throw core::Error("ParaView script '" + script.string() + "': '" + file.string() +
                      "' is not in the script's folder");
  }
  return file.filename().string();
}

}  // namespace

void writeParaviewScript(const std::filesystem::path& path, const ParaviewScene& scene) {
  const std::string mesh = nameInFolder(path, scene.mesh);
  const std::string curves = scene.curves.empty() ? "" : nameInFolder(path, scene.curves);
  std::ostringstream s;
  s << std::setprecision(9);
  s << "# ParaView scene written by tfd: the field's mesh, its degenerate curves (the paper's\n"
       "# Fig. 5 colours) and tensor glyphs, from the files beside this script.\n"
       "#   paraview --script="
    << path.filename().string()
    << "\n"
       "#   pvpython "
    << path.filename().string()
    << " --png view.png"
       "   (xvfb-run -a pvpython ... without a display)\n"
       "import os\nimport sys\n\nfrom paraview.simple import *\n\n"
       "try:\n    HERE = os.path.dirname(os.path.abspath(__file__))\nexcept NameError:\n"
       "    HERE = "
    << pyString(std::filesystem::absolute(path).parent_path().string())
    << "\n\n"
       "view = GetActiveViewOrCreate('RenderView')\n"
       "mesh = XMLUnstructuredGridReader(registrationName="
    << pyString(mesh) << ",\n                                 FileName=[os.path.join(HERE, "
    << pyString(mesh)
    << ")])\n"
       "meshDisplay = Show(mesh, view)\n"
       "meshDisplay.Representation = 'Surface'\n"
       "meshDisplay.ColorArrayName = ['POINTS', '']  # solid colour\n"
       "meshDisplay.AmbientColor = [0.75, 0.75, 0.75]\n"
       "meshDisplay.DiffuseColor = [0.75, 0.75, 0.75]\n"
       "meshDisplay.Opacity = 0.15\n";
  if (!curves.empty()) {
    s << "\ncurves = XMLPolyDataReader(registrationName=" << pyString(curves)
      << ",\n                           FileName=[os.path.join(HERE, " << pyString(curves)
      << ")])\n";
    if (scene.tubeRadius > 0) {
      s << "curveShape = Tube(registrationName='curve tubes', Input=curves)\n"
           "curveShape.Radius = "
        << scene.tubeRadius << "\ncurveShape.NumberofSides = 12\n";
    } else {
      s << "curveShape = curves\n";
    }
    s << "curvesDisplay = Show(curveShape, view)\n"
         "ColorBy(curvesDisplay, ('POINTS', 'colour'))\n"
         "curvesDisplay.MapScalars = 0  # the RGB values as they are: Fig. 5 colours\n"
         "curvesDisplay.LineWidth = 3\n";
  }
  if (!scene.glyphTensor.empty()) {
    s << "\nsites = MaskPoints(registrationName='glyph sites', Input=mesh)\n"
         "sites.OnRatio = 1\n"
         "sites.MaximumNumberofPoints = "
      << scene.maxGlyphs
      << "\nsites.RandomSampling = 1\n"
         "sites.GenerateVertices = 0\n"
         "glyphs = TensorGlyph(registrationName='glyphs', Input=sites, GlyphType='Sphere')\n"
         "glyphs.Tensors = ['POINTS', "
      << pyString(scene.glyphTensor)
      << "]\n"
         "glyphs.ExtractEigenvalues = 1\n"
         "glyphs.ScaleFactor = "
      << scene.glyphScale << "\n";
    if (!scene.typeArray.empty()) {
      s << "glyphs.Scalars = ['POINTS', " << pyString(scene.typeArray)
        << "]\n"
           "glyphs.ColorGlyphs = 1\n"
           "glyphs.Colorby = 'input scalars'\n";
    }
    s << "glyphsDisplay = Show(glyphs, view)\n";
    if (!scene.typeArray.empty()) {
      s << "ColorBy(glyphsDisplay, ('POINTS', " << pyString(scene.typeArray)
        << "))\n"
           "glyphsDisplay.RescaleTransferFunctionToDataRange(True, False)\n";
    }
  }
  s << "\nview.ResetCamera()\n"
       "view.GetActiveCamera().Dolly(1.6)\n"
       "if '--png' in sys.argv:\n"
       "    view.ViewSize = [1200, 900]\n"
       "    view.OrientationAxesVisibility = 0\n"
       "    SaveScreenshot(sys.argv[sys.argv.index('--png') + 1], view,\n"
       "                   ImageResolution=[1200, 900])\n"
       "else:\n"
       "    Render(view)\n";
  const std::string text = s.str();
  writeAtomically(path, [&](OutputFile& out) { out.stream() << text; });
}

}  // namespace tfd::io

namespace tfd::io {

ParaviewSceneFiles writeFieldParaviewScene(const std::filesystem::path& vtu,
                                           const core::TensorField& field,
                                           const core::DegenerateCurves* curves,
                                           const std::string& glyphTensor, double glyphMargin) {
  const core::TetMesh& mesh = field.mesh();
  ParaviewScene scene;
  scene.mesh = vtu;
  scene.glyphTensor = glyphTensor;
  const double shift = glyphTensorShift(field.values(), glyphMargin);
  double largest = 0;
  for (const core::Tensor& t : field.values())
    largest = std::max(largest, core::eigenDecompose(t).values[0] + shift);
  double volume = 0;
  for (double v : mesh.tetVolumes()) volume += v;
  const double sites = double(std::max<std::size_t>(
      1, std::min<std::size_t>(std::size_t(scene.maxGlyphs), mesh.vertexCount())));
  const double spacing = std::cbrt(volume / sites);
  scene.glyphScale = largest > 0 ? 0.6 * spacing / largest : 1.0;
  scene.tubeRadius = 0.003 * (mesh.boundsMax() - mesh.boundsMin()).norm();

  ParaviewSceneFiles files;
  std::filesystem::path stem = vtu;
  stem.replace_extension();
  if (curves) {
    files.curves = stem.string() + ".curves.vtp";
    writeCurvesVtp(files.curves, *curves);
    scene.curves = files.curves;
  }
  files.script = stem.string() + ".paraview.py";
  writeParaviewScript(files.script, scene);
  return files;
}

}  // namespace tfd::io
