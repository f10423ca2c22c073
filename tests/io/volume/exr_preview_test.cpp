// EXR slices' preview channels R, G, B (the chosen measure through the documented colour map)
// and the layer names OpenEXR parses from the data channels, read back with OpenEXR.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <string>

#include "io/volume/exr_reader.h"
#include "io/volume/exr_writer.h"
#include "io/volume/voxel_density.h"
#include "tests/support/blend_field.h"
#include "tests/support/temp_dir.h"

namespace tfd {
namespace {

using core::Vec3;

TEST(ExrPreview, ColourMapRunsDarkToLightThroughItsStops) {
  const auto at = [](double v) { return io::previewColour(v); };
  EXPECT_EQ(at(0), (std::array<float, 3>{0.05f, 0.05f, 0.35f}));
  EXPECT_EQ(at(1), (std::array<float, 3>{1.0f, 0.95f, 0.6f}));
  EXPECT_EQ(at(-3), at(0));
  EXPECT_EQ(at(7), at(1));
  double previous = -1;
  for (int i = 0; i <= 100; ++i) {  // luminance rises: grey conversions keep the order
    const auto c = at(i / 100.0);
    const double luminance = 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2];
    EXPECT_GT(luminance, previous) << i;
    previous = luminance;
  }
}

TEST(ExrPreview, RgbChannelsShowTheDegeneracyBesideTheDataLayers) {
  test::TempDir dir("exr-preview");
  const core::TensorField field = test::blendField();
  io::ExrExportOptions o;
  o.voxelSize = 0.05;
  o.quantities.eigenvalues = true;
  o.preview = io::voxelDensityFunction(io::VoxelDensity::Degeneracy, field);
  const auto stats = io::writeFieldExrSlices((dir.path() / "s.%03d.exr").string(), field, o);
  ASSERT_EQ(stats.filesWritten, 7);
  const io::ExrImage image = io::readExrImage(stats.files[3]);
  std::set<std::string> channels;
  for (const auto& [name, type] : image.channelTypes) {
    channels.insert(name);
    EXPECT_EQ(type, "float") << name;
  }
  EXPECT_EQ(channels,
            (std::set<std::string>{"A", "B", "G", "R", "T.eigval.x", "T.eigval.y", "T.eigval.z",
                                   "T.xx", "T.xy", "T.xz", "T.yy", "T.yz", "T.zz"}));
  // OpenEXR's own parse: layer T (passes xx …) and T.eigval (x, y, z); R G B A in no layer.
  EXPECT_EQ(image.layers, (std::set<std::string>{"T", "T.eigval"}));

  const Vec3 firstPixel(image.attributes.at("tfd.firstPixel").numbers.at(0),
                        image.attributes.at("tfd.firstPixel").numbers.at(1),
                        image.attributes.at("tfd.firstPixel").numbers.at(2));
  float lo = 2, hi = -1;
  int inside = 0;
  for (int r = 0; r < image.height; ++r) {
    for (int c = 0; c < image.width; ++c) {
      const Vec3 p = firstPixel + Vec3(c * 0.05, -r * 0.05, 0);
      if (image.at("A", c, r) == 0) {
        for (const char* ch : {"R", "G", "B"}) EXPECT_EQ(image.at(ch, c, r), 0.0f);
        continue;
      }
      ++inside;
      const auto expected = io::previewColour(test::independentCloseness(test::blendTensor(p)));
      int k = 0;
      for (const char* ch : {"R", "G", "B"}) {
        const float v = image.at(ch, c, r);
        ASSERT_GE(v, 0.0f);
        ASSERT_LE(v, 1.0f);
        ASSERT_NEAR(v, expected[k++], 2e-5) << ch << " at " << p.transpose();
      }
      lo = std::min(lo, image.at("R", c, r));
      hi = std::max(hi, image.at("R", c, r));
    }
  }
  EXPECT_EQ(inside, image.width * image.height);
  EXPECT_GT(hi - lo, 0.9f);  // R varies over the slice
  // From degenerate (x = 0: light yellow) to neutral (x = 1: dark blue), in every row.
  for (int r = 0; r < image.height; ++r) {
    EXPECT_NEAR(image.at("R", 0, r), 1.0f, 1e-4);
    EXPECT_NEAR(image.at("B", 0, r), 0.6f, 1e-4);
    EXPECT_NEAR(image.at("R", image.width - 1, r), 0.05f, 1e-4);
    EXPECT_NEAR(image.at("B", image.width - 1, r), 0.35f, 1e-4);
  }
}

TEST(ExrPreview, WithoutPreviewThereAreNoRgbChannels) {
  test::TempDir dir("exr-no-preview");
  const core::TensorField field = test::blendField();
  io::ExrExportOptions o;
  o.voxelSize = 0.1;
  const auto stats = io::writeFieldExrSlices((dir.path() / "s.%03d.exr").string(), field, o);
  const io::ExrImage image = io::readExrImage(stats.files[0]);
  for (const char* ch : {"R", "G", "B"}) EXPECT_EQ(image.channelTypes.count(ch), 0u) << ch;
  EXPECT_EQ(image.channelTypes.count("A"), 1u);
}

}  // namespace
}  // namespace tfd
