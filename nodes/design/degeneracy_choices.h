#pragma once
// The string tables of the degeneracy vocabulary (core/degeneracy.h) for design nodes: the
// words users write in graph files and the enums core takes.
#include "core/degeneracy.h"
#include "graph/param.h"

namespace tfd::nodes {

inline const graph::Choices<core::DegenerateType> kDegenerateTypeChoices{
    {"linear", core::DegenerateType::Linear}, {"planar", core::DegenerateType::Planar}};

/// The patterns a design element can have (transition points only arise on extracted curves).
inline const graph::Choices<core::DegeneratePattern> kDesignPatternChoices{
    {"wedge", core::DegeneratePattern::Wedge}, {"trisector", core::DegeneratePattern::Trisector}};

}  // namespace tfd::nodes
