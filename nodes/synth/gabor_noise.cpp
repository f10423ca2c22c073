// GaborNoise: solid anisotropic Gabor noise following the field (paper §8.1), on voxels.
#include "core/synth/gabor_noise.h"

#include <sstream>

#include "graph/node_registry.h"
#include "nodes/export/voxel_export_support.h"
#include "nodes/node_support.h"
#include "nodes/value_types.h"

namespace tfd::nodes {
namespace {

const graph::Choices<core::NoiseOrientation> kOrientationChoices{
    {"auto", core::NoiseOrientation::Auto},
    {"major", core::NoiseOrientation::Major},
    {"medium", core::NoiseOrientation::Medium},
    {"minor", core::NoiseOrientation::Minor}};

const graph::Choices<core::NoiseRange> kRangeChoices{{"positive", core::NoiseRange::Positive},
                                                     {"unit", core::NoiseRange::Unit},
                                                     {"signed", core::NoiseRange::Signed}};

void declare(graph::NodeDecl& d) {
  d.doc(
       "Solid anisotropic Gabor noise whose kernels follow the field: fibres along the major "
       "eigenvector where the tensor is linear, sheets normal to the minor one where it is "
       "planar, isotropic where that structure is undefined. Each kernel is oriented by the "
       "tensor at its centre and has a random phase; the noise depends only on the field, the "
       "parameters and the seed (not on the voxels or the thread count). Voxels whose centre "
       "lies inside the mesh make the volume.")
      .category("Synthesis");
  d.input<core::TensorField>("field").doc("Orients the kernels.");
  d.output<core::ScalarVolume>("volume").doc("The noise on voxels, with the inside mask.");
  d.param<double>("frequency")
      .byDefault(8)
      .min(1e-6)
      .doc("Cycles per world unit across the fibres or sheets (their spacing is 1 / frequency).");
  d.param<double>("bandwidth")
      .byDefault(1)
      .min(0.05)
      .max(8)
      .doc(
          "Spread of frequencies in octaves: smaller gives longer, more regular fibres and "
          "sheets (and wider kernels, slower).");
  d.param<int>("impulses_per_kernel")
      .byDefault(16)
      .min(1)
      .max(128)
      .doc("Mean number of kernels overlapping a point: more is smoother and slower.");
  d.param<int>("seed").byDefault(0).min(0).doc("Another seed gives another noise.");
  declareVoxelSize(d);
  d.param<std::string>("orientation")
      .byDefault("auto")
      .choices(kOrientationChoices)
      .doc(
          "auto: fibres along e1 where linear, sheets normal to e3 where planar, isotropic at "
          "the transition; major / medium: fibres along e1 / e2 everywhere; minor: sheets "
          "normal to e3 everywhere.");
  d.param<std::string>("range")
      .byDefault("positive")
      .choices(kRangeChoices)
      .doc(
          "Voxel values, with sigma the noise's standard deviation: positive: max(0, N) / 3 "
          "sigma up to 1 (crests only, for fog volumes); unit: 0.5 + N / 6 sigma in [0, 1] "
          "(grey levels for images); signed: N / sigma.");
}

void cook(graph::CookContext& c) {
  const auto field = c.input<core::TensorField>("field");
  core::GaborNoiseOptions o;
  o.frequency = c.param<double>("frequency");
  o.bandwidth = c.param<double>("bandwidth");
  o.impulsesPerKernel = c.param<int>("impulses_per_kernel");
  o.seed = std::uint64_t(c.param<int>("seed"));
  o.orientation = c.param("orientation", kOrientationChoices);
  o.range = c.param("range", kRangeChoices);
  const core::VoxelGrid grid = voxelGridOf(c, field->mesh());
  if (1 / (o.frequency * grid.voxelSize) < 3) {
    c.warning("a period of the noise spans fewer than 3 voxels: lower frequency or voxel_size");
  }
  core::GaborNoiseStats stats;
  auto volume = std::make_shared<const core::ScalarVolume>(
      core::gaborNoiseVolume(*field, grid, o, progressOf(c), &stats));
  const auto dims = grid.dims();
  std::ostringstream info;
  info << dims[0] << " x " << dims[1] << " x " << dims[2] << " voxels of " << grid.voxelSize << ", "
       << stats.insideVoxels << " inside; " << stats.impulses << " kernels, "
       << stats.kernelEvaluations << " kernel evaluations";
  c.info(info.str());
  c.setOutput("volume", volume);
}

}  // namespace

void registerGaborNoise(graph::NodeRegistry& r) { r.add("GaborNoise", 1, declare, cook); }

}  // namespace tfd::nodes
