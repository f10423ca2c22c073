#pragma once
// Pixel statistics of rendered pictures for screenshot tests: how many pixels are close to
// each Figure 5 colour (render/ draws curves in exactly those colours, lit only by
// antialiasing), white, the background, and how many distinct colours appear at all.
#include <map>
#include <string>

#include "render/image.h"

namespace tfd::test {

struct ColourCounts {
  std::map<std::string, int> fig5;  ///< "L-wedge", "L-trisector", "P-wedge", "P-trisector"
  int white = 0;
  int background = 0;  ///< pixels equal to the renderer's default background
  int constraint = 0;  ///< the magenta of design elements
  int distinct = 0;    ///< distinct colours (quantised to 5 bits per channel)
};

ColourCounts countColours(const render::Image& image, int tolerance = 40);

/// Writes the picture to $TFD_TEST_IMAGES/<name>.png when that variable is set (to look at
/// what a screenshot test saw); does nothing otherwise.
void keepImage(const render::Image& image, const std::string& name);

}  // namespace tfd::test
