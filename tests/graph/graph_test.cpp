// The graph document: named nodes, validated parameters and links by port name.
#include <gtest/gtest.h>

#include "graph/errors.h"
#include "graph/graph.h"
#include "graph/topology.h"
#include "tests/support/graph_test_nodes.h"

namespace tfd::graph {
namespace {

class GraphDocument : public ::testing::Test {
 protected:
  void SetUp() override { test::registerTestNodes(registry); }
  std::string errorOf(const std::function<void()>& f) {
    try {
      f();
    } catch (const GraphError& e) {
      return e.what();
    }
    return "no error";
  }
  NodeRegistry registry;
};

TEST_F(GraphDocument, NodesGetUniqueValidNames) {
  Graph g(registry);
  EXPECT_EQ(g.addNode("Constant").name(), "constant1");
  EXPECT_EQ(g.addNode("Constant").name(), "constant2");
  EXPECT_EQ(g.addNode("Constant", "c").name(), "c");
  EXPECT_EQ(errorOf([&] { g.addNode("Constant", "c"); }), "a node named \"c\" already exists");
  EXPECT_NE(errorOf([&] { g.addNode("Constant", "a.b"); }).find("invalid node name \"a.b\""),
            std::string::npos);
  EXPECT_NE(errorOf([&] { g.addNode("Constnt"); }).find("did you mean \"Constant\""),
            std::string::npos);
  EXPECT_EQ(g.nodeCount(), 3u);
  EXPECT_EQ(g.nodes()[2].name(), "c");
}

TEST_F(GraphDocument, ParametersAreValidatedAndDefaultsAreNotStored) {
  Graph g(registry);
  g.addNode("Scale", "s");
  const auto rev = g.revision();
  g.setParam("s", "factor", 3.0);
  EXPECT_GT(g.revision(), rev);
  EXPECT_EQ(g.param("s", "factor"), ParamValue(3.0));
  EXPECT_TRUE(g.node("s").isSet(0));
  g.setParam("s", "factor", std::int64_t{2});  // the default, given as an int
  EXPECT_FALSE(g.node("s").isSet(0)) << "a value equal to the default is not an override";
  EXPECT_EQ(g.param("s", "factor"), ParamValue(2.0));
  EXPECT_EQ(errorOf([&] { g.setParam("s", "factor", 1000.0); }),
            "parameter \"factor\" of node \"s\" (Scale): expected a number in [-100, 100], found "
            "1000.0");
  EXPECT_EQ(errorOf([&] { g.setParam("s", "fail", 1.0); }),
            "parameter \"fail\" of node \"s\" (Scale): expected true or false, found 1.0");
  EXPECT_EQ(errorOf([&] { g.setParam("s", "nope", 1.0); }),
            "node \"s\" (Scale) has no parameter \"nope\" (parameters: factor, fail, warn)");
  EXPECT_EQ(errorOf([&] { g.setParam("zz", "factor", 1.0); }), "unknown node \"zz\"");
  g.setParam("s", "warn", true);
  g.resetParam("s", "warn");
  EXPECT_EQ(g.param("s", "warn"), ParamValue(false));
}

TEST_F(GraphDocument, LinksAreCheckedByNameTypeMultiplicityAndCycles) {
  Graph g(registry);
  g.addNode("Constant", "c1");
  g.addNode("Constant", "c2");
  g.addNode("Scale", "s1");
  g.addNode("Scale", "s2");
  g.addNode("Concat", "t");
  g.addNode("Sum", "sum");
  g.connect({"c1", "out"}, {"s1", "in"});
  g.connect({"s1", "out"}, {"s2", "in"});
  EXPECT_EQ(errorOf([&] {
              g.connect({"zz", "out"}, {"s1", "in"});
            }),
            "link source: unknown node \"zz\"");
  EXPECT_EQ(errorOf([&] {
              g.connect({"c1", "value"}, {"s1", "in"});
            }),
            "link source: node \"c1\" (Constant) has no output \"value\" (outputs: out)");
  EXPECT_EQ(errorOf([&] {
              g.connect({"s1", "in"}, {"s2", "in"});
            }),
            "link source: node \"s1\" (Scale) has no output \"in\" (outputs: out); \"in\" is an "
            "input");
  EXPECT_EQ(errorOf([&] {
              g.connect({"c1", "out"}, {"t", "texts"});
            }),
            "cannot link c1.out -> t.texts: output c1.out is Number but input t.texts takes Text");
  EXPECT_EQ(errorOf([&] {
              g.connect({"c2", "out"}, {"s1", "in"});
            }),
            "cannot link c2.out -> s1.in: input s1.in takes a single link and is already linked "
            "from c1.out");
  EXPECT_EQ(errorOf([&] {
              g.connect({"c1", "out"}, {"s1", "in"});
            }),
            "duplicate link c1.out -> s1.in");
  g.disconnect({"c1", "out"}, {"s1", "in"});
  EXPECT_EQ(errorOf([&] {
              g.connect({"s2", "out"}, {"s1", "in"});
            }),
            "link s2.out -> s1.in would create a cycle: s1 -> s2 -> s1");
  EXPECT_EQ(errorOf([&] {
              g.connect({"s1", "out"}, {"s1", "in"});
            }),
            "link s1.out -> s1.in would create a cycle: s1 -> s1");
  // A multiple input keeps its links in order.
  g.connect({"c2", "out"}, {"sum", "values"});
  g.connect({"c1", "out"}, {"sum", "values"});
  g.connect({"s2", "out"}, {"sum", "values"});
  auto into = g.linksInto("sum", "values");
  ASSERT_EQ(into.size(), 3u);
  EXPECT_EQ(into[0].from.node, "c2");
  EXPECT_EQ(into[1].from.node, "c1");
  EXPECT_EQ(into[2].from.node, "s2");
}

TEST_F(GraphDocument, RemoveAndRenameKeepLinksConsistent) {
  Graph g(registry);
  g.addNode("Constant", "c");
  g.addNode("Scale", "s");
  g.addNode("Sink", "out");
  g.connect({"c", "out"}, {"s", "in"});
  g.connect({"s", "out"}, {"out", "in"});
  g.renameNode("s", "scale");
  ASSERT_EQ(g.links().size(), 2u);
  EXPECT_EQ(g.links()[0].to.node, "scale");
  EXPECT_EQ(g.links()[1].from.node, "scale");
  EXPECT_EQ(g.findNode("s"), nullptr);
  g.removeNode("scale");
  EXPECT_TRUE(g.links().empty());
  EXPECT_EQ(g.nodeIndex("out"), 1);
}

TEST_F(GraphDocument, TopologyHelpers) {
  Graph g(registry);
  g.addNode("Sink", "sink");  // first in file order, but downstream
  g.addNode("Constant", "a");
  g.addNode("Constant", "b");
  g.addNode("Add", "add");
  g.addNode("Constant", "lonely");
  g.connect({"a", "out"}, {"add", "a"});
  g.connect({"b", "out"}, {"add", "b"});
  g.connect({"add", "sum"}, {"sink", "in"});
  const auto order = topologicalOrder(g);
  std::vector<std::string> names;
  for (int i : order) names.push_back(g.nodes()[i].name());
  EXPECT_EQ(names, (std::vector<std::string>{"a", "b", "add", "sink", "lonely"}));
  EXPECT_EQ(downstreamOf(g, "b"), (std::vector<std::string>{"sink", "add"}));
  EXPECT_EQ(leafNodes(g), (std::vector<int>{0, 4}));
  auto closure = upstreamClosure(g, {3});
  EXPECT_EQ(closure, (std::vector<bool>{false, true, true, true, false}));
}

TEST_F(GraphDocument, EndpointParsing) {
  EXPECT_EQ(Endpoint::parse("mesh1.mesh"), (Endpoint{"mesh1", "mesh"}));
  EXPECT_THROW(Endpoint::parse("mesh1"), GraphError);
  EXPECT_THROW(Endpoint::parse(".mesh"), GraphError);
  EXPECT_THROW(Endpoint::parse("mesh1."), GraphError);
}

}  // namespace
}  // namespace tfd::graph
