#include "apps/tfd/cook_manifest.h"

#include <nlohmann/json.hpp>

#include "graph/atomic_write.h"
#include "graph/graph_file.h"
#include "graph/hash.h"
#include "graph/version.h"

namespace tfd::cli {

namespace {

using Json = nlohmann::ordered_json;

Json header(const ManifestInput& in, const std::string& status) {
  Json j;
  j["format"] = "tfd-cook";
  j["formatVersion"] = 1;
  j["generator"] = std::string("tfd ") + graph::toolVersion();
  j["graph"] = {{"path", in.graphPath},
                {"hash", graph::Hasher().add(graph::graphToText(in.graph)).finish().toHex()},
                {"sets", in.sets}};
  j["status"] = status;
  return j;
}

void write(const std::filesystem::path& dir, const Json& j) {
  graph::writeTextFileAtomically(dir / kManifestName, j.dump(2) + "\n");
}

}  // namespace

void writeRunningManifest(const std::filesystem::path& dir, const ManifestInput& in) {
  Json j = header(in, "running");
  j["nodes"] = Json::array();
  j["files"] = Json::array();
  write(dir, j);
}

void writeFinalManifest(const std::filesystem::path& dir, const ManifestInput& in,
                        const graph::CookResult& result, bool cancelled, const std::string& error) {
  const bool failed = !error.empty() || (!result.ok() && !cancelled && !result.cancelled);
  const char* status = cancelled || result.cancelled ? "cancelled" : failed ? "failed" : "complete";
  Json j = header(in, status);
  if (std::string(status) == "failed") {
    Json list = Json::array();
    if (!error.empty()) list.push_back({{"node", nullptr}, {"type", nullptr}, {"message", error}});
    for (const graph::NodeReport& r : result.reports)
      if (r.state == graph::NodeState::Failed) {
        std::string message;
        for (const graph::NodeMessage& m : r.messages)
          if (m.severity == graph::Severity::Error)
            message += (message.empty() ? "" : "; ") + m.text;
        list.push_back({{"node", r.node}, {"type", r.type}, {"message", message}});
      }
    j["failed"] = std::move(list);
  }
  Json nodes = Json::array(), files = Json::array();
  for (const graph::NodeReport& r : result.reports) {
    std::string state(graph::stateName(r.state));
    if (r.fromDisk) state += " (disk)";
    nodes.push_back({{"node", r.node}, {"type", r.type}, {"key", r.key.toHex()}, {"state", state}});
    const bool written = r.state == graph::NodeState::Cooked;
    if (!written && r.state != graph::NodeState::Cached) continue;
    for (const graph::FileStamp& f : r.files)
      files.push_back({{"node", r.node},
                       {"path", f.path.string()},
                       {"size", static_cast<std::uint64_t>(f.size)},
                       {"written", written}});
  }
  j["nodes"] = std::move(nodes);
  j["files"] = std::move(files);
  write(dir, j);
}

}  // namespace tfd::cli
