#pragma once
// What `tfd cook` prints after cooking, and its exit code:
//   stderr  tfd: node "propagate1" (Propagate): <error>           (always)
//           tfd: warning: node "x" (T): <warning>                 (not with --quiet, unless
//           --strict)
//   stdout  info: node "extract1": 3 curves (2 linear, 1 planar)  (not with --quiet)
//           profile <node-name> <type> <seconds>                  (with --profile; nodes that
//           cooked)
//           file <node-name> <path>                               (with --files; every file
//           this cook wrote, from CookResult::writtenFiles, in graph order)
// Exit 1 when a node failed, the cook was cancelled, or --strict and there were warnings.
#include <iosfwd>

#include "graph/evaluator.h"

namespace tfd::cli {

struct ReportOptions {
  bool quiet = false;
  bool strict = false;
  bool profile = false;
  bool files = false;
};

int printCookReport(const graph::CookResult& result, const ReportOptions& options,
                    std::ostream& out, std::ostream& err);

}  // namespace tfd::cli
