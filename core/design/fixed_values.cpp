#include "core/design/fixed_values.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/error.h"

namespace tfd::core {

std::string FixedValues::summary() const {
  std::ostringstream out;
  out << vertices.size() << " fixed vertices from " << pointElements << " point / " << curveElements
      << " curve elements";
  if (conflicts > 0) out << " (" << conflicts << " shared vertices blended)";
  return out.str();
}

double blendWeight(double distance, double epsilon) {
  return 1.0 / (distance * distance + epsilon * epsilon);
}

FixedValueAccumulator::FixedValueAccumulator(std::size_t vertexCount)
    : sums_(vertexCount), weights_(vertexCount, 0.0), counts_(vertexCount, 0) {}

void FixedValueAccumulator::add(int vertex, const Tensor& value, double weight) {
  if (vertex < 0 || static_cast<std::size_t>(vertex) >= weights_.size())
    throw Error("fixed value for vertex " + std::to_string(vertex) + " out of range (mesh has " +
                std::to_string(weights_.size()) + " vertices)");
  if (!std::isfinite(weight) || weight <= 0)
    throw Error("fixed value for vertex " + std::to_string(vertex) +
                " has an invalid blending weight " + std::to_string(weight));
  for (double c : value.components())
    if (!std::isfinite(c))
      throw Error("fixed value for vertex " + std::to_string(vertex) + " is not finite");
  if (counts_[vertex] == 0) claimed_.push_back(vertex);
  sums_[vertex] += value * weight;
  weights_[vertex] += weight;
  ++counts_[vertex];
  ++contributions_;
}

FixedValues FixedValueAccumulator::finish() const {
  FixedValues result;
  result.vertices = claimed_;
  std::sort(result.vertices.begin(), result.vertices.end());
  result.values.reserve(result.vertices.size());
  for (int v : result.vertices) {
    result.values.push_back(sums_[v] * (1.0 / weights_[v]));
    if (counts_[v] > 1) ++result.conflicts;
  }
  result.contributions = contributions_;
  return result;
}

}  // namespace tfd::core
