#include "graph/version.h"
namespace tfd::graph {
const char* toolVersion() { return "0.1.0"; }
}  // namespace tfd::graph
