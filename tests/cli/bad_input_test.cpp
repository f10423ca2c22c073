// Bad input through the CLI (issue 15, items 4, 5 and 7): what a file or a parameter announces
// is checked against the memory budget before anything is allocated; messages name the file,
// the place or the parameter, say what is wrong without contradicting themselves, and never
// echo raw control bytes; a later cook removes the hidden temporaries a killed cook left.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <tuple>
#include <vector>

#include "tests/support/cli_runner.h"
#include "tests/support/temp_dir.h"

#if defined(__SANITIZE_ADDRESS__)
#define TFD_TEST_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define TFD_TEST_ASAN 1
#endif
#endif
#ifndef TFD_TEST_ASAN
#define TFD_TEST_ASAN 0
#endif

namespace tfd::test {
namespace {

namespace fs = std::filesystem;
using nlohmann::ordered_json;

std::string bytesOf(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

void writeBytes(const fs::path& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary) << bytes;
}

bool has(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

bool hasRawControlByte(const std::string& text) {
  for (unsigned char c : text)
    if ((c < 0x20 && c != '\n' && c != '\t' && c != '\r') || c == 0x7f) return true;
  return false;
}

ordered_json node(const std::string& type, ordered_json params = ordered_json::object()) {
  return {{"type", type}, {"typeVersion", 1}, {"params", std::move(params)}};
}

ordered_json graphOf(ordered_json nodes, ordered_json links = ordered_json::array()) {
  return {{"format", "tfd-graph"},
          {"formatVersion", 2},
          {"nodes", std::move(nodes)},
          {"links", std::move(links)}};
}

/// A mesh node, a field from an expression and one exporter of `type` with `params`.
ordered_json exportGraph(ordered_json mesh, const std::string& type, ordered_json params) {
  return graphOf({{"ball", std::move(mesh)},
                  {"field", node("FieldExpression", {{"xx", "x*x"}, {"yy", "-y"}, {"xy", "z"}})},
                  {"out", node(type, std::move(params))}},
                 {{{"from", "ball.mesh"}, {"to", "field.mesh"}},
                  {{"from", "field.field"}, {"to", "out.field"}}});
}

ordered_json smallBall() { return node("TetMesh", {{"target_tets", 3000}}); }

/// A pid that no process has: a child that has exited and been reaped.
long deadPid() {
  const pid_t child = ::fork();
  if (child == 0) ::_exit(0);
  int status = 0;
  ::waitpid(child, &status, 0);
  return child;
}

class BadInput : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!cliAvailable()) GTEST_SKIP() << "the tfd binary was not built";
  }
  CliRun cook(const ordered_json& graph, const std::string& extra = "") {
    const fs::path file = dir.path() / "g.tfd.json";
    std::ofstream(file) << graph.dump(2);
    return runCli("cook --quiet " + shellQuote(file.string()) + " " + extra);
  }
  TempDir dir{"bad-input"};
};

// A tetrahedron's four outward triangles, and OFF text for any triangles.
const char* kTetraVertices = "0 0 0\n1 0 0\n0 1 0\n0 0 1\n";
std::string offText(const std::string& vertices, int vertexCount,
                    const std::vector<std::string>& faces) {
  std::string s = "OFF\n" + std::to_string(vertexCount) + " " + std::to_string(faces.size()) +
                  " 0\n" + vertices;
  for (const auto& f : faces) s += "3 " + f + "\n";
  return s;
}

TEST_F(BadInput, AnOpenSurfaceFileIsReportedAsOpenNamingTheFile) {
  writeBytes(dir.path() / "open.off", offText(kTetraVertices, 4, {"0 2 1", "0 1 3", "0 3 2"}));
  const CliRun r = cook(graphOf({{"m", node("TetMesh", {{"file", "open.off"}})}}));
  EXPECT_EQ(r.exitCode, 1) << r.err;
  EXPECT_TRUE(has(r.err, "open.off")) << r.err;
  EXPECT_TRUE(has(r.err, "is not a closed, manifold")) << r.err;
  EXPECT_FALSE(has(r.err, "primitive")) << "not a primitive's message: " << r.err;
}

