#include "render/colormap.h"

#include <algorithm>
#include <cmath>

namespace tfd::render {

namespace {

struct Stop {
  double t;
  double r, g, b;
};

template <std::size_t N>
Rgba interpolate(const Stop (&stops)[N], double t) {
  if (!std::isfinite(t)) t = stops[0].t;
  t = std::clamp(t, stops[0].t, stops[N - 1].t);
  std::size_t i = 0;
  while (i + 2 < N && t > stops[i + 1].t) ++i;
  const Stop& a = stops[i];
  const Stop& b = stops[i + 1];
  const double u = (t - a.t) / (b.t - a.t);
  auto mix = [u](double x, double y) {
    return static_cast<std::uint8_t>(std::lround(255 * ((1 - u) * x + u * y)));
  };
  return {mix(a.r, b.r), mix(a.g, b.g), mix(a.b, b.b), 255};
}

}  // namespace

Rgba coolWarm(double t) {
  static const Stop stops[] = {{-1, 0.23, 0.30, 0.75},
                               {-0.5, 0.55, 0.69, 1.00},
                               {0, 0.87, 0.87, 0.87},
                               {0.5, 0.96, 0.60, 0.48},
                               {1, 0.71, 0.02, 0.15}};
  return interpolate(stops, t);
}

Rgba sequential(double t) {
  static const Stop stops[] = {{0, 0.27, 0.00, 0.33},
                               {0.25, 0.23, 0.32, 0.55},
                               {0.5, 0.13, 0.57, 0.55},
                               {0.75, 0.37, 0.79, 0.38},
                               {1, 0.99, 0.91, 0.14}};
  return interpolate(stops, t);
}

}  // namespace tfd::render
