#pragma once
// Shared OpenVDB set-up for tfd's VDB reader and writer (no OpenVDB types in this header).

namespace tfd::io {

/// Calls openvdb::initialize() exactly once per process (thread-safe); registers the grid
/// types the reader and writer use.
void initializeOpenVdb();

}  // namespace tfd::io
