// VTU export: the file is read back with an independent VTK XML reader and checked against
// the mesh, the field and analytic eigen-decompositions.
#include "io/vtk/vtu_writer.h"
#include "tests/support/temp_dir.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/error.h"
#include "core/structured_mesh.h"
#include "tests/support/vtk_xml_reader.h"

namespace tfd {
namespace {

namespace fs = std::filesystem;
using core::Mat3;
using core::Tensor;
using core::Vec3;

/// Folder names get a per-file prefix so tests running in parallel never share one.
class TempDir : public test::TempDir {
 public:
  explicit TempDir(const std::string& name) : test::TempDir("vtu-" + name) {}
};

Mat3 rotation(double a, double b, double c) {
  return (Eigen::AngleAxisd(a, Vec3::UnitZ()) * Eigen::AngleAxisd(b, Vec3::UnitY()) *
          Eigen::AngleAxisd(c, Vec3::UnitX()))
      .toRotationMatrix();
}

/// Per-vertex tensors R diag(λ) Rᵀ with known, distinct eigenvalues: linear (λ2 < mean),
/// planar (λ2 > mean) and neutral (λ2 = mean) in turn, so every type appears.
struct KnownField {
  std::shared_ptr<const core::TensorField> field;
  std::vector<Vec3> lambdas;
  std::vector<Mat3> rotations;
  std::vector<int> expectedType;
};

KnownField knownField() {
  auto mesh = core::makeBoxMesh(3, 2, 2, Vec3(-1, 0, 0), Vec3(2, 1, 1.5));
  KnownField k;
  std::vector<Tensor> values;
  for (std::size_t v = 0; v < mesh->vertexCount(); ++v) {
    const Vec3 p = mesh->positions()[v];
    const double s = 1 + 0.1 * double(v % 7);
    Vec3 lambda;
    int type;
    switch (v % 3) {
      case 0:
        lambda = Vec3(2, -0.5, -1.5) * s, type = 1;
        break;  // deviator λ2 < 0
      case 1:
        lambda = Vec3(1.5, 0.5, -2) * s, type = -1;
        break;  // deviator λ2 > 0
      default:
        lambda = Vec3(1.3, 0.3, -0.7) * s, type = 0;
        break;  // mean 0.3: neutral
    }
    const Mat3 r = rotation(0.3 + p.x(), 0.7 * p.y() - 0.2, 1.1 * p.z() + 0.4);
    values.push_back(Tensor::fromMatrix(r * lambda.asDiagonal() * r.transpose()));
    k.lambdas.push_back(lambda);
    k.rotations.push_back(r);
    k.expectedType.push_back(type);
  }
  k.field = std::make_shared<core::TensorField>(mesh, std::move(values));
  return k;
}

std::string readBytes(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

void checkFile(const fs::path& path, const KnownField& k, io::VtkEncoding encoding) {
  const auto& mesh = k.field->mesh();
  const test::VtkXmlFile file = test::readVtkXmlFile(path);
  const auto& root = file.root;
  EXPECT_EQ(root.attribute("type"), "UnstructuredGrid");
  EXPECT_EQ(root.attribute("version"), "1.0");
  EXPECT_EQ(root.attribute("byte_order"), "LittleEndian");
  EXPECT_EQ(root.attribute("header_type"), "UInt64");
  const auto& piece = root.child("UnstructuredGrid").child("Piece");
  ASSERT_EQ(piece.attribute("NumberOfPoints"), std::to_string(mesh.vertexCount()));
  ASSERT_EQ(piece.attribute("NumberOfCells"), std::to_string(mesh.tetCount()));
  const std::string format = encoding == io::VtkEncoding::Appended ? "appended"
                             : encoding == io::VtkEncoding::Base64 ? "binary"
                                                                   : "ascii";

  const auto& pointsArray = file.array(piece.child("Points"), "Points");
  EXPECT_EQ(pointsArray.attribute("type"), "Float64");
  EXPECT_EQ(pointsArray.attribute("format"), format);
  EXPECT_EQ(pointsArray.attribute("NumberOfComponents"), "3");
  const auto points = file.values(pointsArray);
  ASSERT_EQ(points.size(), 3 * mesh.vertexCount());
  for (std::size_t v = 0; v < mesh.vertexCount(); ++v)
    for (int a = 0; a < 3; ++a) ASSERT_EQ(points[3 * v + a], mesh.positions()[v][a]);

  const auto& cells = piece.child("Cells");
  const auto connectivity = file.values(file.array(cells, "connectivity"));
  const auto offsets = file.values(file.array(cells, "offsets"));
  const auto types = file.values(file.array(cells, "types"));
  EXPECT_EQ(file.array(cells, "types").attribute("type"), "UInt8");
  ASSERT_EQ(connectivity.size(), 4 * mesh.tetCount());
  ASSERT_EQ(offsets.size(), mesh.tetCount());
  ASSERT_EQ(types.size(), mesh.tetCount());
  for (std::size_t t = 0; t < mesh.tetCount(); ++t) {
    ASSERT_EQ(offsets[t], double(4 * (t + 1)));
    ASSERT_EQ(types[t], 10.0);  // VTK_TETRA
    core::Vec3 q[4];
    for (int i = 0; i < 4; ++i) {
      ASSERT_EQ(connectivity[4 * t + i], mesh.tets()[t][i]);
      q[i] = mesh.positions()[std::size_t(connectivity[4 * t + i])];
    }
    // VTK's tetra convention: the first three points seen from the fourth are CCW.
    EXPECT_GT(core::signedVolume(q[0], q[1], q[2], q[3]), 0);
  }

  const auto& pointData = piece.child("PointData");
  EXPECT_EQ(pointData.attribute("Tensors"), "T");
  const auto& tensorArray = file.array(pointData, "T");
  EXPECT_EQ(tensorArray.attribute("NumberOfComponents"), "6");
  EXPECT_EQ(tensorArray.attribute("type"), "Float64");
  EXPECT_EQ(tensorArray.attribute("ComponentName0"), "XX");
  EXPECT_EQ(tensorArray.attribute("ComponentName3"), "XY");
  EXPECT_EQ(tensorArray.attribute("ComponentName4"), "YZ");
  EXPECT_EQ(tensorArray.attribute("ComponentName5"), "XZ");
  const auto tensors = file.values(tensorArray);
  const auto eigval = file.values(file.array(pointData, "T.eigval"));
  const auto e1 = file.values(file.array(pointData, "T.e1"));
  const auto e2 = file.values(file.array(pointData, "T.e2"));
  const auto e3 = file.values(file.array(pointData, "T.e3"));
  const auto& typeArray = file.array(pointData, "T.type");
  EXPECT_EQ(typeArray.attribute("type"), "Int32");
  const auto type = file.values(typeArray);
  ASSERT_EQ(tensors.size(), 6 * mesh.vertexCount());
  ASSERT_EQ(eigval.size(), 3 * mesh.vertexCount());
  ASSERT_EQ(type.size(), mesh.vertexCount());
  for (std::size_t v = 0; v < mesh.vertexCount(); ++v) {
    const Tensor& t = k.field->at(int(v));
    const Mat3 m = t.matrix();
    // VTK order XX YY ZZ XY YZ XZ, read back from the matrix, not from Tensor's fields.
    const double expected[6] = {m(0, 0), m(1, 1), m(2, 2), m(0, 1), m(1, 2), m(0, 2)};
    for (int c = 0; c < 6; ++c) ASSERT_EQ(tensors[6 * v + c], expected[c]) << v << " " << c;
    const double scale = k.lambdas[v].cwiseAbs().maxCoeff();
    const std::vector<double>* vectors[3] = {&e1, &e2, &e3};
    for (int i = 0; i < 3; ++i) {
      EXPECT_NEAR(eigval[3 * v + i], k.lambdas[v][i], 1e-12 * scale) << v;
      const Vec3 e((*vectors[i])[3 * v], (*vectors[i])[3 * v + 1], (*vectors[i])[3 * v + 2]);
      EXPECT_NEAR(e.norm(), 1.0, 1e-12);
      EXPECT_NEAR(std::abs(e.dot(k.rotations[v].col(i))), 1.0, 1e-10) << v << " e" << i + 1;
      EXPECT_LT((m * e - eigval[3 * v + i] * e).norm(), 1e-12 * scale);
    }
    EXPECT_EQ(type[v], k.expectedType[v]) << "vertex " << v;
  }
}

TEST(VtuFieldWriter, AllEncodingsRoundTripMeshTensorsAndEigenData) {
  TempDir dir("encodings");
  const KnownField k = knownField();
  for (auto encoding :
       {io::VtkEncoding::Appended, io::VtkEncoding::Base64, io::VtkEncoding::Ascii}) {
    SCOPED_TRACE(int(encoding));
    io::VtuFieldOptions options;
    options.encoding = encoding;
    const fs::path path = dir.path() / ("field" + std::to_string(int(encoding)) + ".vtu");
    io::writeFieldVtu(path, *k.field, options);
    checkFile(path, k, encoding);
  }
  // Nothing but the three files: no temporary left behind.
  EXPECT_EQ(dir.entries().size(), 3u);
}

TEST(VtuFieldWriter, ExtraPointAndCellArraysKeepTypeAndValues) {
  TempDir dir("extra");
  const KnownField k = knownField();
  const auto& mesh = k.field->mesh();
  io::VtuFieldOptions options;
  options.encoding = io::VtkEncoding::Base64;
  options.eigenvectors = false;
  io::NamedArray colour{"curve colour", 3, {}, io::VtkType::UInt8};
  io::NamedArray height{"height", 1, {}, io::VtkType::Float32};
  for (std::size_t v = 0; v < mesh.vertexCount(); ++v) {
    colour.values.insert(colour.values.end(), {double(v % 256), 255.0, 0.0});
    height.values.push_back(mesh.positions()[v].z() + 0.1);
  }
  io::NamedArray region{"region", 1, {}, io::VtkType::Int32};
  io::NamedArray volume{"volume<&>", 1, mesh.tetVolumes(), io::VtkType::Float64};
  for (std::size_t t = 0; t < mesh.tetCount(); ++t) region.values.push_back(-double(t));
  options.pointData = {colour, height};
  options.cellData = {region, volume};
  const fs::path path = dir.path() / "extra.vtu";
  io::writeFieldVtu(path, *k.field, options);

  const test::VtkXmlFile file = test::readVtkXmlFile(path);
  const auto& piece = file.root.child("UnstructuredGrid").child("Piece");
  const auto& pd = piece.child("PointData");
  const auto& cd = piece.child("CellData");
  EXPECT_THROW(file.array(pd, "T.e1"), std::runtime_error);  // switched off
  EXPECT_EQ(file.array(pd, "curve colour").attribute("type"), "UInt8");
  EXPECT_EQ(file.values(file.array(pd, "curve colour")), colour.values);
  EXPECT_EQ(file.array(pd, "height").attribute("type"), "Float32");
  const auto h = file.values(file.array(pd, "height"));
  for (std::size_t v = 0; v < h.size(); ++v) EXPECT_EQ(h[v], double(float(height.values[v])));
  EXPECT_EQ(file.values(file.array(cd, "region")), region.values);
  EXPECT_EQ(file.values(file.array(cd, "volume<&>")), mesh.tetVolumes());
}

TEST(VtuFieldWriter, BadArraysAndPathsFailWithoutLeavingFiles) {
  TempDir dir("errors");
  const KnownField k = knownField();
  io::VtuFieldOptions options;
  options.pointData = {io::NamedArray{"short", 2, {1.0, 2.0, 3.0}, io::VtkType::Float64}};
  try {
    io::writeFieldVtu(dir.path() / "a.vtu", *k.field, options);
    FAIL() << "expected an error";
  } catch (const core::Error& e) {
    EXPECT_NE(std::string(e.what()).find("'short'"), std::string::npos) << e.what();
  }
  options.pointData = {io::NamedArray{"T", 1, std::vector<double>(k.field->mesh().vertexCount()),
                                      io::VtkType::Float64}};
  EXPECT_THROW(io::writeFieldVtu(dir.path() / "b.vtu", *k.field, options), core::Error);
  options.pointData = {io::NamedArray{
      "half", 1, std::vector<double>(k.field->mesh().vertexCount(), 0.5), io::VtkType::Int32}};
  EXPECT_THROW(io::writeFieldVtu(dir.path() / "c.vtu", *k.field, options), core::Error);
  options.pointData.clear();
  options.cellData = {io::NamedArray{"cells", 1, {1.0}, io::VtkType::Float64}};
  EXPECT_THROW(io::writeFieldVtu(dir.path() / "d.vtu", *k.field, options), core::Error);
  EXPECT_TRUE(dir.entries().empty());

  // A folder that cannot be created: its parent is a regular file.
  { std::ofstream(dir.path() / "file") << "x"; }
  try {
    io::writeFieldVtu(dir.path() / "file" / "sub" / "f.vtu", *k.field);
    FAIL() << "expected an error";
  } catch (const core::Error& e) {
    EXPECT_NE(std::string(e.what()).find("file"), std::string::npos) << e.what();
  }
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"file"});

