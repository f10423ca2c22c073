// Hyperstreamlines: evenly spaced lines of one eigenvector field (paper §8, Figure 20).
#include "core/trace/hyperstreamlines.h"

#include "graph/node_registry.h"
#include "nodes/node_support.h"
#include "nodes/value_types.h"

namespace tfd::nodes {
namespace {

const graph::Choices<core::EigenFamily> kFamilies{{"major", core::EigenFamily::Major},
                                                  {"medium", core::EigenFamily::Medium},
                                                  {"minor", core::EigenFamily::Minor}};

void declare(graph::NodeDecl& d) {
  d.doc(
       "Evenly spaced lines along one eigenvector field (Jobard-Lefer placement): RK4 on the "
       "interpolated tensor with every stage sign-aligned to the previous step. Lines stop at "
       "degenerate points (small eigen-gap), at the boundary, on sharp turns, at a maximum "
       "length, or where they come closer to another line than the test distance. The same "
       "lines for any thread count.")
      .category("Synth");
  d.input<core::TensorField>("field");
  d.output<core::Polylines>("lines").doc("Polylines with the eigenvalues at every point.");
  d.param<std::string>("direction")
      .choices(kFamilies)
      .doc("The eigenvector followed: major (largest eigenvalue), medium or minor.");
  d.param<double>("separation")
      .byDefault(0.1)
      .min(1e-6)
      .doc("Distance of every new seed from all lines (world units).");
  d.param<double>("test_ratio")
      .byDefault(0.5)
      .range(0.05, 1)
      .doc(
          "A line stops when it comes within test_ratio × separation of another line (or of "
          "itself): no two lines are ever closer than that.");
  d.param<double>("step").byDefault(0).min(0).doc(
      "RK4 step length; 0: half the smaller of the test distance and the mean edge length.");
  d.param<double>("min_gap").byDefault(0.01).range(0, 1).doc(
      "Stop where the followed eigenvalue's distance to the nearest other one, over the "
      "tensor's deviatoric norm, falls below this (the direction is undefined on degenerate "
      "curves).");
  d.param<double>("max_turn")
      .byDefault(30)
      .range(1, 90)
      .doc("Stop where the direction turns more than this many degrees in one step.");
  d.param<double>("max_length")
      .byDefault(0)
      .min(0)
      .doc("Longest line (half of it on each side of its seed); 0: no limit.");
  d.param<double>("min_length").byDefault(0).min(0).doc("Drop lines shorter than this.");
  d.param<std::vector<graph::Vec3Param>>("seeds").doc(
      "Points to start lines from, traced first and in order (a seed closer than the test "
      "distance to an earlier line is skipped).");
  d.param<bool>("fill").byDefault(true).doc(
      "After the seeds, fill the volume: seeds beside every line, then a lattice of seeds "
      "for the parts not reached.");
}

void cook(graph::CookContext& c) {
  core::HyperstreamlineOptions o;
  o.family = c.param("direction", kFamilies);
  o.separation = c.param<double>("separation");
  o.testRatio = c.param<double>("test_ratio");
  o.step = c.param<double>("step");
  o.minGap = c.param<double>("min_gap");
  o.maxTurnDegrees = c.param<double>("max_turn");
  o.maxLength = c.param<double>("max_length");
  o.minLength = c.param<double>("min_length");
  for (const graph::Vec3Param& p : c.param<std::vector<graph::Vec3Param>>("seeds"))
    o.seeds.push_back(toVec3(p));
  o.automaticSeeds = c.param<bool>("fill");
  const auto field = c.input<core::TensorField>("field");
  auto lines = std::make_shared<const core::Polylines>(
      core::traceHyperstreamlines(*field, o, progressOf(c)));
  if (lines->lines.empty())
    c.warning("no lines: every seed was outside the mesh, degenerate or too close to a line");
  c.info(lines->summary());
  c.setOutput("lines", std::move(lines));
}

}  // namespace

void registerHyperstreamlines(graph::NodeRegistry& r) {
  r.add("Hyperstreamlines", 1, declare, cook);
}

}  // namespace tfd::nodes
