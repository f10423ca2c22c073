#include "apps/tfd/cook_report.h"

#include <cstdio>
#include <ostream>

#include "apps/tfd/cli.h"

namespace tfd::cli {

int printCookReport(const graph::CookResult& result, const ReportOptions& options,
                    std::ostream& out, std::ostream& err) {
  using graph::NodeState;
  using graph::Severity;
  std::size_t failed = 0, warnings = 0;
  for (const graph::NodeReport& r : result.reports) {
    const std::string who = "node \"" + r.node + "\" (" + r.type + ")";
    for (const graph::NodeMessage& m : r.messages) {
      switch (m.severity) {
        case Severity::Error:
          err << "tfd: " << who << ": " << m.text << "\n";
          break;
        case Severity::Warning:
          ++warnings;
          if (!options.quiet || options.strict)
            err << "tfd: warning: " << who << ": " << m.text << "\n";
          break;
        case Severity::Info:
          if (!options.quiet) out << "info: node \"" << r.node << "\": " << m.text << "\n";
          break;
      }
    }
    failed += r.state == NodeState::Failed;
  }
  if (options.profile)
    for (const graph::NodeReport& r : result.reports)
      if (r.cookCalled) {
        char seconds[32];
        std::snprintf(seconds, sizeof seconds, "%.6f", r.seconds);
        out << "profile " << r.node << " " << r.type << " " << seconds << "\n";
      }
  if (options.files)
    for (const graph::WrittenFile& f : result.writtenFiles())
      out << "file " << f.node << " " << f.path.string() << "\n";
  if (result.cancelled) {
    err << "tfd: cancelled\n";
    return kNodeFailed;
  }
  const std::size_t upstream = result.count(NodeState::UpstreamFailed);
  if (failed > 0) {
    err << "tfd: " << failed << (failed == 1 ? " node" : " nodes") << " failed";
    if (upstream > 0) err << ", " << upstream << " not cooked because of that";
    err << "\n";
    return kNodeFailed;
  }
  if (options.strict && warnings > 0) {
    err << "tfd: --strict: " << warnings << (warnings == 1 ? " warning" : " warnings")
        << " treated as errors\n";
    return kNodeFailed;
  }
  if (!options.quiet) {
    std::size_t fromDisk = 0;
    for (const graph::NodeReport& r : result.reports) fromDisk += r.fromDisk;
    err << "tfd: cooked " << result.count(NodeState::Cooked) << " of " << result.reports.size()
        << " nodes (" << result.count(NodeState::Cached) << " cached";
    if (fromDisk > 0) err << ", " << fromDisk << " of them on disk";
    err << ")\n";
  }
  return kOk;
}

}  // namespace tfd::cli
