#include "tests/support/graph_test_nodes.h"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

#include <nlohmann/json.hpp>

#include "graph/cook_context.h"

namespace tfd::test {

using graph::CookContext;
using graph::NodeDecl;
using graph::Vec3Param;

void CookLog::record(const std::string& node) {
  std::lock_guard lock(mutex_);
  order_.push_back(node);
}
int CookLog::count(const std::string& node) const {
  std::lock_guard lock(mutex_);
  return static_cast<int>(std::count(order_.begin(), order_.end(), node));
}
int CookLog::total() const {
  std::lock_guard lock(mutex_);
  return static_cast<int>(order_.size());
}
std::vector<std::string> CookLog::nodes() const {
  std::lock_guard lock(mutex_);
  return order_;
}
void CookLog::clear() {
  std::lock_guard lock(mutex_);
  order_.clear();
  sinks_.clear();
}
void CookLog::sink(const std::string& node, double value) {
  std::lock_guard lock(mutex_);
  sinks_[node] = value;
}
std::map<std::string, double> CookLog::sinks() const {
  std::lock_guard lock(mutex_);
  return sinks_;
}
CookLog& cookLog() {
  static CookLog log;
  return log;
}
RendezvousState& rendezvous() {
  static RendezvousState state;
  return state;
}

namespace {

std::shared_ptr<const Number> number(double v) { return std::make_shared<const Number>(Number{v}); }

void declareConstant(NodeDecl& d) {
  d.doc("A constant number.").category("Test");
  d.output<Number>("out").doc("The value.");
  d.param<double>("value").byDefault(1.0).doc("The number.");
}
void cookConstant(CookContext& c) {
  cookLog().record(c.nodeName());
  c.setOutput("out", number(c.param<double>("value")));
}

void declareAdd(NodeDecl& d) {
  d.doc("a + b + bias.").category("Test");
  d.input<Number>("a");
  d.input<Number>("b");
  d.output<Number>("sum");
  d.param<double>("bias").byDefault(0.0);
}
void cookAdd(CookContext& c) {
  cookLog().record(c.nodeName());
  c.setOutput("sum", number(c.input<Number>("a")->value + c.input<Number>("b")->value +
                            c.param<double>("bias")));
}

void declareSum(NodeDecl& d) {
  d.doc("Sum of every linked value; the first value is weighted 1, the second 10, ...");
  d.input<Number>("values").optional().multiple();
  d.output<Number>("out");
}
void cookSum(CookContext& c) {
  cookLog().record(c.nodeName());
  double total = 0, weight = 1;
  for (const auto& v : c.inputs<Number>("values")) {
    total += weight * v->value;
    weight *= 10;
  }
  c.info(std::to_string(c.inputs<Number>("values").size()) + " values");
  c.setOutput("out", number(total));
}

void declareScale(NodeDecl& d) {
  d.doc("in * factor; can fail or warn on request.");
  d.input<Number>("in");
  d.output<Number>("out");
  d.param<double>("factor").byDefault(2.0).min(-100).max(100);
  d.param<bool>("fail").byDefault(false);
  d.param<bool>("warn").byDefault(false);
  // typeVersion 1 called the factor "multiplier".
  d.migration(1, [](graph::Json& params) {
    if (params.contains("multiplier")) {
      params["factor"] = params["multiplier"];
      params.erase("multiplier");
    }
  });
}
void cookScale(CookContext& c) {
  cookLog().record(c.nodeName());
  if (c.param<bool>("fail")) throw graph::NodeError("scale failed on purpose");
  if (c.param<bool>("warn")) c.warning("scaled with a warning");
  c.setOutput("out", number(c.input<Number>("in")->value * c.param<double>("factor")));
}

void declareSink(NodeDecl& d) {
  d.doc("Records its input (an exporter stand-in).");
  d.input<Number>("in");
  d.param<std::string>("path").byDefault("out.txt").outputFile("*.txt").doc("Where it would go.");
}
void cookSink(CookContext& c) {
  cookLog().record(c.nodeName());
  cookLog().sink(c.nodeName(), c.input<Number>("in")->value);
  c.info("wrote " + c.path("path").string());
}

void declareWriteFile(NodeDecl& d) {
  d.doc("Writes its input as text (a real exporter stand-in).").sideEffect();
  d.input<Number>("in");
  d.param<std::string>("path").byDefault("out.txt").outputFile("*.txt");
  d.param<int>("copies").byDefault(1).min(1).max(9);
}
void cookWriteFile(CookContext& c) {
  cookLog().record(c.nodeName());
  const std::filesystem::path path = c.path("path");
  for (int k = 0; k < c.param<int>("copies"); ++k) {
    const std::filesystem::path file =
        k == 0 ? path : std::filesystem::path(path.string() + "." + std::to_string(k));
    std::ofstream out(file, std::ios::binary);
    out << c.input<Number>("in")->value << "\n";
    if (!out.flush()) throw graph::NodeError("cannot write " + file.string());
    out.close();
    c.wroteFile(file);
  }
}

void declareWait(NodeDecl& d) {
  d.doc("Passes its input on after a while, checking for cancellation.");
  d.input<Number>("in").optional();
  d.output<Number>("out");
  d.param<double>("seconds").byDefault(0.05).min(0).max(60);
  d.param<bool>("ignore_cancel").byDefault(false);
}
void cookWait(CookContext& c) {
  cookLog().record(c.nodeName());
  const auto end =
      std::chrono::steady_clock::now() + std::chrono::duration<double>(c.param<double>("seconds"));
  int step = 0;
  while (std::chrono::steady_clock::now() < end) {
    if (!c.param<bool>("ignore_cancel")) c.throwIfCancelled();
    c.progress(0.5, "waiting " + std::to_string(step++));
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  auto in = c.inputOr<Number>("in", number(0));
  c.setOutput("out", number(in->value + 1));
}

void declareRendezvous(NodeDecl& d) {
  d.doc("Waits (up to `timeout` seconds) until a second Rendezvous node has started.");
  d.output<Number>("out");
  d.param<double>("value").byDefault(0.0);
  d.param<double>("timeout").byDefault(10.0).min(0);
}
void cookRendezvous(CookContext& c) {
  cookLog().record(c.nodeName());
  RendezvousState& s = rendezvous();
  int now = ++s.inside;
  for (int peak = s.peak; now > peak && !s.peak.compare_exchange_weak(peak, now);) {
  }
  ++s.arrived;
  const auto end =
      std::chrono::steady_clock::now() + std::chrono::duration<double>(c.param<double>("timeout"));
  while (s.arrived < 2 && std::chrono::steady_clock::now() < end)
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  --s.inside;
  c.setOutput("out", number(c.param<double>("value")));
}

void declareBlob(NodeDecl& d) {
  d.doc("A value of the given size.");
  d.output<Blob>("out");
  d.param<int>("kilobytes").byDefault(1).min(0).max(1 << 20);
  d.param<int>("seed").byDefault(0);
}
void cookBlob(CookContext& c) {
  cookLog().record(c.nodeName());
  auto b = std::make_shared<Blob>();
  b->bytes.assign(static_cast<std::size_t>(c.param<int>("kilobytes")) * 1024,
                  static_cast<char>(c.param<int>("seed")));
  c.setOutput("out", b);
}

void declareConcat(NodeDecl& d) {
  d.doc("Joins texts | with a separator.");
  d.input<Text>("texts").multiple().doc("Joined in link order.");
  d.output<Text>("out");
  d.param<std::string>("separator").byDefault(",");
}
void cookConcat(CookContext& c) {
  cookLog().record(c.nodeName());
  std::string out;
  for (const auto& t : c.inputs<Text>("texts"))
    out += (out.empty() ? "" : c.param<std::string>("separator")) + t->value;
  c.setOutput("out", std::make_shared<const Text>(Text{out}));
}

void declareReadText(NodeDecl& d) {
  d.doc("Reads a text file.");
  d.output<Text>("out");
  d.param<std::string>("path").inputFile("*.txt");
}
void cookReadText(CookContext& c) {
  cookLog().record(c.nodeName());
  std::ifstream in(c.path("path"));
  if (!in) throw c.paramError("path", "cannot open " + c.path("path").string());
  std::stringstream s;
  s << in.rdbuf();
  c.setOutput("out", std::make_shared<const Text>(Text{s.str()}));
}

void declareAllParams(NodeDecl& d) {
  d.doc("Every parameter kind, formatted into a text.");
  d.output<Text>("out");
  d.param<bool>("flag").byDefault(true).doc("A bool.");
  d.param<int>("count").byDefault(3).min(1).max(10).hint(graph::UiHint::Slider);
  d.param<std::int64_t>("big").byDefault(1).min(-5);
  d.param<double>("tolerance").byDefault(1e-8).min(1e-14).max(1e-2).hint(graph::UiHint::LogSlider);
  d.param<double>("angle").byDefault(0).hint(graph::UiHint::Angle);
  d.param<std::string>("name").byDefault("x");
  d.param<std::string>("primitive").choices({"sphere", "box", "torus"});
  d.param<std::string>("mesh_file").inputFile("*.obj *.ply");
  d.param<std::string>("output").byDefault("result.vtu").outputFile("*.vtu");
  d.param<Vec3Param>("position").byDefault({0.1, 0, 0}).hint(graph::UiHint::Position);
  d.param<std::vector<Vec3Param>>("points").minSize(0);
  d.param<std::vector<double>>("components").size(6).byDefault({1, 2, 3, 0, 0, 0});
  d.param<std::vector<double>>("weights").range(0, 1);
}
void cookAllParams(CookContext& c) {
  cookLog().record(c.nodeName());
  std::string out;
  for (const auto& p : c.decl().params()) {
    out += p.name + "=";
    switch (p.kind) {
      case graph::ParamKind::Bool:
        out += c.param<bool>(p.name) ? "true" : "false";
        break;
      case graph::ParamKind::Int:
        out += std::to_string(c.param<std::int64_t>(p.name));
        break;
      case graph::ParamKind::Double:
        out += std::to_string(c.param<double>(p.name));
        break;
      case graph::ParamKind::String:
        out += c.param<std::string>(p.name);
        break;
      case graph::ParamKind::Vec3:
        out += std::to_string(c.param<Vec3Param>(p.name)[0]);
        break;
      case graph::ParamKind::Vec3List:
        out += std::to_string(c.param<std::vector<Vec3Param>>(p.name).size());
        break;
      case graph::ParamKind::DoubleList:
        out += std::to_string(c.param<std::vector<double>>(p.name).size());
        break;
      case graph::ParamKind::StringList:
        for (const auto& s : c.param<std::vector<std::string>>(p.name)) out += s + ",";
        break;
    }
    out += ";";
  }
  c.setOutput("out", std::make_shared<const Text>(Text{out}));
}

void declareLazy(NodeDecl& d) {
  d.doc("Forgets to set its output.");
  d.input<Number>("in");
  d.output<Number>("out");
}
void cookLazy(CookContext& c) { cookLog().record(c.nodeName()); }

}  // namespace

void registerTestNodes(graph::NodeRegistry& r) {
  r.add("Constant", 1, declareConstant, cookConstant);
  r.add("Add", 1, declareAdd, cookAdd);
  r.add("Sum", 1, declareSum, cookSum);
  r.add("Scale", 2, declareScale, cookScale);
  r.add("Sink", 1, declareSink, cookSink);
  r.add("WriteFile", 1, declareWriteFile, cookWriteFile);
  r.add("Wait", 1, declareWait, cookWait);
  r.add("Rendezvous", 1, declareRendezvous, cookRendezvous);
  r.add("Blob", 1, declareBlob, cookBlob);
  r.add("Concat", 1, declareConcat, cookConcat);
  r.add("ReadText", 1, declareReadText, cookReadText);
  r.add("AllParams", 1, declareAllParams, cookAllParams);
  r.add("Lazy", 1, declareLazy, cookLazy);
}

}  // namespace tfd::test
