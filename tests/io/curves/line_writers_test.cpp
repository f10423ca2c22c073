// Line writers (io/curves/line_writers.h): the .vtp read back by an independent VTK XML reader
// in every encoding, and the .obj's two-point line elements.
#include "io/curves/line_writers.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "core/error.h"
#include "tests/support/temp_dir.h"
#include "tests/support/vtk_xml_reader.h"

namespace tfd::io {
namespace {

using core::Vec3;

core::Polylines sampleLines() {
  core::Polylines lines;
  lines.family = core::EigenFamily::Minor;
  core::Polyline a;
  a.points = {{0, 0, 0}, {1, 0, 0}, {1, 1.0 / 3, 0}};
  a.eigenvalues = {{3, 1, -4}, {2, 0.5, -2.5}, {1, 0, -1}};
  a.stops = {core::LineStop::Degenerate, core::LineStop::TooClose};
  core::Polyline b;
  b.points = {{5, 5, 5}, {5, 5, 6}};
  b.eigenvalues = {{1, 1, -2}, {0.1, 0.2, -0.3}};
  b.stops = {core::LineStop::Boundary, core::LineStop::MaxLength};
  lines.lines = {a, b};
  return lines;
}

TEST(LineWriters, VtpHoldsPolylinesEigenvaluesArcLengthAndStopsInEveryEncoding) {
  test::TempDir dir("line-writers");
  const core::Polylines lines = sampleLines();
  for (VtkEncoding encoding : {VtkEncoding::Appended, VtkEncoding::Base64, VtkEncoding::Ascii}) {
    SCOPED_TRACE(int(encoding));
    const auto path = dir.path() / "lines.vtp";
    writeLines(path, lines, encoding);
    const test::VtkXmlFile f = test::readVtkXmlFile(path);
    EXPECT_EQ(f.root.attribute("type"), "PolyData");
    const test::XmlElement& poly = f.root.child("PolyData");
    EXPECT_EQ(f.values(f.array(poly.child("FieldData"), "family")), std::vector<double>{2});
    const test::XmlElement& piece = poly.child("Piece");
    EXPECT_EQ(piece.attribute("NumberOfPoints"), "5");
    EXPECT_EQ(piece.attribute("NumberOfLines"), "2");
    EXPECT_EQ(f.values(f.array(piece.child("Points"), "Points")),
              (std::vector<double>{0, 0, 0, 1, 0, 0, 1, 1.0 / 3, 0, 5, 5, 5, 5, 5, 6}));
    EXPECT_EQ(f.values(f.array(piece.child("Lines"), "connectivity")),
              (std::vector<double>{0, 1, 2, 3, 4}));
    EXPECT_EQ(f.values(f.array(piece.child("Lines"), "offsets")), (std::vector<double>{3, 5}));
    const test::XmlElement& pd = piece.child("PointData");
    EXPECT_EQ(pd.attribute("Scalars"), "eigenvalues");
    EXPECT_EQ(f.values(f.array(pd, "eigenvalues")),
              (std::vector<double>{3, 1, -4, 2, 0.5, -2.5, 1, 0, -1, 1, 1, -2, 0.1, 0.2, -0.3}));
    EXPECT_EQ(f.array(pd, "eigenvalues").attribute("NumberOfComponents"), "3");
    EXPECT_EQ(f.array(pd, "eigenvalues").attribute("ComponentName2"), "minor");
    EXPECT_EQ(f.values(f.array(pd, "medium")), (std::vector<double>{1, 0.5, 0, 1, 0.2}));
    EXPECT_EQ(f.values(f.array(pd, "arc_length")), (std::vector<double>{0, 1, 1 + 1.0 / 3, 0, 1}));
    EXPECT_EQ(f.values(f.array(pd, "line_id")), (std::vector<double>{0, 0, 0, 1, 1}));
    const test::XmlElement& cd = piece.child("CellData");
    EXPECT_EQ(f.values(f.array(cd, "length")), (std::vector<double>{1 + 1.0 / 3, 1}));
    EXPECT_EQ(f.values(f.array(cd, "start_stop")), (std::vector<double>{0, 1}));
    EXPECT_EQ(f.values(f.array(cd, "end_stop")), (std::vector<double>{4, 3}));
  }
}

TEST(LineWriters, ObjHasEveryPointAndOneTwoPointElementPerSegment) {
  test::TempDir dir("line-writers-obj");
  const auto path = dir.path() / "lines.OBJ";
  writeLines(path, sampleLines());
  std::ifstream in(path);
  std::string line;
  std::vector<Vec3> v;
  std::vector<std::pair<int, int>> segments;
  std::vector<std::string> objects;
  while (std::getline(in, line)) {
    std::istringstream s(line);
    std::string tag;
    s >> tag;
    if (tag == "v") {
      Vec3 p;
      s >> p.x() >> p.y() >> p.z();
      v.push_back(p);
    } else if (tag == "l") {
      int a = 0, b = 0, extra = 0;
      s >> a >> b;
      EXPECT_FALSE(s >> extra) << "two points per element: " << line;
      segments.emplace_back(a, b);
    } else if (tag == "o") {
      std::string name;
      s >> name;
      objects.push_back(name);
    }
  }
  ASSERT_EQ(v.size(), 5u);
  EXPECT_EQ(v[2], Vec3(1, 1.0 / 3, 0)) << "exact round trip";
  EXPECT_EQ(segments, (std::vector<std::pair<int, int>>{{1, 2}, {2, 3}, {4, 5}}));
  EXPECT_EQ(objects, (std::vector<std::string>{"line_0", "line_1"}));
}

TEST(LineWriters, AnUnknownExtensionIsRefusedNamingTheFile) {
  test::TempDir dir("line-writers-ext");
  try {
    writeLines(dir.path() / "lines.ply", sampleLines());
    FAIL() << "accepted .ply";
  } catch (const core::Error& e) {
    EXPECT_NE(std::string(e.what()).find("lines.ply"), std::string::npos) << e.what();
  }
  EXPECT_TRUE(dir.entries().empty());
}

}  // namespace
}  // namespace tfd::io