TEST_F(BadInput, AFlatSurfaceFileIsReportedAsEnclosingNoVolume) {
  // Two triangles back to back: closed and consistently oriented, but flat.
  writeBytes(dir.path() / "flat.off", offText("0 0 0\n1 0 0\n0 1 0\n", 3, {"0 1 2", "0 2 1"}));
  const CliRun r = cook(graphOf({{"m", node("TetMesh", {{"file", "flat.off"}})}}));
  EXPECT_EQ(r.exitCode, 1) << r.err;
  EXPECT_TRUE(has(r.err, "flat.off")) << r.err;
  EXPECT_TRUE(has(r.err, "encloses no volume")) << r.err;
  EXPECT_FALSE(has(r.err, "primitive")) << r.err;
}

TEST_F(BadInput, ANegligibleVolumeIsExplainedByTheSurfaceSizeNotContradicted) {
  // One vertex far away: the volume is large in absolute terms, negligible for the extent.
  writeBytes(dir.path() / "far.off",
             offText("0 0 0\n1 0 0\n0 1 0\n0 0 1e10\n", 4, {"0 2 1", "0 1 3", "0 3 2", "1 2 3"}));
  const CliRun r = cook(graphOf({{"m", node("TetMesh", {{"file", "far.off"}})}}));
  EXPECT_EQ(r.exitCode, 1) << r.err;
  EXPECT_TRUE(has(r.err, "encloses no volume: its signed volume")) << r.err;
  EXPECT_TRUE(has(r.err, "negligible for its size (1e+10 across")) << r.err;
}

TEST_F(BadInput, ACurveFileMissingAKeyNamesThePlaceNotTheJsonLibrary) {
  writeBytes(dir.path() / "c.json",
             R"({"format": "tfd-degenerate-curves", "formatVersion": 1, "curves": [)"
             R"({"id": 0, "type": "linear", "closed": false, "points": [[0, 0, 0]]}]})");
  const CliRun r = runCli("info " + shellQuote((dir.path() / "c.json").string()));
  EXPECT_EQ(r.exitCode, 2) << r.err;
  EXPECT_TRUE(has(r.err, "c.json' at /curves/0: missing key \"pattern\"")) << r.err;
  EXPECT_FALSE(has(r.err, "json.exception")) << r.err;
}

TEST_F(BadInput, AnExporterRefusesAFileNameOfAnotherFormatNamingTheParameter) {
  const ordered_json g =
      exportGraph(smallBall(), "ExportVTU", {{"path", "field.vdb"}, {"encoding", "ascii"}});
  const CliRun r = cook(g);
  EXPECT_EQ(r.exitCode, 1) << r.err;
  EXPECT_TRUE(has(r.err, "(ExportVTU): parameter 'path': 'field.vdb' does not end in .vtu"))
      << r.err;
  EXPECT_FALSE(fs::exists(dir.path() / "field.vdb"));
  // tfd validate says so before any cook.
  const CliRun v = runCli("validate " + shellQuote((dir.path() / "g.tfd.json").string()));
  EXPECT_EQ(v.exitCode, 2) << v.out << v.err;
  EXPECT_TRUE(has(v.out + v.err, "does not end in .vtu")) << v.out << v.err;
  // Any case of the right extension is fine; so is each of ExportCurves' three.
  EXPECT_EQ(cook(exportGraph(smallBall(), "ExportVTU", {{"path", "F.VTU"}})).exitCode, 0);
}

TEST_F(BadInput, ATorusTooFineForTheMemoryBudgetIsRefusedNamingItsRadii) {
  for (const auto& [param, value, text] :
       {std::tuple{"major_radius", 1e9, "major radius 1e+09"},
        std::tuple{"minor_radius", 1e-9, "minor radius 1e-09"}}) {
    const auto start = std::chrono::steady_clock::now();
    const CliRun r =
        cook(graphOf({{"m", node("TetMesh", {{"primitive", "torus"}, {param, value}})}}));
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_EQ(r.exitCode, 1) << r.err;
    EXPECT_TRUE(has(r.err, "primitive torus (")) << r.err;
    EXPECT_TRUE(has(r.err, text)) << r.err;
    EXPECT_TRUE(has(r.err, "more than the memory budget")) << r.err;
    EXPECT_LT(seconds, 20) << "refused before building anything";
  }
}

