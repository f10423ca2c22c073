// Curve writers: the JSON schema other tools read, VTK PolyData for ParaView, OBJ lines.
#include <gtest/gtest.h>

#include <unistd.h>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "core/error.h"
#include "io/curves/curve_writers.h"
#include "io/vtk/xml_lite.h"

namespace tfd::io {
namespace {

using core::DegenerateCurve;
using core::DegenerateCurves;
using core::DegeneratePattern;
using core::DegenerateType;
using core::Vec3;

std::filesystem::path tempDir() {
  const auto dir =
      std::filesystem::temp_directory_path() / ("tfd_curve_writers_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  return dir;
}

std::string readFile(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

/// An open L curve of 3 points (wedge, transition, trisector) and a closed P loop of 4.
DegenerateCurves sampleCurves() {
  DegenerateCurve open;
  open.type = DegenerateType::Linear;
  open.points = {{0.1, 0.2, 0.3}, {0.4, 0.5, 0.6}, {1.0 / 3, 0.8, 0.9}};
  open.patterns = {DegeneratePattern::Wedge, DegeneratePattern::Transition,
                   DegeneratePattern::Trisector};
  open.tangents.assign(3, Vec3::UnitX());
  open.eigenvectors.assign(3, Vec3::UnitZ());
  DegenerateCurve loop;
  loop.type = DegenerateType::Planar;
  loop.closed = true;
  loop.points = {{2, 0, 0}, {3, 0, 0}, {3, 1, 0}, {2, 1, 0}};
  loop.patterns.assign(4, DegeneratePattern::Wedge);
  return DegenerateCurves({loop, open}, {"a warning"});
}

TEST(CurveWriters, JsonHasExactlyTheDocumentedSchema) {
  const DegenerateCurves curves = sampleCurves();
  const auto path = tempDir() / "curves.json";
  writeCurves(path, curves);
  const auto doc = nlohmann::ordered_json::parse(readFile(path));
  ASSERT_EQ(doc.size(), 3u);
  EXPECT_EQ(doc["format"], "tfd-degenerate-curves");
  EXPECT_EQ(doc["formatVersion"], 1);
  ASSERT_EQ(doc["curves"].size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) {
    const auto& j = doc["curves"][i];
    const DegenerateCurve& c = curves.curve(int(i));
    std::vector<std::string> keys;
    for (auto it = j.begin(); it != j.end(); ++it) keys.push_back(it.key());
    EXPECT_EQ(keys, (std::vector<std::string>{"id", "type", "closed", "points", "pattern"}));
    EXPECT_EQ(j["id"], int(i));
    EXPECT_EQ(j["type"], c.type == DegenerateType::Linear ? "linear" : "planar");
    EXPECT_EQ(j["closed"], c.closed);
    ASSERT_EQ(j["points"].size(), c.points.size());
    ASSERT_EQ(j["pattern"].size(), c.points.size());
    for (std::size_t k = 0; k < c.points.size(); ++k) {
      ASSERT_EQ(j["points"][k].size(), 3u);
      for (int d = 0; d < 3; ++d) EXPECT_EQ(j["points"][k][d].get<double>(), c.points[k][d]);
      EXPECT_EQ(j["pattern"][k], core::toString(c.patterns[k]));
    }
  }
  // Canonical order: the open curve starts at x = 0.1 < 2.
  EXPECT_EQ(doc["curves"][0]["type"], "linear");
  EXPECT_EQ(doc["curves"][0]["pattern"][1], "transition");
  EXPECT_EQ(doc["curves"][1]["closed"], true);
}

TEST(CurveWriters, VtpIsPolyDataWithLinesAndArrays) {
  const DegenerateCurves curves = sampleCurves();
  const auto path = tempDir() / "curves.vtp";
  writeCurves(path, curves);
  const XmlDocument doc = parseXml(readFile(path), path.string());
  ASSERT_EQ(doc.root.name, "VTKFile");
  EXPECT_EQ(*doc.root.attribute("type"), "PolyData");
  const XmlElement* piece = doc.root.child("PolyData")->child("Piece");
  ASSERT_NE(piece, nullptr);
  EXPECT_EQ(*piece->attribute("NumberOfPoints"), "7");
  EXPECT_EQ(*piece->attribute("NumberOfLines"), "2");
  const auto numbers = [&](const XmlElement* parent, const std::string& name) {
    for (const XmlElement* a : parent->childrenNamed("DataArray")) {
      if (*a->attribute("Name") == name) {
        std::vector<double> v;
        std::istringstream s(a->text);
        for (double x; s >> x;) v.push_back(x);
        return v;
      }
    }
    ADD_FAILURE() << "no array " << name;
    return std::vector<double>{};
  };
  const XmlElement* pd = piece->child("PointData");
  ASSERT_NE(pd, nullptr);
  EXPECT_EQ(*pd->attribute("Scalars"), "colour") << "ParaView shows the Fig. 5 colours at once";
  EXPECT_EQ(numbers(pd, "type"), (std::vector<double>{1, 1, 1, -1, -1, -1, -1}));
  EXPECT_EQ(numbers(pd, "pattern"), (std::vector<double>{1, 0, -1, 1, 1, 1, 1}));
  // Fig. 5 colours: L-wedge green, transition white, L-trisector blue, P-wedge yellow.
  const auto colour = numbers(pd, "colour");
  ASSERT_EQ(colour.size(), 21u);
  const auto rgb = [&](int i) {
    return std::array<double, 3>{colour[3 * i], colour[3 * i + 1], colour[3 * i + 2]};
  };
  EXPECT_GT(rgb(0)[1], rgb(0)[0]);
  EXPECT_GT(rgb(0)[1], rgb(0)[2]);
  EXPECT_EQ(rgb(1), (std::array<double, 3>{255, 255, 255}));
  EXPECT_GT(rgb(2)[2], rgb(2)[0]);
  EXPECT_GT(rgb(3)[0], rgb(3)[2]);
  EXPECT_GT(rgb(3)[1], rgb(3)[2]);
  EXPECT_EQ(numbers(pd, "tangent").size(), 21u);
  EXPECT_EQ(numbers(pd, "curve_id"), (std::vector<double>{0, 0, 0, 1, 1, 1, 1}));
  const auto pts = numbers(piece->child("Points"), "Points");
  ASSERT_EQ(pts.size(), 21u);
  EXPECT_EQ(pts[6], 1.0 / 3);  // round-trip precision
  const XmlElement* lines = piece->child("Lines");
  EXPECT_EQ(numbers(lines, "connectivity"), (std::vector<double>{0, 1, 2, 3, 4, 5, 6, 3}));
  EXPECT_EQ(numbers(lines, "offsets"), (std::vector<double>{3, 8}));
  EXPECT_EQ(numbers(piece->child("CellData"), "closed"), (std::vector<double>{0, 1}));

  // The binary encoding parses too.
  writeCurvesVtp(tempDir() / "curves_b64.vtp", curves, VtkEncoding::Base64);
  EXPECT_NO_THROW(parseXml(readFile(tempDir() / "curves_b64.vtp"), "b64"));
}

TEST(CurveWriters, ObjHasOneTwoPointLineElementPerSegment) {
  const auto path = tempDir() / "curves.OBJ";  // extension is case-insensitive
  writeCurves(path, sampleCurves());
  std::istringstream in(readFile(path));
  int vertices = 0;
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("v ", 0) == 0) ++vertices;
    if (line.rfind("l ", 0) == 0) lines.push_back(line);
  }
  EXPECT_EQ(vertices, 7);
  // Blender 3.4 keeps only the first segment of a longer `l` element.
  EXPECT_EQ(lines,
            (std::vector<std::string>{"l 1 2", "l 2 3", "l 4 5", "l 5 6", "l 6 7", "l 7 4"}));
}

TEST(CurveWriters, UnknownExtensionIsAClearErrorAndWritesNothing) {
  const auto path = tempDir() / "curves.xyz";
  try {
    writeCurves(path, sampleCurves());
    FAIL();
  } catch (const core::Error& e) {
    EXPECT_NE(std::string(e.what()).find("curves.xyz"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find(".json"), std::string::npos);
  }
  EXPECT_FALSE(std::filesystem::exists(path));
}

TEST(CurveWriters, EmptyCurveSetsAreValidFiles) {
  const DegenerateCurves none;
  writeCurves(tempDir() / "none.json", none);
  const auto doc = nlohmann::json::parse(readFile(tempDir() / "none.json"));
  EXPECT_TRUE(doc["curves"].is_array());
  EXPECT_TRUE(doc["curves"].empty());
  writeCurves(tempDir() / "none.vtp", none);
  EXPECT_NO_THROW(parseXml(readFile(tempDir() / "none.vtp"), "none"));
}

}  // namespace
}  // namespace tfd::io
