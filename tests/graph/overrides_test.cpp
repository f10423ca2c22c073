// `--set NODE.PARAM=VALUE` parsing and application.
#include <gtest/gtest.h>

#include "graph/errors.h"
#include "graph/overrides.h"
#include "tests/support/graph_test_nodes.h"

namespace tfd::graph {
namespace {

class Overrides : public ::testing::Test {
 protected:
  void SetUp() override {
    test::registerTestNodes(registry);
    graph.addNode("AllParams", "p1");
  }
  std::string errorOf(const std::string& text) {
    try {
      applyOverride(graph, parseOverride(text));
    } catch (const GraphError& e) {
      return e.what();
    }
    return "no error";
  }
  NodeRegistry registry;
  Graph graph{registry};
};

TEST_F(Overrides, ParsesNodeParamAndValue) {
  const ParamOverride o = parseOverride("p1.name=a.b=c");
  EXPECT_EQ(o.node, "p1");
  EXPECT_EQ(o.param, "name");
  EXPECT_EQ(o.value, "a.b=c");
  EXPECT_EQ(parseOverride("p1.name=").value, "");
  EXPECT_THROW(parseOverride("p1name=3"), GraphError);
  EXPECT_THROW(parseOverride("p1.name"), GraphError);
  EXPECT_THROW(parseOverride(".name=3"), GraphError);
  EXPECT_THROW(parseOverride("p1.=3"), GraphError);
}

TEST_F(Overrides, ValuesParsePerParameterKind) {
  for (const char* text :
       {"p1.flag=off", "p1.count=9", "p1.big=-5", "p1.tolerance=1e-6", "p1.name=hello world",
        "p1.primitive=box", "p1.mesh_file=../meshes/a.obj", "p1.position=[0.1,0,0]",
        "p1.points=[[0,0,0],[1,2,3]]", "p1.components=1,2,3,4,5,6", "p1.weights=[0.5]"})
    EXPECT_EQ(errorOf(text), "no error") << text;
  EXPECT_EQ(graph.param("p1", "flag"), ParamValue(false));
  EXPECT_EQ(graph.param("p1", "count"), ParamValue(std::int64_t{9}));
  EXPECT_EQ(graph.param("p1", "big"), ParamValue(std::int64_t{-5}));
  EXPECT_EQ(graph.param("p1", "tolerance"), ParamValue(1e-6));
  EXPECT_EQ(graph.param("p1", "name"), ParamValue(std::string("hello world")));
  EXPECT_EQ(graph.param("p1", "primitive"), ParamValue(std::string("box")));
  EXPECT_EQ(graph.param("p1", "position"), ParamValue(Vec3Param{0.1, 0, 0}));
  EXPECT_EQ(graph.param("p1", "points"), ParamValue(std::vector<Vec3Param>{{0, 0, 0}, {1, 2, 3}}));
  EXPECT_EQ(graph.param("p1", "components"), ParamValue(std::vector<double>{1, 2, 3, 4, 5, 6}));
}

TEST_F(Overrides, ErrorsNameTheOverrideNodeAndParameter) {
  EXPECT_EQ(errorOf("p1.count=11"),
            "--set p1.count=11: parameter \"count\" of node \"p1\" (AllParams): expected an "
            "integer in [1, 10], found 11");
  EXPECT_EQ(errorOf("p1.primitive=cone"),
            "--set p1.primitive=cone: parameter \"primitive\" of node \"p1\" (AllParams): "
            "expected one of \"sphere\", \"box\", \"torus\", found \"cone\"");
  EXPECT_EQ(errorOf("p1.flag=maybe"),
            "--set p1.flag=maybe: parameter \"flag\" of node \"p1\" (AllParams): expected true "
            "or false, found \"maybe\"");
  EXPECT_EQ(errorOf("p2.count=1"), "--set p2.count=1: unknown node \"p2\"");
  EXPECT_NE(errorOf("p1.cuont=1")
                .find("node \"p1\" (AllParams) has no parameter \"cuont\" "
                      "(parameters: flag, count,"),
            std::string::npos);
  EXPECT_NE(errorOf("p1.position=[1,2]").find("expected an array of 3 numbers"), std::string::npos);
}

}  // namespace
}  // namespace tfd::graph