TEST_F(BadInput, MaxMemoryIsTheBudgetOfACook) {
  const CliRun small = cook(graphOf({{"m", smallBall()}}), "--max-memory 1M");
  EXPECT_EQ(small.exitCode, 1) << small.err;
  EXPECT_TRUE(has(small.err, "memory budget of 1.0 MB (--max-memory)")) << small.err;
  EXPECT_EQ(cook(graphOf({{"m", smallBall()}}), "--max-memory 4G").exitCode, 0);
  const CliRun bad = cook(graphOf({{"m", smallBall()}}), "--max-memory lots");
  EXPECT_EQ(bad.exitCode, 2) << bad.err;
  EXPECT_TRUE(has(bad.err, "expected a memory size")) << bad.err;
}

/// Offsets of the 8-byte value of every "file_mem_bytes" metadata entry of a VDB file: the
/// name, then the type name "int64" and the value size (each length-prefixed, 32-bit), then
/// the value.
std::vector<std::size_t> memBytesValueOffsets(const std::string& vdb) {
  std::vector<std::size_t> out;
  for (std::size_t at = vdb.find("file_mem_bytes"); at != std::string::npos;
       at = vdb.find("file_mem_bytes", at + 1)) {
    const std::size_t type = at + 14 + 4;
    if (vdb.compare(type, 5, "int64") == 0) out.push_back(type + 5 + 4);
  }
  return out;
}

// A VDB whose grids announce a petabyte each: `tfd info` once read the trees (and so checked
// the announcement against the budget); it now reads metadata only (io/volume/vdb_reader.h),
// so the announcement costs nothing and the file is described, also with a small budget.
TEST_F(BadInput, InfoOfAVdbAnnouncingMoreMemoryThanTheBudgetReadsNoTree) {
  const ordered_json g = exportGraph(smallBall(), "ExportVDB", {{"voxel_size", 0.2}});
  ASSERT_EQ(cook(g).exitCode, 0);
  std::string vdb = bytesOf(dir.path() / "field.vdb");
  const auto offsets = memBytesValueOffsets(vdb);
  ASSERT_FALSE(offsets.empty()) << "OpenVDB writes file_mem_bytes with every grid";
  const std::int64_t huge = std::int64_t(1) << 50;  // 1 PB
  for (std::size_t at : offsets) std::memcpy(vdb.data() + at, &huge, sizeof huge);
  writeBytes(dir.path() / "damaged.vdb", vdb);
  for (const char* name : {"damaged.vdb", "field.vdb"}) {
    const CliRun r = runCli("info --max-memory 64M " + shellQuote((dir.path() / name).string()));
    EXPECT_EQ(r.exitCode, 0) << name << ": " << r.err;
    EXPECT_TRUE(has(r.out, "grid T.xx:")) << r.out;
    EXPECT_TRUE(has(r.out, " active voxels in [")) << r.out;
  }
}

/// `tfd info file` where a runaway allocation fails fast: under a 4 GB address-space limit,
/// or, with AddressSanitizer (which reserves its shadow memory up front), its allocation cap.
CliRun runInfoLimited(const fs::path& file) {
#if TFD_TEST_ASAN
  const std::string limit =
      "export ASAN_OPTIONS=allocator_may_return_null=1:max_allocation_size_mb=4000 && ";
#else
  const std::string limit = "ulimit -v 4000000 && ";
#endif
  const fs::path err = file.string() + ".err";
  const std::string command = "(" + limit + "exec " + shellQuote(TFD_CLI_PATH) + " info " +
                              shellQuote(file.string()) + ") >/dev/null 2>" +
                              shellQuote(err.string()) + " </dev/null";
  const int status = std::system(command.c_str());
  CliRun run;
  run.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  run.err = bytesOf(err);
  return run;
}

