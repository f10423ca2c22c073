// Graph files: canonical saving, format and typeVersion migrations, and load errors that point
// at the JSON place.
#include <gtest/gtest.h>

#include <unistd.h>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "graph/errors.h"
#include "graph/format_migrations.h"
#include "graph/graph_file.h"
#include "graph/json_text.h"
#include "graph/version.h"
#include "tests/support/graph_test_nodes.h"

namespace tfd::graph {
namespace {

namespace fs = std::filesystem;
const fs::path kFixtures = fs::path(TFD_TEST_DATA_DIR) / "graphs";

class GraphFile : public ::testing::Test {
 protected:
  void SetUp() override { test::registerTestNodes(registry); }

  Graph everyKind() {
    Graph g(registry);
    g.addNode("AllParams", "all");
    g.setParam("all", "flag", false);
    g.setParam("all", "count", std::int64_t{7});
    g.setParam("all", "tolerance", 1e-10);
    g.setParam("all", "angle", 0.1);
    g.setParam("all", "name", std::string("quote \" and unicode \xC3\xA9"));
    g.setParam("all", "primitive", std::string("torus"));
    g.setParam("all", "mesh_file", std::string("meshes/bunny.obj"));
    g.setParam("all", "position", Vec3Param{0.1, -2.5, 1e-7});
    g.setParam("all", "points", std::vector<Vec3Param>{{0, 0, 0}, {1, 0.5, 0.25}});
    g.setParam("all", "components", std::vector<double>{1, 0, -1, 0.3333333333333333, 0, 0});
    g.setParam("all", "weights", std::vector<double>{0.25, 0.75});
    g.setUi("all", Json::parse(R"({"position": [10.5, -3], "collapsed": true})"));
    g.addNode("Constant", "c1");
    g.setParam("c1", "value", 3.0);
    g.addNode("Constant", "c2");
    g.addNode("Sum", "sum");
    g.connect({"c2", "out"}, {"sum", "values"});
    g.connect({"c1", "out"}, {"sum", "values"});
    g.addNode("Sink", "sink");
    g.connect({"sum", "out"}, {"sink", "in"});
    return g;
  }

  std::string read(const fs::path& p) { return readTextFile(p); }

  /// Committed fixtures name the tool version that wrote them; compare without it.
  static std::string withoutGenerator(std::string text) {
    const std::string current = std::string("\"generator\": \"tfd ") + toolVersion() + "\"";
    if (auto pos = text.find(current); pos != std::string::npos)
      text.replace(pos, current.size(), "\"generator\": \"tfd <version>\"");
    return text;
  }

  /// Parses `text` and returns the LoadError (fails the test when it loads).
  LoadError loadError(const std::string& text) {
    try {
      parseGraph(text, registry, "test.tfd.json");
    } catch (const LoadError& e) {
      return e;
    }
    ADD_FAILURE() << "loaded without error:\n" << text;
    return LoadError("", "", "");
  }

