#include "fuzz/fuzz_support.h"

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>

#include "core/memory_budget.h"

namespace tfd::fuzz {

namespace {

std::filesystem::path scratchFolder() {
  static const std::filesystem::path folder = [] {
    const char* tmp = std::getenv("TMPDIR");
    std::filesystem::path p = std::filesystem::path(tmp && *tmp ? tmp : "/tmp") /
                              ("tfd-fuzz-" + std::to_string(::getpid()));
    std::filesystem::create_directories(p);
    return p;
  }();
  return folder;
}

}  // namespace

std::filesystem::path inputFile(const std::uint8_t* data, std::size_t size,
                                const std::string& fileName) {
  const std::filesystem::path path = scratchFolder() / fileName;
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  out.close();
  if (!out) finding("cannot write the scratch file " + path.string());
  return path;
}

void finding(const std::string& what) {
  std::fprintf(stderr, "tfd fuzz finding: %s\n", what.c_str());
  std::fflush(stderr);
  std::abort();
}

void checkSurface(const core::SurfaceMesh& mesh) {
  if (mesh.triangles.empty()) finding("a surface reader returned a mesh without triangles");
  const long n = static_cast<long>(mesh.positions.size());
  for (const auto& p : mesh.positions)
    if (!p.allFinite()) finding("a surface reader returned a non-finite position");
  for (const auto& t : mesh.triangles)
    for (int v : t)
      if (v < 0 || v >= n) finding("a surface reader returned an out-of-range index");
}

void checkTetMesh(const core::TetMesh& mesh) {
  const auto problems = core::TetMesh::validate(mesh.positions(), mesh.tets());
  if (!problems.empty()) finding("a tet-mesh reader returned an invalid mesh: " + problems[0]);
}

void checkMessage(const std::filesystem::path& file, std::string_view message) {
  if (message.find(file.filename().string()) == std::string_view::npos)
    finding("an error message does not name the file: " + std::string(message));
  for (unsigned char c : message)
    if ((c < 0x20 && c != '\n' && c != '\t') || c == 0x7f)
      finding("an error message echoes a raw control byte: " + std::string(message));
}

void useSmallMemoryBudget() {
  static const bool once = [] {
    core::setMemoryBudget(std::uint64_t(256) << 20);
    return true;
  }();
  (void)once;
}

}  // namespace tfd::fuzz
