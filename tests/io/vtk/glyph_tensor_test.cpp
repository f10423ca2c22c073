// The glyph-ready tensor of the .vtu export (T.glyph = T + c I) and the ParaView scene script
// that shows it, read back with the independent test reader.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <regex>
#include <set>
#include <sstream>

#include "core/structured_mesh.h"
#include "core/topology/degenerate_curves.h"
#include "io/vtk/paraview_script.h"
#include "io/vtk/vtu_writer.h"
#include "tests/support/temp_dir.h"
#include "tests/support/vtk_xml_reader.h"

namespace tfd {
namespace {

namespace fs = std::filesystem;
using core::Tensor;
using core::Vec3;

/// A traceless field with eigenvalues of both signs and magnitudes that vary over the box,
/// random but fixed (seeded), plus a few degenerate and zero tensors.
core::TensorField mixedField() {
  auto mesh = core::makeBoxMesh(4, 3, 3, Vec3(0, 0, 0), Vec3(1, 0.8, 0.6));
  std::mt19937 rng(7);
  std::normal_distribution<double> normal;
  std::vector<Tensor> values;
  for (std::size_t v = 0; v < mesh->vertexCount(); ++v) {
    Tensor t{normal(rng), normal(rng), normal(rng), normal(rng), normal(rng), normal(rng)};
    values.push_back(t.deviator() * (0.2 + 3 * mesh->positions()[v].x()));
  }
  values[0] = Tensor{2, -1, -1, 0, 0, 0};
  values[1] = Tensor{1, 1, -2, 0, 0, 0};
  values[2] = Tensor{};
  return core::TensorField(std::move(mesh), std::move(values));
}

std::vector<double> pointArray(const test::VtkXmlFile& f, const std::string& name) {
  const auto& pd = f.root.child("UnstructuredGrid").child("Piece").child("PointData");
  return f.values(f.array(pd, name));
}

core::Mat3 matrixAt(const std::vector<double>& a, std::size_t v) {
  return Tensor::fromComponents(
             {a[6 * v], a[6 * v + 1], a[6 * v + 2], a[6 * v + 3], a[6 * v + 4], a[6 * v + 5]})
      .matrix();
}

TEST(GlyphTensor, PositiveDefiniteWithTheEigenvectorsOfT) {
  test::TempDir dir("glyph-tensor");
  const core::TensorField field = mixedField();
  io::VtuFieldOptions o;
  o.glyphTensor = true;
  const fs::path path = dir.path() / "f.vtu";
  io::writeFieldVtu(path, field, o);

  const test::VtkXmlFile f = test::readVtkXmlFile(path);
  const auto& pd = f.root.child("UnstructuredGrid").child("Piece").child("PointData");
  EXPECT_EQ(pd.attribute("Tensors"), "T.glyph");  // Tensor Glyph's default input
  EXPECT_EQ(f.array(pd, "T").attribute("ComponentName0"), "XX");
  const std::vector<double> t = pointArray(f, "T"), g = pointArray(f, "T.glyph");
  ASSERT_EQ(g.size(), 6 * field.mesh().vertexCount());
  double largest = 0;  // max |λ| over the field, from Eigen's solver
  for (std::size_t v = 0; v < field.mesh().vertexCount(); ++v)
    largest = std::max(largest, Eigen::SelfAdjointEigenSolver<core::Mat3>(matrixAt(t, v))
                                    .eigenvalues()
                                    .cwiseAbs()
                                    .maxCoeff());
  double shift = std::nan("");
  for (std::size_t v = 0; v < field.mesh().vertexCount(); ++v) {
    SCOPED_TRACE(v);
    const core::Mat3 mt = matrixAt(t, v), mg = matrixAt(g, v);
    // G − T is one multiple of the identity for the whole field.
    const core::Mat3 d = mg - mt;
    if (std::isnan(shift)) shift = d(0, 0);
    EXPECT_NEAR((d - shift * core::Mat3::Identity()).norm(), 0, 1e-12 * (1 + shift));
    Eigen::SelfAdjointEigenSolver<core::Mat3> es(mg), et(mt);
    // Every eigenvalue positive, at least 0.1 of the field's largest |λ|.
    EXPECT_GT(es.eigenvalues().minCoeff(), 0.1 * largest * (1 - 1e-9));
    // Same eigenvectors where T's eigenvalues are distinct (else any basis of the repeated
    // eigenspace is one): both solvers sort ascending and the shift keeps the order.
    const auto& l = et.eigenvalues();
    for (int k = 0; k < 3; ++k) {
      const bool isolated = (k == 0 || l[k] - l[k - 1] > 1e-6 * largest) &&
                            (k == 2 || l[k + 1] - l[k] > 1e-6 * largest);
      if (!isolated) continue;
      EXPECT_NEAR(std::abs(es.eigenvectors().col(k).dot(et.eigenvectors().col(k))), 1.0, 1e-9)
          << "eigenvector " << k;
      EXPECT_NEAR(es.eigenvalues()[k] - l[k], shift, 1e-9 * (1 + shift));
    }
  }
  EXPECT_NEAR(shift, io::glyphTensorShift(field.values(), 0.1), 1e-12);
}

TEST(GlyphTensor, ShiftFollowsTheDocumentedFormulaAndRefusesABadMargin) {
  // Eigenvalues (2, −1, −1) and (1, 1, −2): min λ3 = −2, max |λ| = 2: c = 2 + 0.1 · 2.
  EXPECT_NEAR(io::glyphTensorShift({Tensor{2, -1, -1, 0, 0, 0}, Tensor{1, 1, -2, 0, 0, 0}}, 0.1),
              2.2, 1e-12);
  EXPECT_NEAR(io::glyphTensorShift({Tensor{}}, 0.1), 0.1, 1e-15);  // zero field: unit scale
  EXPECT_THROW(io::glyphTensorShift({Tensor{}}, 0), core::Error);
}

TEST(GlyphTensor, WithoutTheOptionThereIsNoGlyphArrayAndTIsActive) {
  test::TempDir dir("glyph-off");
  io::writeFieldVtu(dir.path() / "f.vtu", mixedField());
  const test::VtkXmlFile f = test::readVtkXmlFile(dir.path() / "f.vtu");
  const auto& pd = f.root.child("UnstructuredGrid").child("Piece").child("PointData");
  EXPECT_EQ(pd.attribute("Tensors"), "T");
  EXPECT_THROW(f.array(pd, "T.glyph"), std::exception);
}

TEST(ParaviewScene, ScriptNamesTheFilesBesideItWithTheirArrays) {
  test::TempDir dir("paraview-scene");
  const core::TensorField field = mixedField();
  io::VtuFieldOptions o;
  o.glyphTensor = true;
  const fs::path vtu = dir.path() / "f.vtu";
  io::writeFieldVtu(vtu, field, o);
  core::DegenerateCurve curve;
  curve.id = 0;
  curve.type = core::DegenerateType::Linear;
  curve.points = {Vec3(0.1, 0.1, 0.1), Vec3(0.5, 0.4, 0.3)};
  curve.patterns = {core::DegeneratePattern::Wedge, core::DegeneratePattern::Wedge};
  const core::DegenerateCurves curves({curve});
  const io::ParaviewSceneFiles files =
      io::writeFieldParaviewScene(vtu, field, &curves, "T.glyph", 0.1);
  EXPECT_EQ(files.script, dir.path() / "f.paraview.py");
  EXPECT_EQ(files.curves, dir.path() / "f.curves.vtp");
  std::ifstream in(files.script);
  std::stringstream text;
  text << in.rdbuf();
  const std::string script = text.str();
  // Every file the script opens (os.path.join(HERE, 'name')) exists beside it.
  std::set<std::string> opened;
  const std::regex join(R"(os\.path\.join\(HERE, '([^']+)'\))");
  for (auto it = std::sregex_iterator(script.begin(), script.end(), join);
       it != std::sregex_iterator(); ++it)
    opened.insert((*it)[1]);
  EXPECT_EQ(opened, (std::set<std::string>{"f.vtu", "f.curves.vtp"}));
  for (const auto& name : opened) EXPECT_TRUE(fs::exists(dir.path() / name)) << name;
  // The arrays it names are in those files.
  EXPECT_NE(script.find("ColorBy(curvesDisplay, ('POINTS', 'colour'))"), std::string::npos);
  EXPECT_NE(script.find("curvesDisplay.MapScalars = 0"), std::string::npos);
  EXPECT_NE(script.find("glyphs.Tensors = ['POINTS', 'T.glyph']"), std::string::npos);
  const test::VtkXmlFile vtp = test::readVtkXmlFile(files.curves);
  EXPECT_NO_THROW(
      vtp.array(vtp.root.child("PolyData").child("Piece").child("PointData"), "colour"));
  EXPECT_NO_THROW(pointArray(test::readVtkXmlFile(vtu), "T.glyph"));
  EXPECT_NO_THROW(pointArray(test::readVtkXmlFile(vtu), "T.type"));
  // A scene file outside the script's folder is refused, naming it.
  io::ParaviewScene scene;
  scene.mesh = dir.path() / "elsewhere" / "g.vtu";
  EXPECT_THROW(io::writeParaviewScript(dir.path() / "g.py", scene), core::Error);
}

}  // namespace
}  // namespace tfd