  // A failed write leaves an existing file untouched.
  const fs::path good = dir.path() / "good.vtu";
  io::writeFieldVtu(good, *k.field);
  const std::string before = readBytes(good);
  options.cellData = {io::NamedArray{"cells", 1, {1.0}, io::VtkType::Float64}};
  EXPECT_THROW(io::writeFieldVtu(good, *k.field, options), core::Error);
  EXPECT_EQ(readBytes(good), before);
  EXPECT_EQ(dir.entries().size(), 2u);
}

TEST(VtuFieldWriter, CancelledExportLeavesNoFile) {
  TempDir dir("cancel");
  const KnownField k = knownField();
  std::atomic<bool> cancel{false};
  const core::Progress progress([&](double, std::string_view) { cancel = true; }, &cancel);
  EXPECT_THROW(io::writeFieldVtu(dir.path() / "c.vtu", *k.field, {}, progress), core::Cancelled);
  EXPECT_TRUE(dir.entries().empty());
}

TEST(VtuFieldWriter, FilesAreByteIdenticalForOneAndTwoThreads) {
  TempDir dir("threads");
  // A larger mesh so the parallel loop really splits.
  auto mesh = core::makeBoxMesh(12, 10, 9, Vec3(-1, -1, -1), Vec3(1, 1, 1));
  std::vector<Tensor> values;
  for (const auto& p : mesh->positions()) {
    values.push_back(Tensor{p.x(), p.y() * p.y(), -p.z(), p.x() * p.y(), 0.3, std::sin(p.z())});
  }
  const core::TensorField field(mesh, std::move(values));
  for (int threads : {1, 2}) {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    io::writeFieldVtu(dir.path() / ("t" + std::to_string(threads) + ".vtu"), field);
  }
  const std::string one = readBytes(dir.path() / "t1.vtu");
  EXPECT_FALSE(one.empty());
  EXPECT_EQ(one, readBytes(dir.path() / "t2.vtu"));
}

TEST(VtkXmlReader, RejectsMalformedXml) {
  EXPECT_THROW(test::parseXml("<a><b></a>"), std::runtime_error);
  EXPECT_THROW(test::parseXml("<a x=1/>"), std::runtime_error);
  EXPECT_THROW(test::parseXml("<a>"), std::runtime_error);
  const auto e = test::parseXml("<?xml version=\"1.0\"?><!-- c --><a k='&lt;v&gt;'><b/>t</a>");
  EXPECT_EQ(e.attribute("k"), "<v>");
  EXPECT_EQ(e.children.size(), 1u);
  EXPECT_EQ(e.text, "t");
}

}  // namespace
}  // namespace tfd
