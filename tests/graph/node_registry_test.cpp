// Node-type declarations: ports and parameters with metadata, validated at registration.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "graph/errors.h"
#include "graph/node_registry.h"
#include "tests/support/graph_test_nodes.h"

namespace {
struct Impostor {};
}  // namespace
TFD_GRAPH_VALUE_TYPE(Impostor, "Number");  // same display name as tfd::test::Number

namespace tfd::graph {
namespace {

void noCook(CookContext&) {}

TEST(NodeRegistry, DeclarationsKeepOrderDefaultsAndMetadata) {
  NodeRegistry r;
  test::registerTestNodes(r);
  const NodeType& t = r.get("AllParams");
  const NodeDecl& d = t.decl();
  ASSERT_EQ(d.params().size(), 13u);
  EXPECT_EQ(d.params()[0].name, "flag");
  EXPECT_EQ(d.params()[0].defaultValue, ParamValue(true));
  EXPECT_EQ(d.findParam("count")->kind, ParamKind::Int);
  EXPECT_EQ(d.findParam("count")->hint, UiHint::Slider);
  EXPECT_EQ(d.findParam("primitive")->defaultValue, ParamValue(std::string("sphere")))
      << "an enum without byDefault defaults to its first choice";
  EXPECT_EQ(typeLabel(*d.findParam("primitive")), "enum");
  EXPECT_EQ(typeLabel(*d.findParam("mesh_file")), "input file");
  EXPECT_EQ(typeLabel(*d.findParam("output")), "output file");
  EXPECT_EQ(typeLabel(*d.findParam("components")), "double[6]");
  EXPECT_EQ(d.findParam("tolerance")->displayLabel(), "Tolerance");
  EXPECT_EQ(d.findParam("mesh_file")->displayLabel(), "Mesh file");
  EXPECT_EQ(describeExpected(*d.findParam("tolerance")), "a number in [1e-14, 0.01]");
  EXPECT_EQ(describeExpected(*d.findParam("primitive")), "one of \"sphere\", \"box\", \"torus\"");

  const NodeDecl& sum = r.get("Sum").decl();
  ASSERT_EQ(sum.inputs().size(), 1u);
  EXPECT_TRUE(sum.inputs()[0].optional);
  EXPECT_TRUE(sum.inputs()[0].multiple);
  EXPECT_EQ(sum.inputs()[0].type, valueType<test::Number>());
  EXPECT_EQ(sum.inputs()[0].type->name, "Number");
  EXPECT_TRUE(r.get("Sink").decl().isSink());
  EXPECT_FALSE(sum.isSink());
  EXPECT_EQ(r.get("Scale").version(), 2);
  EXPECT_NE(r.get("Scale").decl().migrationFrom(1), nullptr);
}

TEST(NodeRegistry, FixedSizeListDefaultsToZeros) {
  NodeRegistry r;
  r.add(
      "T", 1, [](NodeDecl& d) { d.param<std::vector<double>>("eig").size(3); }, noCook);
  EXPECT_EQ(r.get("T").decl().params()[0].defaultValue, ParamValue(std::vector<double>(3, 0.0)));
}

TEST(NodeRegistry, RefusesBadDeclarations) {
  NodeRegistry r;
  test::registerTestNodes(r);
  auto expectLogicError = [&](const char* type, const DeclareFn& declare, const char* needle) {
    try {
      r.add(type, 1, declare, noCook);
      ADD_FAILURE() << "accepted " << type;
    } catch (const std::logic_error& e) {
      EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find(type), std::string::npos) << e.what();
    }
  };
  expectLogicError(
      "Constant", [](NodeDecl&) {}, "registered twice");
  expectLogicError(
      "BadDefault", [](NodeDecl& d) { d.param<double>("r").byDefault(-1).min(0); },
      "parameter 'r': default value: expected a number >= 0, found -1");
  expectLogicError(
      "BadChoice",
      [](NodeDecl& d) {
        d.param<std::string>("k").byDefault("x").choices({"a", "b"});
      },
      "parameter 'k'");
  expectLogicError(
      "DupParam",
      [](NodeDecl& d) {
        d.param<int>("n");
        d.param<double>("n");
      },
      "duplicate parameter 'n'");
  expectLogicError(
      "DupPort",
      [](NodeDecl& d) {
        d.input<test::Number>("in");
        d.input<test::Number>("in");
      },
      "duplicate input 'in'");
  expectLogicError(
      "BadName", [](NodeDecl& d) { d.param<int>("has.dot"); }, "not an identifier");
  expectLogicError(
      "Bad.Type", [](NodeDecl&) {}, "identifier");
  expectLogicError(
      "ChoicesOnInt", [](NodeDecl& d) { d.param<int>("n").choices({"a"}); },
      "choices need a string");
  expectLogicError(
      "Impostor", [](NodeDecl& d) { d.output<Impostor>("out"); },
      "used by two different C++ types");
  expectLogicError(
      "OptionalOutput", [](NodeDecl& d) { d.output<test::Number>("o").optional(); },
      "cannot be optional");
  EXPECT_THROW(r.add(
                   "NoCook", 1, [](NodeDecl&) {}, CookFn{}),
               std::logic_error);
  EXPECT_THROW(r.add(
                   "BadMigration", 1, [](NodeDecl& d) { d.migration(1, [](Json&) {}); }, noCook),
               std::logic_error)
      << "a migration from typeVersion 1 needs typeVersion >= 2";
}

TEST(NodeRegistry, UnknownTypeSuggestsCloseName) {
  NodeRegistry r;
  test::registerTestNodes(r);
  try {
    r.get("Constnt");
    FAIL();
  } catch (const GraphError& e) {
    EXPECT_STREQ(e.what(), "unknown node type \"Constnt\" (did you mean \"Constant\"?)");
  }
  EXPECT_EQ(r.suggest("Zzzzzzzzzz"), "");
  std::vector<std::string> names;
  for (const NodeType* t : r.types()) names.push_back(t->name());
  EXPECT_TRUE(std::is_sorted(names.begin(), names.end()));
  EXPECT_EQ(names.size(), r.size());
}

TEST(ParamValues, CheckConvertsAndRefusesWithExpectedAndFound) {
  ParamDecl d;
  d.name = "factor";
  d.kind = ParamKind::Double;
  d.min = -100;
  d.max = 100;
  EXPECT_EQ(checkParamValue(d, std::int64_t{3}), ParamValue(3.0)) << "int converts to double";
  try {
    checkParamValue(d, 1000.0);
    FAIL();
  } catch (const GraphError& e) {
    EXPECT_STREQ(e.what(), "expected a number in [-100, 100], found 1000.0");
  }
  EXPECT_THROW(checkParamValue(d, std::string("x")), GraphError);
  EXPECT_THROW(checkParamValue(d, std::numeric_limits<double>::quiet_NaN()), GraphError);

  ParamDecl v;
  v.name = "p";
  v.kind = ParamKind::Vec3;
  EXPECT_EQ(paramFromJson(v, Json::parse("[1, 2, 3]")), ParamValue(Vec3Param{1, 2, 3}));
  EXPECT_THROW(paramFromJson(v, Json::parse("[1, 2]")), GraphError);
  EXPECT_THROW(paramFromJson(v, Json::parse("[1, 2, \"3\"]")), GraphError);

  ParamDecl i;
  i.name = "n";
  i.kind = ParamKind::Int;
  EXPECT_EQ(paramFromJson(i, Json::parse("1e6")), ParamValue(std::int64_t{1000000}));
  EXPECT_THROW(paramFromJson(i, Json::parse("1.5")), GraphError);
  EXPECT_THROW(paramFromJson(i, Json::parse("true")), GraphError);
  EXPECT_THROW(paramFromJson(i, Json::parse("18446744073709551615")), GraphError);

  ParamDecl list;
  list.name = "pts";
  list.kind = ParamKind::Vec3List;
  list.minSize = 2;
  EXPECT_THROW(paramFromJson(list, Json::parse("[[0,0,0]]")), GraphError);
  EXPECT_EQ(paramFromJson(list, Json::parse("[[0,0,0],[1,1,1]]")),
            ParamValue(std::vector<Vec3Param>{{0, 0, 0}, {1, 1, 1}}));
}

TEST(ParamValues, TextParsingPerKind) {
  auto decl = [](ParamKind k) {
    ParamDecl d;
    d.name = std::string(1, 'x');  // (assigning "x" trips GCC 12's -Wrestrict false positive)
    d.kind = k;
    return d;
  };
  EXPECT_EQ(paramFromText(decl(ParamKind::Bool), "on"), ParamValue(true));
  EXPECT_EQ(paramFromText(decl(ParamKind::Bool), "FALSE"), ParamValue(false));
  EXPECT_THROW(paramFromText(decl(ParamKind::Bool), "maybe"), GraphError);
  EXPECT_EQ(paramFromText(decl(ParamKind::Int), "42"), ParamValue(std::int64_t{42}));
  EXPECT_THROW(paramFromText(decl(ParamKind::Int), "4.2"), GraphError);
  EXPECT_EQ(paramFromText(decl(ParamKind::Double), "1e-6"), ParamValue(1e-6));
  EXPECT_EQ(paramFromText(decl(ParamKind::Double), "+.5"), ParamValue(0.5));
  EXPECT_THROW(paramFromText(decl(ParamKind::Double), "inf"), GraphError);
  EXPECT_THROW(paramFromText(decl(ParamKind::Double), "1x"), GraphError);
  EXPECT_EQ(paramFromText(decl(ParamKind::String), "a b=c"), ParamValue(std::string("a b=c")));
  EXPECT_EQ(paramFromText(decl(ParamKind::Vec3), "[0.1,0,0]"), ParamValue(Vec3Param{0.1, 0, 0}));
  EXPECT_EQ(paramFromText(decl(ParamKind::Vec3), "0.1, 0, 0"), ParamValue(Vec3Param{0.1, 0, 0}));
  EXPECT_EQ(paramFromText(decl(ParamKind::Vec3List), "[[1,2,3]]"),
            ParamValue(std::vector<Vec3Param>{{1, 2, 3}}));
  EXPECT_EQ(paramFromText(decl(ParamKind::DoubleList), "1,2"),
            ParamValue(std::vector<double>{1, 2}));
  try {
    paramFromText(decl(ParamKind::Vec3), "[0.1,0");
    FAIL();
  } catch (const GraphError& e) {
    EXPECT_NE(std::string(e.what()).find("not valid JSON"), std::string::npos) << e.what();
  }
}

TEST(ParamValues, JsonRoundTripAndFormatting) {
  const std::vector<ParamValue> values{true,
                                       std::int64_t{-7},
                                       0.1,
                                       std::string("a\"b"),
                                       Vec3Param{1, 2.5, -3},
                                       std::vector<Vec3Param>{{0, 0, 0}, {1, 1, 1}},
                                       std::vector<double>{1e-14, 2}};
  for (const ParamValue& v : values) {
    ParamDecl d;
    d.name = "x";
    d.kind = static_cast<ParamKind>(v.index());
    EXPECT_EQ(paramFromJson(d, paramToJson(v)), v) << formatParamValue(v);
  }
  EXPECT_EQ(formatParamValue(Vec3Param{0.1, 0, 0}), "[0.1, 0.0, 0.0]");
  EXPECT_EQ(formatParamValue(std::string("sphere")), "\"sphere\"");
}

TEST(CookContextApi, MisuseNamesThePortOrParameter) {
  NodeRegistry r;
  test::registerTestNodes(r);
  const NodeDecl& d = r.get("Scale").decl();
  std::vector<ParamValue> params;
  for (const ParamDecl& p : d.params()) params.push_back(p.defaultValue);
  CookContext c("scale1", d, params, {}, nullptr, nullptr);
  EXPECT_EQ(c.param<double>("factor"), 2.0);
  EXPECT_FALSE(c.cancelled());
  auto message = [](auto&& f) {
    try {
      f();
    } catch (const NodeError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(message([&] { c.param<int>("factor"); }), "parameter 'factor' is double, read as int");
  EXPECT_EQ(message([&] { c.param<double>("nope"); }), "node type Scale has no parameter 'nope'");
  EXPECT_EQ(message([&] { c.input<test::Number>("in"); }), "input 'in' is not connected");
  EXPECT_EQ(message([&] { c.input<test::Number>("nope"); }), "node type Scale has no input 'nope'");
  EXPECT_EQ(message([&] { c.setOutput("out", std::make_shared<const test::Text>()); }),
            "output 'out' is Number, set to Text");
  EXPECT_EQ(c.inputOr<test::Number>("in"), nullptr);
  EXPECT_EQ(message([&] { throw c.paramError("factor", "too big"); }),
            "parameter 'factor': too big");
}

}  // namespace
}  // namespace tfd::graph
