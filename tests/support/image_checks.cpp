#include "tests/support/image_checks.h"

#include <cstdlib>
#include <set>
#include <vector>

#include "core/topology/degenerate_curves.h"
#include "render/renderer.h"
#include "render/scene_builder.h"

namespace tfd::test {

ColourCounts countColours(const render::Image& image, int tolerance) {
  // Each pixel goes to the nearest colour of a palette (Figure 5's four, white, the constraint
  // magenta, greys for the background and the translucent boundary) when it lies within
  // `tolerance` * 2 of it in RGB: curves seen through the boundary are tinted, not recoloured.
  ColourCounts c;
  struct Named {
    std::string name;
    std::array<int, 3> rgb;
  };
  using core::DegenerateType;
  using core::DegeneratePattern;
  auto rgb = [](std::array<std::uint8_t, 3> x) { return std::array<int, 3>{x[0], x[1], x[2]}; };
  const render::DrawOptions defaults;
  const std::array<int, 3> bg{int(defaults.background[0] * 255 + 0.5),
                              int(defaults.background[1] * 255 + 0.5),
                              int(defaults.background[2] * 255 + 0.5)};
  const auto& m = render::kConstraintColour;
  const std::vector<Named> palette = {
      {"L-wedge", rgb(core::fig5Colour(DegenerateType::Linear, DegeneratePattern::Wedge))},
      {"L-trisector", rgb(core::fig5Colour(DegenerateType::Linear, DegeneratePattern::Trisector))},
      {"P-wedge", rgb(core::fig5Colour(DegenerateType::Planar, DegeneratePattern::Wedge))},
      {"P-trisector", rgb(core::fig5Colour(DegenerateType::Planar, DegeneratePattern::Trisector))},
      {"white", {255, 255, 255}},
      {"constraint", {m[0], m[1], m[2]}},
      {"grey", {110, 115, 125}},
      {"dark", bg},
  };
  for (int i = 0; i < 4; ++i) c.fig5[palette[i].name] = 0;
  std::set<int> distinct;
  const long limit = long(2 * tolerance) * (2 * tolerance);
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const std::uint8_t* p = image.pixel(x, y);
      distinct.insert((p[0] >> 3) << 10 | (p[1] >> 3) << 5 | (p[2] >> 3));
      if (std::abs(p[0] - bg[0]) <= 2 && std::abs(p[1] - bg[1]) <= 2 && std::abs(p[2] - bg[2]) <= 2)
        ++c.background;
      long best = limit;
      int which = -1;
      for (int i = 0; i < static_cast<int>(palette.size()); ++i) {
        long d = 0;
        for (int k = 0; k < 3; ++k)
          d += long(p[k] - palette[i].rgb[k]) * (p[k] - palette[i].rgb[k]);
        if (d < best) best = d, which = i;
      }
      if (which < 0) continue;
      if (which < 4) ++c.fig5[palette[which].name];
      if (palette[which].name == "white") ++c.white;
      if (palette[which].name == "constraint") ++c.constraint;
    }
  c.distinct = static_cast<int>(distinct.size());
  return c;
}

void keepImage(const render::Image& image, const std::string& name) {
  const char* dir = std::getenv("TFD_TEST_IMAGES");
  if (!dir || !*dir) return;
  render::writePng(image, std::string(dir) + "/" + name + ".png");
}

}  // namespace tfd::test
