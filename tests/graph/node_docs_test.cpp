// The node reference generated from the declarations.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "graph/node_docs.h"
#include "tests/support/graph_test_nodes.h"

namespace tfd::graph {
namespace {

TEST(NodeDocs, MarkdownListsEveryTypePortAndParameter) {
  NodeRegistry registry;
  test::registerTestNodes(registry);
  const std::string md = nodeTypesMarkdown(registry);
  EXPECT_EQ(md.rfind("# Node reference\n", 0), 0u);
  for (const NodeType* t : registry.types()) {
    EXPECT_NE(md.find("\n## " + t->name() + "\n"), std::string::npos) << t->name();
    for (const ParamDecl& p : t->decl().params())
      EXPECT_NE(md.find("| `" + p.name + "` | " + typeLabel(p) + " | `"), std::string::npos)
          << t->name() << "." << p.name;
    for (const PortDecl& p : t->decl().inputs())
      EXPECT_NE(md.find("| `" + p.name + "` | " + std::string(p.type->name)), std::string::npos);
  }
  EXPECT_NE(md.find("| `tolerance` | double | `1e-08` | [1e-14, 0.01] |"), std::string::npos);
  EXPECT_NE(md.find("| `primitive` | enum | `\"sphere\"` | sphere \\| box \\| torus |"),
            std::string::npos);
  EXPECT_EQ(md, nodeTypesMarkdown(registry)) << "deterministic";
  NodeRegistry empty;
  EXPECT_NE(nodeTypesMarkdown(empty).find("No node types"), std::string::npos);
}

TEST(NodeDocs, JsonDescribesDeclarationsForEditors) {
  NodeRegistry registry;
  test::registerTestNodes(registry);
  const Json j = Json::parse(nodeTypesJson(registry).dump());
  EXPECT_EQ(j["format"], "tfd-node-types");
  ASSERT_EQ(j["nodeTypes"].size(), registry.size());
  const Json* all = nullptr;
  for (const Json& t : j["nodeTypes"])
    if (t["type"] == "AllParams") all = &t;
  ASSERT_NE(all, nullptr);
  const Json& params = (*all)["params"];
  EXPECT_EQ(params[1]["name"], "count");
  EXPECT_EQ(params[1]["kind"], "int");
  EXPECT_EQ(params[1]["min"], 1.0);
  EXPECT_EQ(params[1]["hint"], "slider");
  EXPECT_EQ(params[6]["choices"], Json::parse(R"(["sphere", "box", "torus"])"));
  EXPECT_EQ(params[7]["hint"], "input-file");
  EXPECT_EQ(params[7]["fileFilter"], "*.obj *.ply");
  EXPECT_EQ(params[11]["size"], 6);
  EXPECT_EQ(params[11]["default"], Json::parse("[1.0, 2.0, 3.0, 0.0, 0.0, 0.0]"));
  const std::string text = nodeTypeText(registry.get("Sum"));
  EXPECT_NE(text.find("values : Number (optional, multiple)"), std::string::npos) << text;
  EXPECT_NE(nodeTypesText(registry).find("Constant"), std::string::npos);
}

}  // namespace
}  // namespace tfd::graph
