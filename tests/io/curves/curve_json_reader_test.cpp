// The degenerate-curve JSON reader: reads what writeCurvesJson writes, and every damaged file
// is a core::Error naming the file and the JSON pointer of the place, in our words (never the
// JSON library's), with text from the file quoted printably.
#include "io/curves/curve_json_reader.h"

#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "core/error.h"
#include "tests/support/temp_dir.h"

namespace tfd {
namespace {

namespace fs = std::filesystem;

class CurveJsonReader : public ::testing::Test {
 protected:
  fs::path write(const std::string& text) {
    const fs::path p = dir.path() / "c.json";
    std::ofstream(p, std::ios::binary) << text;
    return p;
  }
  /// The message of the error reading `text`; fails the test when it reads.
  std::string errorOf(const std::string& text) {
    try {
      io::readCurvesJson(write(text));
    } catch (const core::Error& e) {
      return e.what();
    }
    ADD_FAILURE() << "read without error: " << text;
    return {};
  }
  test::TempDir dir{"curve-json-reader"};
};

const std::string kHead = R"({"format": "tfd-degenerate-curves", "formatVersion": 1, "curves": )";

TEST_F(CurveJsonReader, ReadsCurvesTheirPointsAndPatterns) {
  const io::CurveFile f = io::readCurvesJson(write(
      kHead + R"([{"id": 3, "type": "planar", "closed": true, "points": [[0, 1, 2], [3, 4.5, -6]],)"
              R"( "pattern": ["wedge", "transition"]}]})"));
  EXPECT_EQ(f.formatVersion, 1);
  ASSERT_EQ(f.curves.size(), 1u);
  const io::CurveFileEntry& c = f.curves[0];
  EXPECT_EQ(c.id, 3);
  EXPECT_EQ(c.type, core::DegenerateType::Planar);
  EXPECT_TRUE(c.closed);
  ASSERT_EQ(c.points.size(), 2u);
  EXPECT_EQ(c.points[1], core::Vec3(3, 4.5, -6));
  EXPECT_EQ(c.patterns[0], core::DegeneratePattern::Wedge);
  EXPECT_EQ(c.patterns[1], core::DegeneratePattern::Transition);
}

TEST_F(CurveJsonReader, AMissingKeyIsNamedWithItsPlace) {
  const std::string m =
      errorOf(kHead + R"([{"id": 0, "type": "linear", "closed": false, "points": []}]})");
  EXPECT_NE(m.find("curve file '"), std::string::npos) << m;
  EXPECT_NE(m.find("c.json' at /curves/0: missing key \"pattern\""), std::string::npos) << m;
  EXPECT_EQ(m.find("json.exception"), std::string::npos) << m;
  EXPECT_NE(errorOf(R"({"format": "tfd-degenerate-curves", "formatVersion": 1})")
                .find("missing key \"curves\""),
            std::string::npos);
}

TEST_F(CurveJsonReader, WrongValuesSayWhatWasExpectedAndFound) {
  const std::string point = errorOf(
      kHead +
      R"([{"id": 0, "type": "linear", "closed": false, "points": [[0, 0]], "pattern": ["wedge"]}]})");
  EXPECT_NE(
      point.find("at /curves/0/points/0: expected [x, y, z] with 3 finite numbers, found [0,0]"),
      std::string::npos)
      << point;
  const std::string count = errorOf(
      kHead +
      R"([{"id": 0, "type": "linear", "closed": false, "points": [[0, 0, 0]], "pattern": []}]})");
  EXPECT_NE(count.find("at /curves/0/pattern: expected an array of 1 patterns"), std::string::npos)
      << count;
  EXPECT_NE(errorOf(kHead + R"([{"id": -1}]})").find("/curves/0/id: expected a non-negative"),
            std::string::npos);
  EXPECT_NE(errorOf(R"({"format": "tfd-graph"})").find("not a tfd-degenerate-curves file"),
            std::string::npos);
  EXPECT_NE(errorOf(R"({"format": "tfd-degenerate-curves", "formatVersion": 2, "curves": []})")
                .find("version 2 is not supported"),
            std::string::npos);
  EXPECT_NE(errorOf("[1, 2").find("c.json': invalid JSON"), std::string::npos);
  EXPECT_NE(errorOf(kHead + "[[1e400]]}").find("invalid JSON"), std::string::npos);
}

TEST_F(CurveJsonReader, TextFromTheFileIsQuotedWithoutRawControlBytes) {
  const std::string m = errorOf(
      kHead +
      R"([{"id": 0, "type": "\u001b[2Jlinear", "closed": false, "points": [], "pattern": []}]})");
  EXPECT_NE(m.find("expected \"linear\" or \"planar\""), std::string::npos) << m;
  for (unsigned char c : m) EXPECT_GE(c, 0x20) << m;
  const std::string binary = errorOf(std::string("\x01\xff\x1b garbage", 11));
  for (unsigned char c : binary) EXPECT_GE(c, 0x20) << binary;
}

}  // namespace
}  // namespace tfd
