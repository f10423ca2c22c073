#include "ui/document/graph_document.h"

#include "graph/errors.h"
#include "graph/graph_file.h"
#include "nodes/display_values.h"
#include "ui/document/graph_clipboard.h"
#include "ui/document/node_ui.h"
#include "ui/document/snapshot_command.h"

namespace tfd::ui {

namespace {
enum MergeId { kMergeParam = 1 };

QString q(std::string_view s) { return QString::fromUtf8(s.data(), static_cast<int>(s.size())); }
}  // namespace

GraphDocument::GraphDocument(const graph::NodeRegistry& registry, QObject* parent)
    : QObject(parent), graph_(registry) {
  QObject::connect(&undo_, &QUndoStack::cleanChanged, this, &GraphDocument::fileStateChanged);
}

GraphDocument::~GraphDocument() {
  // The commands refer to this document: drop them before the members go.
  undo_.clear();
}

bool GraphDocument::refuse(const std::string& message) {
  lastError_ = message;
  emit editRefused(q(message));
  return false;
}

bool GraphDocument::edit(const QString& text, int flags,
                         const std::function<void(graph::Graph&)>& mutate, int mergeId,
                         std::string mergeKey) {
  graph::Graph after = graph_;
  try {
    mutate(after);
  } catch (const std::exception& e) {
    return refuse(e.what());
  }
  lastError_.clear();
  undo_.push(new SnapshotCommand(*this, text, graph_, std::move(after), flags, mergeId,
                                 std::move(mergeKey)));
  return true;
}

void GraphDocument::applySnapshot(const graph::Graph& graph, int flags) {
  emit aboutToChange(flags);
  std::filesystem::path source = graph_.sourcePath();
  graph_ = graph;
  graph_.setSourcePath(source);
  ++revision_;
  emit changed(flags);
}

std::string GraphDocument::addNode(std::string_view type, QPointF position, std::string_view name) {
  std::string added;
  const bool ok = edit("Add " + q(type), kStructureChanged, [&](graph::Graph& g) {
    added = g.addNode(type, name).name();
    g.setUi(added, withPosition(graph::Json::object(), position));
  });
  return ok ? added : std::string();
}

bool GraphDocument::remove(const std::vector<std::string>& nodes,
                           const std::vector<graph::Link>& links) {
  if (nodes.empty() && links.empty()) return false;
  const QString text = nodes.size() == 1 && links.empty() ? "Delete " + q(nodes.front())
                                                          : QString("Delete selection");
  return edit(text, kStructureChanged, [&](graph::Graph& g) {
    for (const graph::Link& l : links) g.disconnect(l.from, l.to);
    for (const std::string& n : nodes) g.removeNode(n);
  });
}

bool GraphDocument::connect(const graph::Endpoint& from, const graph::Endpoint& to) {
  return edit("Connect " + q(from.str()) + " to " + q(to.str()), kStructureChanged,
              [&](graph::Graph& g) {
                const graph::Node* n = g.findNode(to.node);
                const graph::PortDecl* in = n ? n->decl().findInput(to.port) : nullptr;
                if (in && !in->multiple)
                  for (const graph::Link& l : g.linksInto(to.node, to.port))
                    if (l.from != from) g.disconnect(l.from, l.to);
                g.connect(from, to);
              });
}

bool GraphDocument::disconnect(const graph::Endpoint& from, const graph::Endpoint& to) {
  return edit("Disconnect " + q(to.str()), kStructureChanged, [&](graph::Graph& g) {
    if (!g.disconnect(from, to))
      throw graph::GraphError("no link " + from.str() + " -> " + to.str());
  });
}

bool GraphDocument::relink(const graph::Link& old, const std::optional<graph::Endpoint>& newTo) {
  if (newTo && *newTo == old.to) return true;
  return edit(newTo ? "Reconnect " + q(old.from.str()) + " to " + q(newTo->str())
                    : "Disconnect " + q(old.to.str()),
              kStructureChanged, [&](graph::Graph& g) {
                if (!g.disconnect(old.from, old.to))
                  throw graph::GraphError("no link " + old.from.str() + " -> " + old.to.str());
                if (newTo) {
                  const graph::PortDecl* in = g.node(newTo->node).decl().findInput(newTo->port);
                  if (in && !in->multiple)
                    for (const graph::Link& l : g.linksInto(newTo->node, newTo->port))
                      g.disconnect(l.from, l.to);
                  g.connect(old.from, *newTo);
                }
              });
}

std::string GraphDocument::addNodeLinked(std::string_view type, QPointF position,
                                         const graph::Endpoint& other, bool otherIsOutput) {
  std::string added;
  const bool ok = edit("Add " + q(type), kStructureChanged, [&](graph::Graph& g) {
    added = g.addNode(type).name();
    g.setUi(added, withPosition(graph::Json::object(), position));
    const graph::Node& n = g.node(other.node);
    const graph::PortDecl* otherPort =
        otherIsOutput ? n.decl().findOutput(other.port) : n.decl().findInput(other.port);
    if (!otherPort) throw graph::GraphError("unknown port " + other.str());
    const auto& ports =
        otherIsOutput ? g.node(added).decl().inputs() : g.node(added).decl().outputs();
    for (const graph::PortDecl& p : ports) {
      if (p.type != otherPort->type) continue;
      const graph::Endpoint mine{added, p.name};
      if (otherIsOutput) {
        g.connect(other, mine);
      } else {
        if (!otherPort->multiple)
          for (const graph::Link& l : g.linksInto(other.node, other.port))
            g.disconnect(l.from, l.to);
        g.connect(mine, other);
      }
      return;
    }
    throw graph::GraphError(std::string(type) + " has no port of type " +
                            std::string(otherPort->type->name));
  });
  return ok ? added : std::string();
}

bool GraphDocument::canConnect(const graph::Endpoint& from, const graph::Endpoint& to) const {
  graph::Graph copy = graph_;
  try {
    const graph::PortDecl* in = copy.node(to.node).decl().findInput(to.port);
    if (in && !in->multiple)
      for (const graph::Link& l : copy.linksInto(to.node, to.port))
        if (l.from != from) copy.disconnect(l.from, l.to);
    copy.connect(from, to);
  } catch (const std::exception&) {
    return false;
  }
  return true;
}

bool GraphDocument::setParam(std::string_view node, std::string_view param, graph::ParamValue value,
                             bool continuous) {
  const std::string key = std::string(node) + "." + std::string(param);
  if (const graph::Node* n = graph_.findNode(node)) {
    const graph::ParamDecl* d = n->decl().findParam(param);
    if (d && n->param(param) == value) return true;  // nothing to do, no undo step
  }
  return edit(
      "Set " + q(key), kParamsChanged,
      [&](graph::Graph& g) { g.setParam(node, param, std::move(value)); },
      continuous ? kMergeParam : -1, key);
}

void GraphDocument::closeContinuousEdit() {
  if (undo_.index() <= 0) return;
  // The top command is ours (the stack holds only SnapshotCommands).
  auto* top = const_cast<QUndoCommand*>(undo_.command(undo_.index() - 1));
  if (auto* s = dynamic_cast<SnapshotCommand*>(top)) s->close();
}

bool GraphDocument::resetParam(std::string_view node, std::string_view param) {
  return edit("Reset " + q(node) + "." + q(param), kParamsChanged,
              [&](graph::Graph& g) { g.resetParam(node, param); });
}

bool GraphDocument::moveNodes(const std::map<std::string, QPointF>& positions) {
  if (positions.empty()) return false;
  return edit(positions.size() == 1 ? "Move " + q(positions.begin()->first) : QString("Move nodes"),
              kUiChanged, [&](graph::Graph& g) {
                for (const auto& [name, p] : positions)
                  g.setUi(name, withPosition(g.node(name).ui(), p));
              });
}

bool GraphDocument::renameNode(std::string_view from, std::string_view to) {
  if (from == to) return true;
  return edit("Rename " + q(from) + " to " + q(to), kStructureChanged,
              [&](graph::Graph& g) { g.renameNode(from, to); });
}

bool GraphDocument::setDisplayNode(std::string_view node) {
  return edit("Display " + q(node), kUiChanged, [&](graph::Graph& g) {
    if (!node.empty()) (void)g.node(node);
    for (const graph::Node& n : g.nodes()) {
      const bool want = n.name() == node;
      if (nodes::hasDisplayFlag(n) != want) g.setUi(n.name(), withDisplayFlag(n.ui(), want));
    }
  });
}

std::string GraphDocument::copyText(const std::vector<std::string>& nodes) const {
  return graph::graphToText(extractNodes(graph_, nodes));
}

std::vector<std::string> GraphDocument::paste(std::string_view text, QPointF offset) {
  std::vector<std::string> added;
  graph::Graph pasted(registry());
  try {
    pasted = parseClipboard(text, registry());
  } catch (const std::exception& e) {
    refuse(std::string("paste: ") + e.what());
    return {};
  }
  if (pasted.nodeCount() == 0) {
    refuse("paste: the text holds no nodes");
    return {};
  }
  const bool ok = edit("Paste", kStructureChanged,
                       [&](graph::Graph& g) { added = mergeNodes(g, pasted, offset); });
  return ok ? added : std::vector<std::string>{};
}

std::vector<std::string> GraphDocument::duplicate(const std::vector<std::string>& nodes,
                                                  QPointF offset) {
  if (nodes.empty()) return {};
  std::vector<std::string> added;
  const bool ok = edit("Duplicate", kStructureChanged, [&](graph::Graph& g) {
    added = mergeNodes(g, extractNodes(g, nodes), offset);
  });
  return ok ? added : std::vector<std::string>{};
}

void GraphDocument::reset(graph::Graph graph, const std::filesystem::path& path, bool dirty) {
  emit aboutToChange(kDocumentReplaced | kStructureChanged | kParamsChanged | kUiChanged);
  undo_.clear();
  graph_ = std::move(graph);
  path_ = path;
  if (!path.empty()) graph_.setSourcePath(path);
  ++revision_;
  if (dirty) undo_.resetClean();  // no state of the history is the saved one
  emit changed(kDocumentReplaced | kStructureChanged | kParamsChanged | kUiChanged);
  emit fileStateChanged();
}

void GraphDocument::newDocument() { reset(graph::Graph(registry()), {}, false); }

void GraphDocument::open(const std::filesystem::path& path) {
  reset(graph::loadGraphFile(path, registry()), path, false);
}

void GraphDocument::save(const std::filesystem::path& path) {
  graph::saveGraphFile(graph_, path);
  path_ = path;
  graph_.setSourcePath(path);
  undo_.setClean();
  emit fileStateChanged();
}

std::string GraphDocument::text() const { return graph::graphToText(graph_); }

}  // namespace tfd::ui
