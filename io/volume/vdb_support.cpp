#include "io/volume/vdb_support.h"

#include <openvdb/openvdb.h>

#include <mutex>

namespace tfd::io {

void initializeOpenVdb() {
  static std::once_flag once;
  std::call_once(once, [] { openvdb::initialize(); });
}

}  // namespace tfd::io