  NodeRegistry registry;
};

TEST_F(GraphFile, SaveLoadSaveIsByteIdentical) {
  const std::string first = graphToText(everyKind());
  const Graph loaded = parseGraph(first, registry, "mem");
  const std::string second = graphToText(loaded);
  EXPECT_EQ(first, second);
  EXPECT_EQ(loaded.param("all", "name"), ParamValue(std::string("quote \" and unicode \xC3\xA9")));
  EXPECT_EQ(loaded.param("all", "components"),
            ParamValue(std::vector<double>{1, 0, -1, 0.3333333333333333, 0, 0}));
  EXPECT_EQ(loaded.linksInto("sum", "values")[0].from.node, "c2") << "link order kept";
  EXPECT_EQ(loaded.node("all").ui()["collapsed"], true);
}

TEST_F(GraphFile, CommittedCanonicalFixtureRoundTrips) {
  const std::string text = withoutGenerator(read(kFixtures / "all_kinds.tfd.json"));
  EXPECT_EQ(withoutGenerator(graphToText(parseGraph(text, registry, "all_kinds"))), text);
  EXPECT_EQ(withoutGenerator(graphToText(everyKind())), text)
      << "the canonical form changed; if on purpose, bump the format version";
}

TEST_F(GraphFile, OnlyNonDefaultParametersAreStoredInDeclarationOrder) {
  Graph g(registry);
  g.addNode("Scale", "s");
  g.setParam("s", "warn", true);
  g.setParam("s", "factor", 3.0);
  g.setParam("s", "fail", false);  // the default
  const Json j = graphToJson(g);
  EXPECT_EQ(
      compactJson(j["nodes"]["s"]),
      R"({"type": "Scale", "typeVersion": 2, "params": {"factor": 3.0, "warn": true}, "ui": {}})");
  EXPECT_EQ(j["generator"], std::string("tfd ") + toolVersion());
  EXPECT_EQ(j["formatVersion"], kGraphFormatVersion);
  std::vector<std::string> keys;
  for (const auto& [k, v] : j.items()) keys.push_back(k);
  EXPECT_EQ(keys,
            (std::vector<std::string>{"format", "formatVersion", "generator", "nodes", "links"}));
}

TEST_F(GraphFile, Version1FixtureIsMigrated) {
  const Graph g = loadGraphFile(kFixtures / "v1_basic.tfd.json", registry);
  EXPECT_EQ(g.loadedFormatVersion(), 1);
  EXPECT_EQ(g.node("c1").ui(), Json::parse(R"({"position": [0, 0]})"));
  EXPECT_EQ(g.node("sink1").ui(), Json::parse(R"({"position": [600, 60]})"));
  EXPECT_EQ(g.param("scale1", "factor"), ParamValue(4.0)) << "Scale typeVersion 1 -> 2 migration";
  EXPECT_EQ(g.param("c1", "value"), ParamValue(2.5));
  EXPECT_EQ(g.linksInto("sum1", "values").size(), 2u);
  EXPECT_EQ(withoutGenerator(graphToText(g)),
            withoutGenerator(read(kFixtures / "v1_basic.upgraded.tfd.json")));
  // The upgraded file is a current-version file that loads to the same text.
  const Graph again = loadGraphFile(kFixtures / "v1_basic.upgraded.tfd.json", registry);
  EXPECT_EQ(again.loadedFormatVersion(), kGraphFormatVersion);
  EXPECT_EQ(graphToText(again), graphToText(g));
}

TEST_F(GraphFile, MigrationIsPureJson) {
  const Json v1 = parseJsonText(read(kFixtures / "v1_basic.tfd.json"), "v1");
  int version = 0;
  const Json v2 = migrateGraphDocument(v1, "v1", &version);
  EXPECT_EQ(version, 1);
  EXPECT_EQ(v2["formatVersion"], 2);
  EXPECT_FALSE(v2.contains("layout"));
  EXPECT_EQ(v2["nodes"]["scale1"]["ui"]["position"], Json::parse("[200, 0]"));
  EXPECT_EQ(v2["nodes"]["scale1"]["params"]["multiplier"], 4) << "node params untouched here";
  EXPECT_EQ(migrateGraphDocument(v2, "v2"), v2) << "current version passes through";
}

struct BadFile {
  const char* name;
  std::string text;
  const char* pointer;
  const char* message;  // a substring of the message
};

std::string doc(const std::string& nodes, const std::string& links = "[]", int version = 2) {
  return R"({"format": "tfd-graph", "formatVersion": )" + std::to_string(version) +
         R"(, "nodes": {)" + nodes + R"(}, "links": )" + links + "}";
}

const std::string kC = R"("c": {"type": "Constant", "typeVersion": 1})";
const std::string kS = R"("s": {"type": "Scale", "typeVersion": 2})";
const std::string kT = R"("t": {"type": "Concat", "typeVersion": 1})";

TEST_F(GraphFile, LoadErrorsPointAtThePlace) {
  const std::vector<BadFile> cases = {
      {"syntax", "{\"format\": \"tfd-graph\",\n \"nodes\": {,}}", "",
       "invalid JSON: parse error at line 2"},
      {"top level array", "[1, 2]", "",
       "expected a JSON object with \"format\": \"tfd-graph\", found [1, 2]"},
      {"missing format", R"({"formatVersion": 2, "nodes": {}, "links": []})", "/format", "missing"},
      {"wrong format", R"({"format": "blender", "formatVersion": 2})", "/format",
       "expected \"tfd-graph\", found \"blender\""},
      {"missing version", R"({"format": "tfd-graph", "nodes": {}, "links": []})", "/formatVersion",
       "missing; a graph file must state its format version"},
      {"string version", R"({"format": "tfd-graph", "formatVersion": "2"})", "/formatVersion",
       "expected an integer, found \"2\""},
      {"newer version", doc("", "[]", 3), "/formatVersion",
       "format version 3 is newer than this tfd ("},
      {"version zero", doc("", "[]", 0), "/formatVersion",
       "expected a format version from 1 to 2, found 0"},
      {"unknown top key", R"({"format": "tfd-graph", "formatVersion": 2, "nodez": {}})", "/nodez",
       "unknown key \"nodez\""},
      {"missing nodes", R"({"format": "tfd-graph", "formatVersion": 2, "links": []})", "/nodes",
       "missing"},
      {"missing links", R"({"format": "tfd-graph", "formatVersion": 2, "nodes": {}})", "/links",
       "missing"},
      {"duplicate node", doc(kC + ", " + kC), "/nodes/c", "duplicate key \"c\""},
      {"unknown type", doc(R"("w": {"type": "Constnt", "typeVersion": 1})"), "/nodes/w/type",
       "unknown node type \"Constnt\" (did you mean \"Constant\"?)"},
      {"missing type", doc(R"("w": {"typeVersion": 1})"), "/nodes/w", "missing \"type\""},
      {"missing typeVersion", doc(R"("w": {"type": "Constant"})"), "/nodes/w",
       "missing \"typeVersion\""},
      {"newer typeVersion", doc(R"("w": {"type": "Constant", "typeVersion": 2})"),
       "/nodes/w/typeVersion", "typeVersion 2 of node type Constant is newer than this tfd ("},
      {"bad node name", doc(R"("a.b": {"type": "Constant", "typeVersion": 1})"), "/nodes/a.b",
       "invalid node name \"a.b\""},
      {"slash in name", doc(R"("a/b": {"type": "Constant", "typeVersion": 1})"), "/nodes/a~1b",
       "invalid node name"},
      {"unknown node key", doc(R"("c": {"type": "Constant", "typeVersion": 1, "parms": {}})"),
       "/nodes/c/parms", "unknown key \"parms\" (expected type, typeVersion, params, ui)"},
      {"unknown param",
       doc(R"("c": {"type": "Constant", "typeVersion": 1, "params": {"valu": 1}})"),
       "/nodes/c/params/valu",
       "unknown parameter \"valu\" of node type Constant (parameters: value)"},
      {"param type",
       doc(R"("c": {"type": "Constant", "typeVersion": 1, "params": {"value": "x"}})"),
       "/nodes/c/params/value", "expected a number, found \"x\""},
      {"param range",
       doc(R"("s": {"type": "Scale", "typeVersion": 2, "params": {"factor": 1000}})"),
       "/nodes/s/params/factor", "expected a number in [-100, 100], found 1000"},
      {"param choice",
       doc(R"("a": {"type": "AllParams", "typeVersion": 1, "params": {"primitive": "cone"}})"),
       "/nodes/a/params/primitive",
       "expected one of \"sphere\", \"box\", \"torus\", found \"cone\""},
      {"vec3 size",
       doc(R"("a": {"type": "AllParams", "typeVersion": 1, "params": {"position": [1, 2]}})"),
       "/nodes/a/params/position", "expected an array of 3 numbers [x, y, z], found [1, 2]"},
      {"list size",
       doc(R"("a": {"type": "AllParams", "typeVersion": 1, "params": {"components": [1]}})"),
       "/nodes/a/params/components", "expected an array of 6 numbers, found [1]"},
      {"int param",
       doc(R"("a": {"type": "AllParams", "typeVersion": 1, "params": {"count": 2.5}})"),
       "/nodes/a/params/count", "expected an integer in [1, 10], found 2.5"},
      {"ui not object", doc(R"("c": {"type": "Constant", "typeVersion": 1, "ui": [1]})"),
       "/nodes/c/ui", "expected an object"},
      {"link unknown node", doc(kC, R"([{"from": "c.out", "to": "zz.in"}])"), "/links/0/to",
       "unknown node \"zz\""},
      {"link missing port", doc(kC + ", " + kS, R"([{"from": "c.outt", "to": "s.in"}])"),
       "/links/0/from", "node \"c\" (Constant) has no output \"outt\" (outputs: out)"},
      {"link from an input", doc(kS + ", " + kC, R"([{"from": "s.in", "to": "c.out"}])"),
       "/links/0/from", "\"in\" is an input"},
      {"link without dot", doc(kC, R"([{"from": "c.out", "to": "s"}])"), "/links/0/to",
       "expected \"node.port\", found \"s\""},
      {"link missing to", doc(kC, R"([{"from": "c.out"}])"), "/links/0", "missing \"to\""},
      {"link unknown key", doc(kC, R"([{"from": "c.out", "to": "s.in", "via": 1}])"),
       "/links/0/via", "unknown key"},
      {"link type mismatch", doc(kC + ", " + kT, R"([{"from": "c.out", "to": "t.texts"}])"),
       "/links/0", "output c.out is Number but input t.texts takes Text"},
      {"two links into single input",
       doc(kC + R"(, "d": {"type": "Constant", "typeVersion": 1}, )" + kS,
           R"([{"from": "c.out", "to": "s.in"}, {"from": "d.out", "to": "s.in"}])"),
       "/links/1", "input s.in takes a single link and is already linked from c.out"},
      {"cycle",
       doc(kS +
               R"(, "s2": {"type": "Scale", "typeVersion": 2}, "s3": {"type": "Scale", "typeVersion": 2})",
           R"([{"from": "s.out", "to": "s2.in"}, {"from": "s2.out", "to": "s3.in"}, {"from": "s3.out", "to": "s.in"}])"),
       "/links/2", "would create a cycle: s -> s2 -> s3 -> s"},
      {"duplicate key in link", doc(kC, R"([{"from": "c.out", "from": "c.out"}])"), "/links/0/from",
       "duplicate key"},
      {"v1 layout of unknown node", doc(kC, "[]", 1).insert(1, R"("layout": {"zz": [0, 0]}, )"),
       "/layout/zz", "layout of an unknown node \"zz\""},
      {"v1 with node ui", doc(R"("c": {"type": "Constant", "typeVersion": 1, "ui": {}})", "[]", 1),
       "/nodes/c/ui", "unexpected key \"ui\" in a format version 1 file"},
  };
  for (const BadFile& c : cases) {
    SCOPED_TRACE(c.name);
    const LoadError e = loadError(c.text);
    EXPECT_EQ(e.pointer(), c.pointer) << e.what();
    EXPECT_NE(e.message().find(c.message), std::string::npos) << e.what();
    EXPECT_EQ(e.file(), "test.tfd.json");
    EXPECT_EQ(std::string(e.what()).rfind("test.tfd.json", 0), 0u) << "what() starts with the file";
  }
}

TEST_F(GraphFile, TypeMigrationFailuresAndGapsPointAtTheNode) {
  NodeRegistry r;
  r.add(
      "Old", 3,
      [](NodeDecl& d) {
        d.param<double>("x");
        d.migration(2, [](Json& p) {
          if (p.contains("bad")) throw std::runtime_error("cannot convert \"bad\"");
          p["x"] = 1.0;
        });
      },
      [](CookContext&) {});
  auto fail = [&](const std::string& text) -> LoadError {
    try {
      parseGraph(text, r, "m.json");
    } catch (const LoadError& e) {
      return e;
    }
    ADD_FAILURE();
    return LoadError("", "", "");
  };
  LoadError gap = fail(doc(R"("o": {"type": "Old", "typeVersion": 1})"));
  EXPECT_EQ(gap.pointer(), "/nodes/o/typeVersion");
  EXPECT_NE(gap.message().find("cannot be upgraded from typeVersion 1"), std::string::npos);
  LoadError bad = fail(doc(R"("o": {"type": "Old", "typeVersion": 2, "params": {"bad": 1}})"));
  EXPECT_EQ(bad.pointer(), "/nodes/o/params");
  EXPECT_NE(bad.message().find("upgrading Old from typeVersion 2 to 3: cannot convert"),
            std::string::npos);
  Graph ok = parseGraph(doc(R"("o": {"type": "Old", "typeVersion": 2})"), r, "m.json");
  EXPECT_EQ(ok.param("o", "x"), ParamValue(1.0));
}

TEST_F(GraphFile, JsonPointerOfDuplicateKeysInsideArrays) {
  try {
    parseJsonText(R"({"a": [1, {"b": 1}, {"c": [0, {"d": 1, "d": 2}]}]})", "f");
    FAIL();
  } catch (const LoadError& e) {
    EXPECT_EQ(e.pointer(), "/a/2/c/1/d");
  }
}

TEST_F(GraphFile, NumbersBeyondTheDoubleRangeAreLoadErrorsAtTheirPlace) {
  const std::vector<BadFile> cases = {
      {"format version", R"({"format": "tfd-graph", "formatVersion": 1e400, "nodes": {}})",
       "/formatVersion", "the number '1e400' is beyond the range of a double"},
      {"param", doc(R"("c": {"type": "Constant", "typeVersion": 1, "params": {"value": 1e309}})"),
       "/nodes/c/params/value", "the number '1e309' is beyond the range of a double"},
      {"array element",
       doc("\"a\": {\"type\": \"AllParams\", \"typeVersion\": 1, \"params\": {\"position\": "
           "[1, 2,\n -1e999]}}"),
       "/nodes/a/params/position/2", "'-1e999' is beyond the range of a double"},
  };
  for (const BadFile& c : cases) {
    SCOPED_TRACE(c.name);
    const LoadError e = loadError(c.text);
    EXPECT_EQ(e.pointer(), c.pointer) << e.what();
    EXPECT_NE(e.message().find(c.message), std::string::npos) << e.what();
  }
  EXPECT_NE(loadError(cases[2].text).message().find("line 2, column 8"), std::string::npos)
      << loadError(cases[2].text).what();
}

TEST_F(GraphFile, BinaryBytesInInvalidJsonAreNotEchoedRaw) {
  const LoadError e = loadError(std::string("{\"format\": \"tfd-graph\", \"a\xff\x01\": 1}"));
  const std::string what = e.what();
  EXPECT_EQ(what.find('\xff'), std::string::npos) << what;
  EXPECT_EQ(what.find('\x01'), std::string::npos) << what;
  EXPECT_NE(what.find("\\xff"), std::string::npos) << what;
}

TEST_F(GraphFile, FilesAreReadAndWrittenWhole) {
  const fs::path dir = fs::temp_directory_path() / ("tfd_graph_file_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const fs::path path = dir / "g.tfd.json";
  saveGraphFile(everyKind(), path);
  const Graph g = loadGraphFile(path, registry);
  EXPECT_EQ(g.sourcePath(), path);
  EXPECT_EQ(read(path), graphToText(everyKind()));
  int entries = 0;
  for (const auto& e : fs::directory_iterator(dir)) entries += e.is_regular_file();
  EXPECT_EQ(entries, 1) << "no temporary file left behind";
  try {
    loadGraphFile(dir / "missing.tfd.json", registry);
    FAIL();
  } catch (const LoadError& e) {
    EXPECT_EQ(e.file(), (dir / "missing.tfd.json").string());
    EXPECT_NE(e.message().find("cannot read: No such file"), std::string::npos) << e.what();
  }
  EXPECT_THROW(saveGraphFile(everyKind(), dir / "no" / "such" / "dir.json"), GraphError);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace tfd::graph
