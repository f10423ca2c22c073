#pragma once
// Colour maps of the cutting plane: a diverging cool-warm map for signed quantities in [−1, 1]
// (Moreland's, blue - grey - red) and a sequential map for [0, 1] (viridis-like, dark to bright).
#include "render/scene.h"

namespace tfd::render {

/// t in [−1, 1]: −1 blue, 0 light grey, +1 red.
Rgba coolWarm(double t);
/// t in [0, 1]: dark purple to yellow.
Rgba sequential(double t);

}  // namespace tfd::render