TEST_F(BadInput, DamagedVdbBytesEndInOurErrorNamingTheFile) {
  const ordered_json g = exportGraph(smallBall(), "ExportVDB", {{"voxel_size", 0.25}});
  ASSERT_EQ(cook(g).exitCode, 0);
  const std::string good = bytesOf(dir.path() / "field.vdb");
  ASSERT_GT(good.size(), 1000u);
  // Truncations and overwritten runs of bytes spread over the file; each read runs under a
  // 4 GB address-space limit so a runaway allocation fails fast instead of growing.
  std::vector<std::string> damaged;
  for (int k = 1; k <= 8; ++k) damaged.push_back(good.substr(0, good.size() * k / 9));
  for (int k = 0; k < 24; ++k) {
    std::string d = good;
    const std::size_t at = 4 + (d.size() - 16) * k / 24;
    for (std::size_t i = 0; i < 8; ++i) d[at + i] = k % 2 ? '\xff' : '\x7f';
    damaged.push_back(d);
  }
  const fs::path file = dir.path() / "d.vdb";
  for (std::size_t i = 0; i < damaged.size(); ++i) {
    writeBytes(file, damaged[i]);
    const CliRun r = runInfoLimited(file);
    EXPECT_TRUE(r.exitCode == 0 || r.exitCode == 2) << "case " << i << ": " << r.exitCode << r.err;
    if (r.exitCode == 0) continue;
    EXPECT_TRUE(r.err.starts_with("tfd: ")) << "case " << i << ": " << r.err;
    EXPECT_TRUE(has(r.err, "d.vdb")) << "case " << i << ": " << r.err;
    EXPECT_TRUE(has(r.err, "VDB file")) << "case " << i << ": " << r.err;
    for (const char* raw : {"bad_alloc", "KeyError:", "IoError:", "type ''", "basic_string"})
      EXPECT_FALSE(has(r.err, raw)) << "case " << i << ": " << r.err;
    EXPECT_FALSE(hasRawControlByte(r.err)) << "case " << i << ": " << r.err;
  }
}

TEST_F(BadInput, ControlBytesFromAGraphFileAreNeverEchoedRaw) {
  const fs::path file = dir.path() / "g.tfd.json";
  std::ofstream(file)
      << R"({"format": "tfd-graph", "formatVersion": 2, "nodes": )"
         R"({"a": {"type": "Evil\u001b[2J\u0007", "typeVersion": 1}}, "links": []})";
  const CliRun r = runCli("validate " + shellQuote(file.string()));
  EXPECT_EQ(r.exitCode, 2) << r.err;
  EXPECT_TRUE(has(r.err, "Evil\\x1b[2J\\x07")) << r.err;
  EXPECT_FALSE(hasRawControlByte(r.err)) << r.err;
}

TEST_F(BadInput, ALaterCookRemovesTheHiddenTemporariesAKilledCookLeft) {
  // What SIGKILL (or a power cut) leaves: the temporary of the target, named with the pid of
  // a process that is gone. A temporary of a running process is never touched.
  const std::string dead = ".field.tfd-tmp" + std::to_string(deadPid()) + "-1.vtu";
  const std::string live = ".field.tfd-tmp" + std::to_string(::getpid()) + "-1.vtu";
  const std::string other = ".other.tfd-tmp" + std::to_string(deadPid()) + "-1.vtu";
  for (const auto& name : {dead, live, other}) writeBytes(dir.path() / name, "partial");
  const CliRun r = cook(exportGraph(smallBall(), "ExportVTU", {{"path", "field.vtu"}}));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_FALSE(fs::exists(dir.path() / dead)) << "a stale temporary of the target is removed";
  EXPECT_TRUE(fs::exists(dir.path() / live)) << "a running process's temporary is kept";
  EXPECT_TRUE(fs::exists(dir.path() / other)) << "another target's temporary is not ours";
  EXPECT_TRUE(fs::exists(dir.path() / "field.vtu"));
}

}  // namespace
}  // namespace tfd::test
